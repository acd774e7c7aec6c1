//! Whether an assigned vector equals the implied one for every state: their difference
//! simplified to zero, else compared at random states. Euler parameters are normalised at each
//! sampled state, so identities that hold only for unit Euler parameters count as equal.
//!
//! In: two vectors and the frame to compare them in. Out: a [`Verdict`].

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{FrameId, Model, Orientation, Result, Vector};

/// States at which the two sides are compared.
const SAMPLES: usize = 32;
/// Largest accepted `|a - b| / max(1, |a|, |b|)`.
const TOLERANCE: f64 = 1e-8;

/// The outcome of a comparison.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Verdict {
    /// Equal: proven, or at every sampled state.
    Same,
    /// Different along the frame's unit vector `axis` (0, 1, 2) at a sampled state.
    Differs { axis: usize, assigned: f64, implied: f64 },
    /// No state was found where both sides are finite.
    Unknown,
}

/// Compares `assigned` with `implied`, both expressed in `frame`.
pub(crate) fn compare(
    model: &mut Model,
    assigned: &Vector,
    implied: &Vector,
    frame: FrameId,
) -> Result<Verdict> {
    let a = model.express(assigned, frame)?;
    let b = model.express(implied, frame)?;
    let mut proven = true;
    for i in 0..3 {
        let d = model.ar.sub(a[i], b[i])?;
        let d = model.ar.simplify(d)?;
        proven &= model.ar.is_zero(d);
    }
    if proven {
        return Ok(Verdict::Same);
    }
    Ok(sample(model, &a, &b))
}

/// The symbols of each set of Euler parameters in the model.
fn euler_groups(model: &Model) -> Vec<Vec<SymbolId>> {
    let mut groups = Vec::new();
    for f in &model.frames {
        if let Some(Orientation::EulerParameters(e)) = &f.orientation {
            groups.push(e.iter().filter_map(|x| model.ar.as_symbol(*x)).collect());
        }
    }
    groups
}

fn sample(model: &Model, a: &[ExprId; 3], b: &[ExprId; 3]) -> Verdict {
    let roots: Vec<ExprId> = a.iter().chain(b).copied().collect();
    let syms = model.ar.free_symbols(&roots);
    let groups = euler_groups(model);
    let mut rng = StdRng::seed_from_u64(0x636865636b);
    let mut compared = 0;
    for _ in 0..SAMPLES * 10 {
        if compared == SAMPLES {
            break;
        }
        let mut values: FxHashMap<SymbolId, f64> =
            syms.iter().map(|s| (*s, rng.random_range(-2.0..2.0))).collect();
        for g in &groups {
            let norm = g.iter().map(|s| values.get(s).map_or(0.0, |v| v * v)).sum::<f64>().sqrt();
            for s in g {
                if let Some(v) = values.get_mut(s) {
                    *v /= norm;
                }
            }
        }
        let Ok(v) = model.ar.eval(&roots, |s| values.get(&s).copied()) else { continue };
        if v.iter().any(|x| !x.is_finite()) {
            continue;
        }
        compared += 1;
        for axis in 0..3 {
            let (x, y) = (v[axis], v[axis + 3]);
            if (x - y).abs() / x.abs().max(y.abs()).max(1.0) > TOLERANCE {
                return Verdict::Differs { axis, assigned: x, implied: y };
            }
        }
    }
    if compared == 0 {
        Verdict::Unknown
    } else {
        Verdict::Same
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn proven_sampled_and_different() {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let x = m.ar.constant("x").unwrap();
        let (z, two) = (m.ar.zero(), m.ar.integer(2));
        let x2 = m.ar.mul(&[two, x]).unwrap();
        let sin2x = m.ar.sin(x2).unwrap();
        let (s, c) = (m.ar.sin(x).unwrap(), m.ar.cos(x).unwrap());
        let twice = m.ar.mul(&[two, s, c]).unwrap();
        let v = |e| Vector::new(n, [e, z, z]);
        assert_eq!(compare(&mut m, &v(x), &v(x), n).unwrap(), Verdict::Same);
        assert_eq!(compare(&mut m, &v(sin2x), &v(twice), n).unwrap(), Verdict::Same);
        let d = compare(&mut m, &Vector::zero(), &v(x), n).unwrap();
        assert!(matches!(d, Verdict::Differs { axis: 0, assigned, .. } if assigned == 0.0), "{d:?}");
    }
}
