//! Sines and cosines of sums and integer multiples of angles written in those of the single
//! angles (`sin(a + b)`, `cos(2 a)`), and proofs of zero that need them or a common denominator.

use super::arena::Arena;
use super::error::ExprError;
use super::expand::TrigBasis;
use super::node::{ExprId, Func, Node};

type Res = Result<ExprId, ExprError>;

/// Most terms of an angle sum that are split; a longer sum is kept as one angle.
const MAX_SPLIT_TERMS: usize = 8;
/// Largest integer multiple of an angle that is written in the single angle's functions.
const MAX_MULTIPLE: i64 = 12;

impl Arena {
    /// Every `sin`, `cos` and `tan` of a sum or an integer multiple of angles written in the
    /// sines and cosines of the single angles: `sin(a - b)` becomes
    /// `sin(a) cos(b) - cos(a) sin(b)`, `cos(2 a)` becomes `cos(a)^2 - sin(a)^2`.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// let mut ar = Arena::new();
    /// let [a, b] = ["a", "b"].map(|n| ar.constant(n).unwrap());
    /// let d = ar.sub(a, b).unwrap();
    /// let s = ar.sin(d).unwrap();
    /// let e = ar.expand_angles(s).unwrap();
    /// assert_eq!(ar.to_text(e), "sin(a)*cos(b) - cos(a)*sin(b)");
    /// ```
    pub fn expand_angles(&mut self, e: ExprId) -> Res {
        Ok(self.expand_angles_many(&[e])?[0])
    }

    /// [`Arena::expand_angles`] over several roots sharing one traversal.
    pub fn expand_angles_many(&mut self, roots: &[ExprId]) -> Result<Vec<ExprId>, ExprError> {
        self.map_bottom_up(
            roots,
            |_| false,
            |ar, id, kids| {
                let Node::Func(f @ (Func::Sin | Func::Cos | Func::Tan), _) = *ar.node(id) else {
                    return Ok(None);
                };
                if !ar.is_compound_angle(kids[0]) {
                    return Ok(None);
                }
                let (s, c) = ar.sin_cos(kids[0])?;
                Ok(Some(match f {
                    Func::Sin => s,
                    Func::Cos => c,
                    _ => ar.div(s, c)?,
                }))
            },
        )
    }

    /// Whether `x` is a sum of angles or an integer multiple of one, as split by
    /// [`Arena::sin_cos`].
    fn is_compound_angle(&self, x: ExprId) -> bool {
        match self.node(x) {
            Node::Sum(t) => t.len() <= MAX_SPLIT_TERMS,
            Node::Product(_) => self.integer_multiple(x).is_some(),
            _ => false,
        }
    }

    /// `(n, a)` when `x = n a` for an integer `n` with `2 <= |n| <= MAX_MULTIPLE` (or `n = -1`).
    fn integer_multiple(&self, x: ExprId) -> Option<(i64, ExprId)> {
        let Node::Product(f) = self.node(x) else { return None };
        let n = self.as_rational(f[0]).and_then(|r| r.as_i64())?;
        let ok = n == -1 || (2..=MAX_MULTIPLE).contains(&n.abs());
        (ok && f.len() >= 2).then_some((n, f[0]))
    }

    /// The sine and cosine of `x`, split over the terms of a sum and over integer multiples.
    fn sin_cos(&mut self, x: ExprId) -> Result<(ExprId, ExprId), ExprError> {
        if let Node::Sum(t) = self.node(x) {
            if t.len() <= MAX_SPLIT_TERMS {
                let terms = t.to_vec();
                let (mut s, mut c) = self.sin_cos(terms[0])?;
                for &t in &terms[1..] {
                    let (st, ct) = self.sin_cos(t)?;
                    (s, c) = self.angle_sum((s, c), (st, ct))?;
                }
                return Ok((s, c));
            }
        }
        if let Some((n, coefficient)) = self.integer_multiple(x) {
            let single = self.div(x, coefficient)?;
            let one = self.sin_cos(single)?;
            let mut acc = one;
            for _ in 1..n.abs() {
                acc = self.angle_sum(acc, one)?;
            }
            let s = if n < 0 { self.neg(acc.0)? } else { acc.0 };
            return Ok((s, acc.1));
        }
        Ok((self.sin(x)?, self.cos(x)?))
    }

    /// `(sin(a + b), cos(a + b))` from `(sin a, cos a)` and `(sin b, cos b)`.
    fn angle_sum(
        &mut self,
        (sa, ca): (ExprId, ExprId),
        (sb, cb): (ExprId, ExprId),
    ) -> Result<(ExprId, ExprId), ExprError> {
        let sc = self.mul(&[sa, cb])?;
        let cs = self.mul(&[ca, sb])?;
        let cc = self.mul(&[ca, cb])?;
        let ss = self.mul(&[sa, sb])?;
        Ok((self.add(&[sc, cs])?, self.sub(cc, ss)?))
    }

    /// `e` with its angles expanded and put in the trigonometric canonical form: equal
    /// expressions that differ only in how angles are combined become the same.
    pub fn reduce_angles(&mut self, e: ExprId) -> Res {
        let split = self.expand_angles(e)?;
        Ok(self.trig_canonical_many(&[split], TrigBasis::Cos)?[0])
    }

