//! Expansion of products and integer powers of sums, and the trigonometric canonical form.

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Func, Node};

type Res = Result<ExprId, ExprError>;

/// Which of sine and cosine keeps its even powers in a trigonometric canonical form.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum TrigBasis {
    /// `sin(x)^2` is rewritten as `1 - cos(x)^2`.
    Cos,
    /// `cos(x)^2` is rewritten as `1 - sin(x)^2`.
    Sin,
}

/// Largest positive integer power of a sum that expansion multiplies out.
const MAX_EXPANDED_POWER: i64 = 64;
/// Most terms one expanded product may have; beyond it expansion is refused, not attempted.
pub(crate) const MAX_EXPANDED_TERMS: usize = 200_000;

impl Arena {
    /// Multiplies out products of sums and positive integer powers of sums, everywhere.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let one = ar.one();
    /// let s = ar.add(&[x, one]).unwrap();
    /// let sq = ar.powi(s, 2).unwrap();
    /// let e = ar.expand(sq).unwrap();
    /// assert_eq!(ar.to_text(e), "2*x + x^2 + 1");
    /// ```
    pub fn expand(&mut self, e: ExprId) -> Res {
        Ok(self.expand_many(&[e])?[0])
    }

    /// [`Arena::expand`] over several roots sharing one traversal.
    pub fn expand_many(&mut self, roots: &[ExprId]) -> Result<Vec<ExprId>, ExprError> {
        self.map_bottom_up(
            roots,
            |_| false,
            |ar, id, kids| {
                Ok(match ar.node(id) {
                    Node::Product(_) => Some(ar.expand_product(kids)?),
                    Node::Pow(_) => Some(ar.expand_pow(kids[0], kids[1])?),
                    _ => None,
                })
            },
        )
    }

    /// The expanded product of already-expanded factors.
    fn expand_product(&mut self, factors: &[ExprId]) -> Res {
        let mut acc: Vec<ExprId> = vec![self.one()];
        for &f in factors {
            let terms = self.terms(f);
            if acc.len().saturating_mul(terms.len()) > MAX_EXPANDED_TERMS {
                return Err(ExprError::TooLarge(acc.len().saturating_mul(terms.len())));
            }
            let mut next = Vec::with_capacity(acc.len() * terms.len());
            for &a in &acc {
                for &t in &terms {
                    next.push(self.mul(&[a, t])?);
                }
            }
            acc = next;
        }
        self.add(&acc)
    }

    fn expand_pow(&mut self, base: ExprId, exponent: ExprId) -> Res {
        let n = self.as_rational(exponent).and_then(|r| r.as_i64());
        match (self.node(base), n) {
            (Node::Sum(_), Some(n)) if (2..=MAX_EXPANDED_POWER).contains(&n) => {
                let factors = vec![base; n as usize];
                self.expand_product(&factors)
            }
            (Node::Sum(_), Some(n)) if (-MAX_EXPANDED_POWER..=-2).contains(&n) => {
                let factors = vec![base; (-n) as usize];
                let p = self.expand_product(&factors)?;
                self.powi(p, -1)
            }
            _ => self.pow(base, exponent),
        }
    }

    /// Canonical form for polynomials in sines and cosines of the same arguments.
    ///
    /// Expands, rewrites `sin(x)^n` (n >= 2) as `sin(x)^(n mod 2) * (1 - cos(x)^2)^(n div 2)`, and
    /// expands again, so `sin(x)^2 + cos(x)^2 - 1` becomes 0.
    pub fn trig_simplify(&mut self, e: ExprId) -> Res {
        Ok(self.trig_simplify_many(&[e])?[0])
    }

    /// [`Arena::trig_simplify`] over several roots.
    pub fn trig_simplify_many(&mut self, roots: &[ExprId]) -> Result<Vec<ExprId>, ExprError> {
        self.trig_canonical_many(roots, TrigBasis::Cos)
    }

