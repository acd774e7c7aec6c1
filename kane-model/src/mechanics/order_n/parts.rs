//! What each link carries: its masses summed into one rigid-body inertia about its pivot, and
//! the applied loads as one spatial force about its pivot; uniform gravity (the force `m g` at
//! every mass) recognised and kept apart, to enter as an acceleration of the base.

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{Dyadic, FrameId, Load, Mat3, Model, PointId, Vector};

use super::super::error::Result;
use super::spatial::{add, cross, scale, V3, V6};
use super::tree::{parameter_only, reads_only, Attach, Links};

/// The mass properties of one link about its pivot, in link components.
#[derive(Clone, Debug)]
pub(crate) struct LinkMass {
    /// The mass of the part.
    pub mass: ExprId,
    /// First moment: mass times the mass centre's offset from the pivot.
    pub moment: V3,
    /// Rotational inertia about the pivot.
    pub inertia: Mat3,
}

/// The links' masses and loads.
pub(crate) struct Parts {
    /// One per link.
    pub mass: Vec<LinkMass>,
    /// The applied spatial force on each link about its pivot (moment, then force).
    pub load: Vec<V6>,
    /// Uniform gravity in Newtonian components (zero when none).
    pub gravity: V3,
}

/// The masses and loads of `model` on `tree`; `None` when a mass or load fits no link.
pub(crate) fn parts(model: &mut Model, tree: &Links, states: &[SymbolId]) -> Result<Option<Parts>> {
    let z = model.ar.zero();
    let n = tree.links.len();
    let empty = LinkMass { mass: z, moment: [z; 3], inertia: [[z; 3]; 3] };
    let mut out = Parts { mass: vec![empty; n], load: vec![[z; 6]; n], gravity: [z; 3] };
    for view in model.masses().collect::<Vec<_>>() {
        let Some(m) = view.mass.filter(|m| parameter_only(model, *m)) else { return Ok(None) };
        match (tree.points.get(&view.point), view.frame) {
            (Some(Attach::Base), None) => continue,
            (Some(Attach::Base), Some(f)) if f == model.newtonian => continue,
            (Some(Attach::Link(k, c)), frame) => {
                let central = match (frame, &view.inertia) {
                    (Some(f), Some(d)) if tree.of_frame.get(&f) == Some(k) => in_link(model, &d.clone(), f)?,
                    (Some(f), None) if tree.of_frame.get(&f) == Some(k) => Some([[z; 3]; 3]),
                    (None, _) => Some([[z; 3]; 3]),
                    _ => None,
                };
                let Some(central) = central else { return Ok(None) };
                add_mass(model, &mut out.mass[*k], m, *c, &central)?;
            }
            _ => return Ok(None),
        }
    }
    let mut loads = model.loads.clone();
    if let Some(g) = gravity(model, &mut loads)? {
        out.gravity = g;
    }
    for load in loads {
        if !add_load(model, tree, &mut out, &load, states)? {
            return Ok(None);
        }
    }
    Ok(Some(out))
}

/// A dyadic's entries in `frame` when every term is written in that frame with parameter-only
/// entries.
fn in_link(model: &mut Model, d: &Dyadic, frame: FrameId) -> Result<Option<Mat3>> {
    let z = model.ar.zero();
    let mut out = [[z; 3]; 3];
    for (fa, fb, m) in d.terms.clone() {
        if fa != frame || fb != frame || !m.iter().flatten().all(|x| parameter_only(model, *x)) {
            return Ok(None);
        }
        for i in 0..3 {
            for j in 0..3 {
                out[i][j] = model.ar.add(&[out[i][j], m[i][j]])?;
            }
        }
    }
    Ok(Some(out))
}

/// Adds a mass `m` at `c` with central inertia `central` to a link's mass properties.
fn add_mass(model: &mut Model, to: &mut LinkMass, m: ExprId, c: V3, central: &Mat3) -> Result<()> {
    let ar = &mut model.ar;
    to.mass = ar.add(&[to.mass, m])?;
    let h = scale(ar, m, &c)?;
    to.moment = add(ar, &to.moment, &h)?;
    for i in 0..3 {
        for j in 0..3 {
            // m (|c|^2 delta_ij - c_i c_j): the off-axis products only.
            let mut terms = vec![to.inertia[i][j], central[i][j]];
            if i == j {
                for k in (0..3).filter(|k| *k != i) {
                    terms.push(ar.mul(&[m, c[k], c[k]])?);
                }
            } else {
                let p = ar.mul(&[m, c[i], c[j]])?;
                terms.push(ar.neg(p)?);
            }
            to.inertia[i][j] = ar.add(&terms)?;
        }
    }
    Ok(())
}

/// Uniform gravity `g`, when every mass bears exactly the force `m g` (in Newtonian components,
/// parameter-only); those forces are taken out of `loads`.
fn gravity(model: &mut Model, loads: &mut Vec<Load>) -> Result<Option<V3>> {
    let masses: Vec<(ExprId, PointId)> =
        model.masses().filter_map(|v| v.mass.map(|m| (m, v.point))).collect();
    let Some(&(m0, p0)) = masses.first() else { return Ok(None) };
    let Some(Load::Force { force, .. }) =
        loads.iter().find(|l| matches!(l, Load::Force { point, .. } if *point == p0))
    else {
        return Ok(None);
    };
    let nf = model.newtonian;
    let g0 = model.express(&force.clone(), nf)?;
    let mut g = [model.ar.zero(); 3];
    for (o, x) in g.iter_mut().zip(g0) {
        *o = model.ar.div(x, m0)?;
        if !parameter_only(model, *o) {
            return Ok(None);
        }
    }
    let gv = Vector::new(nf, g);
    let mut rest = loads.clone();
    for (m, p) in masses {
        let want = model.scale(&gv, m)?;
        let want = model.express(&want, nf)?;
        let mut hit = None;
        for (i, l) in rest.iter().enumerate() {
            if let Load::Force { point, force } = l {
                if *point == p && model.express(&force.clone(), nf)? == want {
                    hit = Some(i);
                    break;
                }
            }
        }
        let Some(i) = hit else { return Ok(None) };
        rest.remove(i);
    }
    *loads = rest;
    Ok(Some(g))
}

/// Adds one applied load to its link's spatial force; false when it fits no link.
fn add_load(
    model: &mut Model,
    tree: &Links,
    out: &mut Parts,
    load: &Load,
    states: &[SymbolId],
) -> Result<bool> {
    let (k, moment, force) = match load {
        Load::Force { point, force } => match tree.points.get(point) {
            Some(Attach::Base) => return Ok(true),
            Some(Attach::Link(k, c)) => {
                let f = model.express(force, tree.links[*k].frame)?;
                let m = cross(&mut model.ar, c, &f)?;
                (*k, m, f)
            }
            None => return Ok(false),
        },
        Load::Torque { frame, torque } => {
            if *frame == model.newtonian {
                return Ok(true);
            }
            let Some(&k) = tree.of_frame.get(frame) else { return Ok(false) };
            let t = model.express(torque, *frame)?;
            (k, t, [model.ar.zero(); 3])
        }
    };
    if !moment.iter().chain(&force).all(|x| reads_only(model, *x, states)) {
        return Ok(false);
    }
    let six: V6 = [moment[0], moment[1], moment[2], force[0], force[1], force[2]];
    out.load[k] = add(&mut model.ar, &out.load[k], &six)?;
    Ok(true)
}
