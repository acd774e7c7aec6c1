//! The 3-DOF gimballed gyroscope of "Dynamical Multi-body Gyroscopic Motion Simulation".
//!
//! Frames: A (Newtonian), B outer gimbal `SIMPROT(A,B,-2,q1)`, C inner gimbal
//! `SIMPROT(B,C,-1,q2)`, D rotor `SIMPROT(C,D,-2,q3)`; `qi' = ui`. All mass centres at the fixed
//! point O (the paper sets their accelerations to zero and never places them). Inertias as the
//! paper's lines 5-13; torques `Y a2` on B and `Z b1` on C; P at `L d1` from O.

use crate::expr::ExprId;
use crate::mechanics::{BodyId, Model, Orientation, PointId, Result, Vector};

/// The gimbal model with handles on its symbols.
pub struct GimbalGyroscope {
    /// The model.
    pub model: Model,
    /// Coordinates q1, q2, q3.
    pub q: [ExprId; 3],
    /// Speeds u1, u2, u3.
    pub u: [ExprId; 3],
    /// Bodies B, C, D.
    pub bodies: [BodyId; 3],
    /// The fixed point O and the rotor point P.
    pub points: [PointId; 2],
}

impl GimbalGyroscope {
    /// Builds the model with the paper's symbol names.
    pub fn new() -> Result<GimbalGyroscope> {
        let mut m = Model::new("A");
        let a = m.newtonian();
        let c = |m: &mut Model, n: &str| m.ar.constant(n);
        let [m1, m2, m3, h1, h2, h3, l, w, y, z] =
            ["M1", "M2", "M3", "H1", "H2", "H3", "L", "W", "Y", "Z"].map(|n| c(&mut m, n));
        let (m1, m2, m3, h1, h2, h3, l, w, y, z) = (m1?, m2?, m3?, h1?, h2?, h3?, l?, w?, y?, z?);
        let q = [m.ar.variable("q1")?, m.ar.variable("q2")?, m.ar.variable("q3")?];
        let u = [m.ar.variable("u1")?, m.ar.variable("u2")?, m.ar.variable("u3")?];

        let bb = m.add_body("B")?;
        let bc = m.add_body("C")?;
        let bd = m.add_body("D")?;
        let (fb, fc, fd) = (m.body(bb).frame, m.body(bc).frame, m.body(bd).frame);
        m.orient(fb, a, Orientation::Axis { axis: -2, angle: q[0] })?;
        m.orient(fc, fb, Orientation::Axis { axis: -1, angle: q[1] })?;
        m.orient(fd, fc, Orientation::Axis { axis: -2, angle: q[2] })?;
        m.set_coordinates(&q)?;
        m.set_speeds(&u)?;
        for i in 0..3 {
            m.set_kinematics(q[i], u[i])?;
        }

        // Lines 5-13: I1 = 2/3 M1 (H1 W - W^2), I2 = 1/6 M1 H1^2 - 1/6 M1 (H1 - W)^2, likewise J
        // for C with M2, H2; K1 = 1/2 M3 L^2, K2 = 1/4 M3 L^2 + 1/12 M3 H3^2.
        let (i1, i2) = gimbal_moments(&mut m, m1, h1, w)?;
        let (j1, j2) = gimbal_moments(&mut m, m2, h2, w)?;
        let ar = &mut m.ar;
        let half = ar.rational(1, 2)?;
        let quarter = ar.rational(1, 4)?;
        let twelfth = ar.rational(1, 12)?;
        let l2 = ar.powi(l, 2)?;
        let h32 = ar.powi(h3, 2)?;
        let k1 = ar.mul(&[half, m3, l2])?;
        let k2a = ar.mul(&[quarter, m3, l2])?;
        let k2b = ar.mul(&[twelfth, m3, h32])?;
        let k2 = ar.add(&[k2a, k2b])?;
        let ib = m.diagonal_inertia(fb, [i1, i1, i2]);
        let ic = m.diagonal_inertia(fc, [j1, j1, j2]);
        let id = m.diagonal_inertia(fd, [k2, k1, k2]);
        for (body, mass, inertia) in [(bb, m1, ib), (bc, m2, ic), (bd, m3, id)] {
            m.set_mass(body, mass);
            m.set_inertia(body, inertia);
        }

        let o = m.add_point("O")?;
        m.fix_point(o, a);
        for body in [bb, bc, bd] {
            let cm = m.body(body).mass_center;
            m.set_position(cm, o, Vector::zero())?;
        }
        let p = m.add_point("P")?;
        let lp = m.scale(&m.unit(fd, 1), l)?;
        m.set_position(p, o, lp)?;

        let ty = m.scale(&m.unit(a, 2), y)?;
        m.add_torque(fb, ty);
        let tz = m.scale(&m.unit(fb, 1), z)?;
        m.add_torque(fc, tz);
        Ok(GimbalGyroscope { model: m, q, u, bodies: [bb, bc, bd], points: [o, p] })
    }
}

/// `(2/3 m (h w - w^2), 1/6 m h^2 - 1/6 m (h - w)^2)`: the paper's gimbal moments.
fn gimbal_moments(m: &mut Model, mass: ExprId, h: ExprId, w: ExprId) -> Result<(ExprId, ExprId)> {
    let ar = &mut m.ar;
    let two_thirds = ar.rational(2, 3)?;
    let sixth = ar.rational(1, 6)?;
    let hw = ar.mul(&[h, w])?;
    let w2 = ar.powi(w, 2)?;
    let hw_w2 = ar.sub(hw, w2)?;
    let first = ar.mul(&[two_thirds, mass, hw_w2])?;
    let h2 = ar.powi(h, 2)?;
    let hmw = ar.sub(h, w)?;
    let hmw2 = ar.powi(hmw, 2)?;
    let a = ar.mul(&[sixth, mass, h2])?;
    let b = ar.mul(&[sixth, mass, hmw2])?;
    let second = ar.sub(a, b)?;
    Ok((first, second))
}
