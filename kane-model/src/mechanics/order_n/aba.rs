//! The articulated-body algorithm on expressions: angular velocities and velocity-product
//! accelerations outward, articulated inertias and bias forces inward, joint accelerations
//! outward. Quantities of a link are in its own frame about its pivot; accelerations are those
//! of the pivot (classical, not spatial), so only angular velocities propagate. Gravity enters
//! as an upward acceleration of the base.

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{Mat3, Model};

use super::super::error::Result;
use super::parts::Parts;
use super::spatial::{self, add, cross, rotate, M6, V3, V6};
use super::tree::Links;

/// The outward kinematics of one link.
struct Motion {
    /// Parent to link components (`parent_i . link_j`).
    rotation: Mat3,
    /// Motion transform from the parent's pivot to this one's.
    transform: M6,
    /// Angular velocity in link components.
    omega: V3,
    /// Velocity-product acceleration of the link (angular, then the pivot's).
    bias: V6,
}

/// The speed rates `u'`, in the equations' speed order, from the articulated-body algorithm.
pub(crate) fn rates(
    model: &mut Model,
    tree: &Links,
    parts: &Parts,
    speeds: &[SymbolId],
) -> Result<Vec<ExprId>> {
    let motions = kinematics(model, tree, speeds)?;
    let (ia, pa) = articulated(model, tree, parts, &motions)?;
    let ar = &mut model.ar;
    let z = ar.zero();
    let mut acc: Vec<V6> = Vec::with_capacity(tree.links.len());
    let mut out = vec![z; speeds.len()];
    let lifted = spatial::scale(ar, ar.minus_one(), &parts.gravity)?;
    for (k, link) in tree.links.iter().enumerate() {
        let m = &motions[k];
        let parent: V6 = match link.parent {
            Some(p) => acc[p],
            None => {
                let a = rotate(ar, &m.rotation, &lifted, true)?;
                [z, z, z, a[0], a[1], a[2]]
            }
        };
        let moved = match link.parent {
            Some(_) => spatial::apply(ar, &m.transform, &parent)?,
            None => parent,
        };
        let a = add(ar, &moved, &m.bias)?;
        // s^T (Ia (a + s u') + pa) = 0.
        let ax = link.axis;
        let sum = spatial::dot(ar, &ia[k][ax], &a)?;
        let sum = ar.add(&[sum, pa[k][ax]])?;
        let ratio = ar.div(sum, ia[k][ax][ax])?;
        let ud = if link.sign < 0 { ratio } else { ar.neg(ratio)? };
        let mut full = a;
        let turn = if link.sign < 0 { ar.neg(ud)? } else { ud };
        full[ax] = ar.add(&[full[ax], turn])?;
        acc.push(full);
        out[link.speed] = ud;
    }
    Ok(out)
}

/// Rotations, transforms, angular velocities and velocity-product accelerations, outward.
fn kinematics(model: &mut Model, tree: &Links, speeds: &[SymbolId]) -> Result<Vec<Motion>> {
    let mut out: Vec<Motion> = Vec::with_capacity(tree.links.len());
    for link in &tree.links {
        let parent_frame = match link.parent {
            Some(p) => tree.links[p].frame,
            None => model.newtonian(),
        };
        let rotation = model.dcm(parent_frame, link.frame)?;
        let ar = &mut model.ar;
        let z = ar.zero();
        let u = ar.symbol_expr(speeds[link.speed]);
        let mut spin = [z; 3];
        spin[link.axis] = if link.sign < 0 { ar.neg(u)? } else { u };
        let transform = spatial::motion_transform(ar, &rotation, &link.offset)?;
        let (omega, bias) = match link.parent {
            None => (spin, [z; 6]),
            Some(p) => {
                let wp = out[p].omega;
                let carried = rotate(ar, &rotation, &wp, true)?;
                let omega = add(ar, &carried, &spin)?;
                let coriolis = cross(ar, &carried, &spin)?;
                let wd = cross(ar, &wp, &link.offset)?;
                let wwd = cross(ar, &wp, &wd)?;
                let lin = rotate(ar, &rotation, &wwd, true)?;
                (omega, [coriolis[0], coriolis[1], coriolis[2], lin[0], lin[1], lin[2]])
            }
        };
        out.push(Motion { rotation, transform, omega, bias });
    }
    Ok(out)
}

/// Articulated inertias and bias forces of each link's subtree, inward.
fn articulated(
    model: &mut Model,
    tree: &Links,
    parts: &Parts,
    motions: &[Motion],
) -> Result<(Vec<M6>, Vec<V6>)> {
    let ar = &mut model.ar;
    let n = tree.links.len();
    let mut ia: Vec<M6> = Vec::with_capacity(n);
    let mut pa: Vec<V6> = Vec::with_capacity(n);
    for (k, lm) in parts.mass.iter().enumerate() {
        ia.push(spatial::inertia(ar, &lm.inertia, &lm.moment, lm.mass)?);
        // Velocity products w x J w and w x (w x h), less the applied load.
        let w = motions[k].omega;
        let jw = rotate(ar, &lm.inertia, &w, false)?;
        let gyro = cross(ar, &w, &jw)?;
        let wh = cross(ar, &w, &lm.moment)?;
        let cent = cross(ar, &w, &wh)?;
        let b: V6 = [gyro[0], gyro[1], gyro[2], cent[0], cent[1], cent[2]];
        let minus = spatial::scale(ar, ar.minus_one(), &parts.load[k])?;
        pa.push(add(ar, &b, &minus)?);
    }
    for k in (0..n).rev() {
        let Some(p) = tree.links[k].parent else { continue };
        let (reduced, bias) = reduce(ar, &ia[k], &pa[k], tree.links[k].axis, &motions[k].bias)?;
        let x = &motions[k].transform;
        let into = spatial::congruence(ar, x, &reduced)?;
        let force = spatial::apply_transpose(ar, x, &bias)?;
        for i in 0..6 {
            for j in i..6 {
                ia[p][i][j] = ar.add(&[ia[p][i][j], into[i][j]])?;
                ia[p][j][i] = ia[p][i][j];
            }
        }
        pa[p] = add(ar, &pa[p], &force)?;
    }
    Ok((ia, pa))
}

/// The subtree's inertia and bias as its parent feels them through a free joint about `axis`:
/// `Ia - U U^T / D` and `pa + Ia^A c - U (s^T pa) / D`, the axis row and column exactly zero.
fn reduce(
    ar: &mut crate::expr::Arena,
    ia: &M6,
    pa: &V6,
    axis: usize,
    c: &V6,
) -> std::result::Result<(M6, V6), crate::expr::ExprError> {
    let z = ar.zero();
    let d = ia[axis][axis];
    let minus_one = ar.minus_one();
    let inv = ar.pow(d, minus_one)?;
    let w: V6 = spatial::scale(ar, inv, &ia[axis])?;
    let mut out = [[z; 6]; 6];
    for i in (0..6).filter(|i| *i != axis) {
        for j in (i..6).filter(|j| *j != axis) {
            let p = spatial::dot(ar, &[ia[i][axis]], &[w[j]])?;
            out[i][j] = ar.sub(ia[i][j], p)?;
            out[j][i] = out[i][j];
        }
    }
    let mut bias = [z; 6];
    for i in (0..6).filter(|i| *i != axis) {
        let ic = spatial::dot(ar, &out[i], c)?;
        let up = spatial::dot(ar, &[w[i]], &[pa[axis]])?;
        let s = ar.sub(pa[i], up)?;
        bias[i] = ar.add(&[s, ic])?;
    }
    Ok((out, bias))
}