    /// The trigonometric canonical form in which even powers of the function other than
    /// `basis` are eliminated: with [`TrigBasis::Sin`], `cos(x)^2` becomes `1 - sin(x)^2`.
    pub fn trig_canonical_many(
        &mut self,
        roots: &[ExprId],
        basis: TrigBasis,
    ) -> Result<Vec<ExprId>, ExprError> {
        let (gone, kept) = match basis {
            TrigBasis::Cos => (Func::Sin, Func::Cos),
            TrigBasis::Sin => (Func::Cos, Func::Sin),
        };
        let untangled = self.tan_as_sin_over_cos(roots)?;
        let expanded = self.expand_many(&untangled)?;
        let rewritten = self.map_bottom_up(
            &expanded,
            |_| false,
            |ar, id, kids| {
                let Node::Pow([b, _]) = *ar.node(id) else { return Ok(None) };
                let Node::Func(f, x) = *ar.node(b) else { return Ok(None) };
                let Some(n) = ar.as_rational(kids[1]).and_then(|r| r.as_i64()) else { return Ok(None) };
                if f != gone || n < 2 {
                    return Ok(None);
                }
                let one = ar.one();
                let c = ar.func(kept, x)?;
                let c2 = ar.powi(c, 2)?;
                let s2 = ar.sub(one, c2)?;
                let p = ar.powi(s2, n / 2)?;
                let odd = ar.powi(b, n % 2)?;
                Ok(Some(ar.mul(&[odd, p])?))
            },
        )?;
        self.expand_many(&rewritten)
    }

    /// `tan(x)` rewritten as `sin(x) / cos(x)` everywhere, so that it cancels against sines and
    /// cosines in a canonical form.
    fn tan_as_sin_over_cos(&mut self, roots: &[ExprId]) -> Result<Vec<ExprId>, ExprError> {
        self.map_bottom_up(
            roots,
            |_| false,
            |ar, id, kids| {
                let Node::Func(Func::Tan, _) = ar.node(id) else { return Ok(None) };
                let s = ar.sin(kids[0])?;
                let c = ar.cos(kids[0])?;
                let inverse = ar.powi(c, -1)?;
                Ok(Some(ar.mul(&[s, inverse])?))
            },
        )
    }

    /// Expansion followed by the trigonometric canonical form.
    pub fn simplify(&mut self, e: ExprId) -> Res {
        self.trig_simplify(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_cancels_against_sine_over_cosine() {
        // 3/2 m r^2 sin(q)/cos(q) - 3/2 m r^2 tan(q), the rolling disc's M[2,3], is 0.
        let mut ar = Arena::new();
        let [m, r, q] = ["m", "r", "q"].map(|n| ar.constant(n).unwrap());
        let (s, c, t) = (ar.sin(q).unwrap(), ar.cos(q).unwrap(), ar.func(Func::Tan, q).unwrap());
        let k = ar.rational(3, 2).unwrap();
        let r2 = ar.powi(r, 2).unwrap();
        let ci = ar.powi(c, -1).unwrap();
        let a = ar.mul(&[k, m, r2, s, ci]).unwrap();
        let b = ar.mul(&[k, m, r2, t]).unwrap();
        let e = ar.sub(a, b).unwrap();
        assert_eq!(ar.simplify(e).unwrap(), ar.zero());
    }

    #[test]
    fn pythagorean_identity_vanishes() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let s = ar.sin(x).unwrap();
        let c = ar.cos(x).unwrap();
        let s2 = ar.powi(s, 2).unwrap();
        let c2 = ar.powi(c, 2).unwrap();
        let m1 = ar.minus_one();
        let e = ar.add(&[s2, c2, m1]).unwrap();
        assert_eq!(ar.simplify(e).unwrap(), ar.zero());
    }

    #[test]
    fn gimbal_like_mixed_terms_cancel() {
        // m (a sin(q) + b cos(q))^2 + m (a cos(q) - b sin(q))^2 = m (a^2 + b^2)
        let mut ar = Arena::new();
        let [m, a, b, q] = ["m", "a", "b", "q"].map(|n| ar.constant(n).unwrap());
        let (s, c) = (ar.sin(q).unwrap(), ar.cos(q).unwrap());
        let as_ = ar.mul(&[a, s]).unwrap();
        let bc = ar.mul(&[b, c]).unwrap();
        let ac = ar.mul(&[a, c]).unwrap();
        let bs = ar.mul(&[b, s]).unwrap();
        let p1 = ar.add(&[as_, bc]).unwrap();
        let p2 = ar.sub(ac, bs).unwrap();
        let p1s = ar.powi(p1, 2).unwrap();
        let p2s = ar.powi(p2, 2).unwrap();
        let sum = ar.add(&[p1s, p2s]).unwrap();
        let lhs = ar.mul(&[m, sum]).unwrap();
        let a2 = ar.powi(a, 2).unwrap();
        let b2 = ar.powi(b, 2).unwrap();
        let ab = ar.add(&[a2, b2]).unwrap();
        let rhs0 = ar.mul(&[m, ab]).unwrap();
        let rhs = ar.expand(rhs0).unwrap();
        assert_eq!(ar.simplify(lhs).unwrap(), rhs);
    }
}
