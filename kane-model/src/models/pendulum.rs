//! The planar n-link pendulum: particles `m_i` at the ends of massless links `l_i`.
//!
//! Link i's frame `A_i` is rotated from the Newtonian frame N by the absolute angle `q_i` about
//! `n3`; `P_i = P_(i-1) + l_i a_i1` from the fixed pivot `P_0`; gravity `-g n2`; `q_i' = u_i`.
//! This is SymPy's `n_link_pendulum_on_cart` without the cart.

use crate::expr::ExprId;
use crate::mechanics::{Model, Orientation, Result};

/// The model of an `n`-link pendulum, with its coordinates and speeds.
pub fn n_link_pendulum(n: usize) -> Result<(Model, Vec<ExprId>, Vec<ExprId>)> {
    let mut m = Model::new("N");
    let nf = m.newtonian();
    let g = m.ar.constant("g")?;
    let mg_dir = m.ar.neg(g)?;
    let mut q = Vec::with_capacity(n);
    let mut u = Vec::with_capacity(n);
    let pivot = m.add_point("P0")?;
    m.fix_point(pivot, nf);
    let mut prev = pivot;
    for i in 1..=n {
        let qi = m.ar.variable(&format!("q{i}"))?;
        let ui = m.ar.variable(&format!("u{i}"))?;
        let li = m.ar.constant(&format!("l{i}"))?;
        let mi = m.ar.constant(&format!("m{i}"))?;
        let frame = m.add_frame(&format!("A{i}"))?;
        m.orient(frame, nf, Orientation::Axis { axis: 3, angle: qi })?;
        let particle = m.add_particle(&format!("P{i}"))?;
        let point = m.particle(particle).point;
        let link = m.scale(&m.unit(frame, 1), li)?;
        m.set_position(point, prev, link)?;
        m.set_particle_mass(particle, mi);
        let weight = m.ar.mul(&[mi, mg_dir])?;
        let f = m.scale(&m.unit(nf, 2), weight)?;
        m.add_force(point, f);
        prev = point;
        q.push(qi);
        u.push(ui);
    }
    m.set_coordinates(&q)?;
    m.set_speeds(&u)?;
    for (qi, ui) in q.iter().zip(&u) {
        m.set_kinematics(*qi, *ui)?;
    }
    Ok((m, q, u))
}
