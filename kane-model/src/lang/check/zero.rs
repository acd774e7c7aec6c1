//! Whether two vectors are equal in every motion the model allows: the same expressions, or
//! equal at random states. A state is a random value of every symbol, with
//! Euler parameters normalised, the kinematic equations applied (`Q' = U` makes `Q'` read `U`),
//! auxiliary speeds zero and the dependent speeds solved from the motion constraints, so
//! identities that hold only in motions that satisfy them count as equal.
//!
//! In: the model, two vectors and the frame to compare them in. Out: a [`Verdict`].

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
    /// Equal: the same expressions, or equal at every sampled state.
    Same,
    /// Different along the frame's unit vector `axis` (0, 1, 2) at a sampled state.
    Differs { axis: usize, assigned: f64, implied: f64 },
    /// No state was found where both sides are finite.
    Unknown,
}

/// What the motions of a model are: the substitutions every compared value takes, and the
/// motion constraints the dependent speeds are solved from.
pub(crate) struct Motions {
    /// `Q'` by its kinematic equation, auxiliary speeds (and their rates) by zero.
    map: FxHashMap<ExprId, ExprId>,
    /// The symbols of each set of Euler parameters.
    euler: Vec<Vec<SymbolId>>,
    /// The dependent speeds and the motion constraints, when the model has any.
    constraints: Option<Dependent>,
}

/// `A_d u_d + r = 0` for the dependent speeds `u_d`, `r = A_i u_i + b`.
struct Dependent {
    speeds: Vec<SymbolId>,
    a_dependent: Vec<Vec<ExprId>>,
    rest: Vec<ExprId>,
}

impl Motions {
    /// The motions of `model` as it stands, in which the quantities `still` (VARIABLES declared
    /// without a derivative that are not states: parameters the file lets vary) keep their value.
    pub(crate) fn of(model: &mut Model, still: &[SymbolId]) -> Result<Motions> {
        let mut map = model.kinematics_map();
        map.extend(model.auxiliary_zero_map()?);
        let zero = model.ar.zero();
        for s in still {
            let mut d = *s;
            for _ in 0..2 {
                d = model.ar.derivative_symbol(d)?;
                map.insert(model.ar.symbol_expr(d), zero);
            }
        }
        let euler = euler_groups(model);
        let constraints = match model.motion_constraint_rows() {
            Some(c) => {
                let independent = model.independent_speeds();
                let mut rest = Vec::with_capacity(c.b.len());
                for (row, b) in c.a_independent.iter().zip(&c.b) {
                    let mut terms = vec![*b];
                    for (a, u) in row.iter().zip(&independent) {
                        let u = model.ar.symbol_expr(*u);
                        terms.push(model.ar.mul(&[*a, u])?);
                    }
                    rest.push(model.ar.add(&terms)?);
                }
                let a_dependent = c
                    .a_dependent
                    .iter()
                    .map(|r| model.ar.subs_many(r, &map))
                    .collect::<std::result::Result<_, _>>()?;
                let rest = model.ar.subs_many(&rest, &map)?;
                Some(Dependent { speeds: c.dependent, a_dependent, rest })
            }
            None => None,
        };
        Ok(Motions { map, euler, constraints })
    }

    /// `e` as every motion reads it: kinematic equations applied, auxiliary speeds zero.
    pub(crate) fn reading(&self, model: &mut Model, e: &[ExprId]) -> Result<Vec<ExprId>> {
        Ok(model.ar.subs_many(e, &self.map)?)
    }

    /// Compares `assigned` with `implied`, both expressed in `frame`.
    pub(crate) fn compare(
        &self,
        model: &mut Model,
        assigned: &Vector,
        implied: &Vector,
        frame: FrameId,
    ) -> Result<Verdict> {
        let a = model.express(assigned, frame)?;
        let b = model.express(implied, frame)?;
        self.compare_scalars(model, &a, &b)
    }

