//! A cheap bound on how large expansion makes an expression, found without expanding it.
//!
//! Expanding multiplies out products of sums, so a DAG of a few hundred nodes can expand into
//! millions of terms. [`Arena::expansion_bounds`] follows the same rules as
//! [`Arena::trig_canonical_many`] on term counts only, in one pass over the DAG.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::node::{ExprId, Func, Node};

/// Largest sum power expansion multiplies out (as in `expand.rs`).
const MAX_POWER: i64 = 64;

impl Arena {
    /// For each root, an upper bound (saturating) on the terms of the largest sum that
    /// expanding it into the trigonometric canonical form builds, itself or in any
    /// subexpression. One pass over the DAG of all roots.
    pub fn expansion_bounds(&self, roots: &[ExprId]) -> Vec<u64> {
        // Per node: (terms of its expansion, most terms met while expanding it).
        let mut bound: FxHashMap<ExprId, (u64, u64)> = FxHashMap::default();
        for id in self.bottom_up(roots, |_| false) {
            let kids = self.node(id).children();
            let worst = kids.iter().map(|c| bound[c].1).max().unwrap_or(1);
            let terms = |c: &ExprId| bound[c].0;
            let (t, w) = match self.node(id) {
                Node::Sum(c) => (c.iter().map(terms).fold(0, u64::saturating_add), 0),
                Node::Product(c) => (c.iter().map(terms).fold(1, u64::saturating_mul), 0),
                Node::Pow([b, x]) => self.power_bound(*b, bound[b].0, *x),
                _ => (1, 0),
            };
            bound.insert(id, (t, worst.max(t).max(w)));
        }
        roots.iter().map(|r| bound[r].1).collect()
    }

    /// (terms, work) of `b^x` where `b` expands into `tb` terms: an integer power of a sum is
    /// multiplied out (its inverse too, then inverted), an even power of sine or cosine
    /// becomes a power of `1 - cos^2` (or `1 - sin^2`).
    fn power_bound(&self, b: ExprId, tb: u64, x: ExprId) -> (u64, u64) {
        let Some(n) = self.as_rational(x).and_then(|r| r.as_i64()) else { return (1, 0) };
        let pow = |k: i64| tb.saturating_pow(u32::try_from(k).unwrap_or(u32::MAX));
        match self.node(b) {
            Node::Sum(_) if (2..=MAX_POWER).contains(&n) => (pow(n), 0),
            Node::Sum(_) if (-MAX_POWER..=-2).contains(&n) => (1, pow(-n)),
            Node::Func(Func::Sin | Func::Cos, _) if n >= 2 => {
                let t = u64::try_from(n / 2 + 1).unwrap_or(u64::MAX);
                (t, t)
            }
            _ => (1, 0),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::expr::Arena;

    #[test]
    fn bounds_follow_expansion_without_expanding() {
        let mut ar = Arena::new();
        let xs: Vec<_> = (0..40).map(|i| ar.constant(&format!("x{i}")).unwrap()).collect();
        let one = ar.one();
        // (x0 + 1)*(x1 + 1)*...*(x39 + 1): 2^40 terms expanded.
        let factors: Vec<_> = xs.iter().map(|x| ar.add(&[*x, one]).unwrap()).collect();
        let big = ar.mul(&factors).unwrap();
        let small = ar.mul(&factors[..3]).unwrap();
        let sq = ar.powi(factors[0], 2).unwrap();
        let c = ar.cos(big).unwrap();
        let bounds = ar.expansion_bounds(&[big, small, sq, c, xs[0]]);
        assert_eq!(bounds[0], 1 << 40);
        assert_eq!(bounds[1], 8);
        assert_eq!(bounds[2], 4);
        assert_eq!(bounds[3], 1 << 40, "the argument of a function is expanded too");
        assert_eq!(bounds[4], 1);
        let expanded = ar.expand(small).unwrap();
        assert!(ar.node(expanded).children().len() as u64 <= bounds[1]);
    }
}