    /// Whether `simplified` (as [`Arena::simplify`] gives it) is identically zero once angles
    /// are expanded and the sum is put over a common denominator (wherever its denominators do
    /// not vanish). `false` means "not shown", including when the expansion would be too large.
    pub fn proves_zero_over_common_denominator(&mut self, simplified: ExprId) -> bool {
        self.zero_over_common_denominator(simplified).unwrap_or(false)
    }

    fn zero_over_common_denominator(&mut self, simplified: ExprId) -> Result<bool, ExprError> {
        let split = self.expand_angles(simplified)?;
        // Without a compound angle the canonical form is already `simplified`'s.
        let reduced = if split == simplified {
            simplified
        } else {
            self.trig_canonical_many(&[split], TrigBasis::Cos)?[0]
        };
        if self.is_zero(reduced) {
            return Ok(true);
        }
        let Some(d) = self.sum_denominators(reduced)? else { return Ok(false) };
        // Term by term, so that each term's own denominators cancel before expansion.
        let terms = self.terms(reduced);
        let cleared = terms.into_iter().map(|t| self.mul(&[t, d])).collect::<Result<Vec<_>, _>>()?;
        let cleared = self.add(&cleared)?;
        let numerator = self.trig_canonical_many(&[cleared], TrigBasis::Cos)?[0];
        Ok(self.is_zero(numerator))
    }

    /// The product of the sums that the terms of `e` divide by, each to its highest power, or
    /// `None` when no term divides by a sum.
    fn sum_denominators(&mut self, e: ExprId) -> Result<Option<ExprId>, ExprError> {
        let mut highest: Vec<(ExprId, i64)> = Vec::new();
        for t in self.terms(e) {
            for f in self.factors(t) {
                let Node::Pow([base, exponent]) = *self.node(f) else { continue };
                let Some(n) = self.as_rational(exponent).and_then(|r| r.as_i64()) else { continue };
                if n >= 0 || !matches!(self.node(base), Node::Sum(_)) {
                    continue;
                }
                match highest.iter_mut().find(|(b, _)| *b == base) {
                    Some((_, k)) => *k = (*k).max(-n),
                    None => highest.push((base, -n)),
                }
            }
        }
        if highest.is_empty() {
            return Ok(None);
        }
        let powers = highest.into_iter().map(|(b, k)| self.powi(b, k)).collect::<Result<Vec<_>, _>>()?;
        Ok(Some(self.mul(&powers)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_differences_and_double_angles_vanish() {
        // sin(a - b) - sin(a + b) + 2 cos(a) sin(b) = 0 and cos(2a) - 1 + 2 sin(a)^2 = 0.
        let mut ar = Arena::new();
        let [a, b] = ["a", "b"].map(|n| ar.constant(n).unwrap());
        let (d, s) = (ar.sub(a, b).unwrap(), ar.add(&[a, b]).unwrap());
        let (sd, ss) = (ar.sin(d).unwrap(), ar.sin(s).unwrap());
        let (ca, sb) = (ar.cos(a).unwrap(), ar.sin(b).unwrap());
        let two = ar.integer(2);
        let k = ar.mul(&[two, ca, sb]).unwrap();
        let diff = ar.sub(sd, ss).unwrap();
        let e = ar.add(&[diff, k]).unwrap();
        assert_eq!(ar.reduce_angles(e).unwrap(), ar.zero());
        let a2 = ar.mul(&[two, a]).unwrap();
        let c2 = ar.cos(a2).unwrap();
        let sa = ar.sin(a).unwrap();
        let sa2 = ar.powi(sa, 2).unwrap();
        let t = ar.mul(&[two, sa2]).unwrap();
        let m1 = ar.minus_one();
        let e = ar.add(&[c2, m1, t]).unwrap();
        assert_eq!(ar.reduce_angles(e).unwrap(), ar.zero());
    }

    #[test]
    fn a_common_denominator_shows_a_quotient_equal() {
        // x/(1 + cos(2a)) - x/(2 cos(a)^2) = 0
        let mut ar = Arena::new();
        let [x, a] = ["x", "a"].map(|n| ar.constant(n).unwrap());
        let (one, two) = (ar.one(), ar.integer(2));
        let a2 = ar.mul(&[two, a]).unwrap();
        let c2 = ar.cos(a2).unwrap();
        let den1 = ar.add(&[one, c2]).unwrap();
        let q1 = ar.div(x, den1).unwrap();
        let ca = ar.cos(a).unwrap();
        let ca2 = ar.powi(ca, 2).unwrap();
        let den2 = ar.mul(&[two, ca2]).unwrap();
        let q2 = ar.div(x, den2).unwrap();
        let e = ar.sub(q1, q2).unwrap();
        let simplified = ar.simplify(e).unwrap();
        assert!(!ar.is_zero(simplified));
        assert!(ar.proves_zero_over_common_denominator(simplified));
        let wrong = ar.add(&[e, x]).unwrap();
        let wrong = ar.simplify(wrong).unwrap();
        assert!(!ar.proves_zero_over_common_denominator(wrong));
    }

    #[test]
    fn a_non_integer_multiple_stays_one_angle() {
        let mut ar = Arena::new();
        let a = ar.constant("a").unwrap();
        let half = ar.rational(1, 2).unwrap();
        let h = ar.mul(&[half, a]).unwrap();
        let s = ar.sin(h).unwrap();
        assert_eq!(ar.expand_angles(s).unwrap(), s);
    }
}