    /// Compares two lists of scalars entry by entry (`axis` of a difference is the entry).
    pub(crate) fn compare_scalars(&self, model: &mut Model, a: &[ExprId], b: &[ExprId]) -> Result<Verdict> {
        let a = self.reading(model, a)?;
        let b = self.reading(model, b)?;
        // The same expression (the arena shares equal ones) needs no sampling.
        if a == b {
            return Ok(Verdict::Same);
        }
        Ok(self.sample(model, &a, &b))
    }

    fn sample(&self, model: &Model, a: &[ExprId], b: &[ExprId]) -> Verdict {
        let n = a.len();
        let mut roots: Vec<ExprId> = a.iter().chain(b).copied().collect();
        if let Some(c) = &self.constraints {
            roots.extend(c.a_dependent.iter().flatten().chain(&c.rest));
        }
        let syms = model.ar.free_symbols(&roots);
        let mut rng = StdRng::seed_from_u64(0x636865636b);
        let mut compared = 0;
        for _ in 0..SAMPLES * 10 {
            if compared == SAMPLES {
                break;
            }
            let mut values: FxHashMap<SymbolId, f64> =
                syms.iter().map(|s| (*s, rng.random_range(-2.0..2.0))).collect();
            for g in &self.euler {
                let norm = g.iter().map(|s| values.get(s).map_or(0.0, |v| v * v)).sum::<f64>().sqrt();
                for s in g {
                    if let Some(v) = values.get_mut(s) {
                        *v /= norm;
                    }
                }
            }
            if let Some(c) = &self.constraints {
                if !solve_dependent(model, c, &mut values) {
                    continue;
                }
            }
            let Ok(v) = model.ar.eval(&roots[..2 * n], |s| values.get(&s).copied()) else { continue };
            if v.iter().any(|x| !x.is_finite()) {
                continue;
            }
            compared += 1;
            for axis in 0..n {
                let (x, y) = (v[axis], v[axis + n]);
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
}

/// Sets the dependent speeds in `values` so that the motion constraints hold; false where
/// they cannot be solved (a singular `A_d` there).
fn solve_dependent(model: &Model, c: &Dependent, values: &mut FxHashMap<SymbolId, f64>) -> bool {
    let m = c.speeds.len();
    let roots: Vec<ExprId> = c.a_dependent.iter().flatten().chain(&c.rest).copied().collect();
    let Ok(v) = model.ar.eval(&roots, |s| values.get(&s).copied()) else { return false };
    let mut a = nalgebra::DMatrix::from_row_slice(m, m, &v[..m * m]);
    let b = nalgebra::DVector::from_iterator(m, v[m * m..].iter().map(|x| -x));
    if a.iter().chain(b.iter()).any(|x| !x.is_finite()) {
        return false;
    }
    let scale = a.amax().max(1.0);
    a /= scale;
    let Some(x) = a.lu().solve(&(b / scale)) else { return false };
    if x.iter().any(|x| !x.is_finite()) {
        return false;
    }
    for (s, x) in c.speeds.iter().zip(x.iter()) {
        values.insert(*s, *x);
    }
    true
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
        let motions = Motions::of(&mut m, &[]).unwrap();
        assert_eq!(motions.compare(&mut m, &v(x), &v(x), n).unwrap(), Verdict::Same);
        assert_eq!(motions.compare(&mut m, &v(sin2x), &v(twice), n).unwrap(), Verdict::Same);
        let d = motions.compare(&mut m, &Vector::zero(), &v(x), n).unwrap();
        assert!(matches!(d, Verdict::Differs { axis: 0, assigned, .. } if assigned == 0.0), "{d:?}");
    }

    #[test]
    fn rates_read_through_the_kinematic_equations() {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let q = m.ar.variable("q").unwrap();
        let u = m.ar.variable("u").unwrap();
        m.set_kinematics(q, u).unwrap();
        let qs = m.ar.as_symbol(q).unwrap();
        let qd = m.ar.derivative_symbol(qs).unwrap();
        let qd = m.ar.symbol_expr(qd);
        let z = m.ar.zero();
        let motions = Motions::of(&mut m, &[]).unwrap();
        let same =
            motions.compare(&mut m, &Vector::new(n, [qd, z, z]), &Vector::new(n, [u, z, z]), n).unwrap();
        assert_eq!(same, Verdict::Same);
    }
}
