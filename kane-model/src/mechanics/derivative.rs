//! Derivatives of vectors as seen in a frame: the time derivative (Autolev's `DT(v>, A)`) and
//! the partial derivative with respect to a symbol (Autolev's `D(v>, q, A)`).
//!
//! In: a [`Vector`], a frame, and (for the partial) a symbol. Out: the derivative vector, each
//! term kept in its own frame where the frames' relative orientation allows it.

use crate::expr::SymbolId;

use super::error::Result;
use super::ids::FrameId;
use super::model::Model;
use super::vector::Vector;

impl Model {
    /// The time derivative of `v` as seen in `frame`, with the kinematic equations applied.
    pub fn dt_in(&mut self, v: &Vector, frame: FrameId) -> Result<Vector> {
        let mut out = Vector::zero();
        for (f, m) in v.terms.clone() {
            let mut d = [self.ar.zero(); 3];
            for i in 0..3 {
                d[i] = self.dt(m[i])?;
            }
            out = self.add_vectors(&out, &Vector::new(f, d))?;
            if f != frame {
                let w = self.angular_velocity(f, frame)?;
                let t = self.cross(&w, &Vector::new(f, m))?;
                out = self.add_vectors(&out, &t)?;
            }
        }
        Ok(out)
    }

    /// The partial derivative of `v` with respect to `s` as seen in `frame` (Autolev's D).
    ///
    /// A term is re-expressed in `frame` only where its orientation there depends on `s`;
    /// otherwise its measure numbers are differentiated where they are.
    pub fn partial_in(&mut self, v: &Vector, s: SymbolId, frame: FrameId) -> Result<Vector> {
        let mut out = Vector::zero();
        for (g, m) in v.terms.clone() {
            let term = Vector::new(g, m);
            let c = self.dcm(frame, g)?;
            let depends = self.ar.free_symbols(&c.iter().flatten().copied().collect::<Vec<_>>()).contains(&s);
            let term = if depends { self.express_vector(&term, frame)? } else { term };
            let d = self.partial(&term, s)?;
            out = self.add_vectors(&out, &d)?;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use crate::expr::{ExprId, SymbolId};
    use crate::mechanics::{FrameId, Model, Orientation, Vector};

    /// `N` with `B` turned by `q` about `N3`, `q' = u`, and the vector `L B1 + K B2` fixed in B.
    fn rotating() -> (Model, FrameId, FrameId, Vector) {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let b = m.add_frame("B").unwrap();
        let q = m.ar.variable("q").unwrap();
        let u = m.ar.variable("u").unwrap();
        m.orient(b, n, Orientation::Axis { axis: 3, angle: q }).unwrap();
        m.set_kinematics(q, u).unwrap();
        let (l, k) = (m.ar.constant("L").unwrap(), m.ar.constant("K").unwrap());
        let z = m.ar.zero();
        let v = Vector::new(b, [l, k, z]);
        (m, n, b, v)
    }

    /// Measure numbers in `frame` at q = 0.7, u = -1.3, L = 2, K = 0.5.
    fn numbers(m: &mut Model, v: &Vector, frame: FrameId) -> [f64; 3] {
        let e = m.express(v, frame).unwrap();
        let value = |s: SymbolId| -> Option<f64> {
            Some(match m.ar.symbol_info(s).name.as_str() {
                "q" => 0.7,
                "u" => -1.3,
                "L" => 2.0,
                "K" => 0.5,
                _ => return None,
            })
        };
        let x = m.ar.eval(&e, value).unwrap();
        [x[0], x[1], x[2]]
    }

    fn assert_close(a: [f64; 3], b: [f64; 3]) {
        for i in 0..3 {
            assert!((a[i] - b[i]).abs() < 1e-12, "{a:?} != {b:?}");
        }
    }

    #[test]
    fn dt_of_a_vector_fixed_in_a_rotating_frame_is_w_cross_v() {
        let (mut m, n, b, v) = rotating();
        let d = m.dt_in(&v, n).unwrap();
        let w = m.angular_velocity(b, n).unwrap();
        let wxv = m.cross(&w, &v).unwrap();
        let (got, want) = (numbers(&mut m, &d, n), numbers(&mut m, &wxv, n));
        assert_close(got, want);
        assert!(got.iter().any(|x| x.abs() > 0.1), "a turning vector changes: {got:?}");
        // Seen from B itself it does not change.
        let in_b = m.dt_in(&v, b).unwrap();
        assert_close(numbers(&mut m, &in_b, n), [0.0; 3]);
    }

    #[test]
    fn partial_in_a_frame_differentiates_the_orientation_too() {
        let (mut m, n, b, v) = rotating();
        let q = m.ar.lookup("q").unwrap();
        // d/dq of a vector fixed in B, seen in N, is N3 x v (the rate per unit q').
        let d = m.partial_in(&v, q, n).unwrap();
        let n3 = m.unit(n, 3);
        let want = m.cross(&n3, &v).unwrap();
        assert_close(numbers(&mut m, &d, n), numbers(&mut m, &want, n));
        // In B, the orientation does not depend on q: the fixed vector's derivative is zero.
        let in_b = m.partial_in(&v, q, b).unwrap();
        assert!(in_b.is_empty());
        // A symbol the orientation does not involve differentiates measure numbers in place.
        let l = m.ar.lookup("L").unwrap();
        let dl = m.partial_in(&v, l, n).unwrap();
        let (one, z): (ExprId, ExprId) = (m.ar.one(), m.ar.zero());
        assert_eq!(dl, Vector::new(b, [one, z, z]));
    }
}
