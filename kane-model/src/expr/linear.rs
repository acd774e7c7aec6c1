//! Coefficients of expressions linear in a set of symbols.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, SymbolId};

impl Arena {
    /// Splits `e = sum(c_i * s_i) + r` for `e` linear in `syms`; returns `(c, r)`.
    ///
    /// This is how a mass matrix is read off the equations: the coefficients of `u'`.
    pub fn linear_coefficients(
        &mut self,
        e: ExprId,
        syms: &[SymbolId],
    ) -> Result<(Vec<ExprId>, ExprId), ExprError> {
        let mut coeffs = Vec::with_capacity(syms.len());
        for &s in syms {
            let c = self.diff(e, s)?;
            let free = self.free_symbols(&[c]);
            if let Some(&bad) = syms.iter().find(|x| free.contains(x)) {
                return Err(ExprError::NotLinear {
                    expr: self.to_text(e),
                    symbol: self.symbol_info(bad).name.clone(),
                });
            }
            coeffs.push(c);
        }
        let zero = self.zero();
        let mut map = FxHashMap::default();
        for &s in syms {
            map.insert(self.symbol_expr(s), zero);
        }
        let rest = self.subs(e, &map)?;
        Ok((coeffs, rest))
    }
}

impl Arena {
    /// Solves equations (each `= 0`, linear in `unknowns`) for the unknowns by Gauss-Jordan
    /// elimination with the first structurally non-zero pivot.
    pub fn solve_linear(
        &mut self,
        equations: &[ExprId],
        unknowns: &[SymbolId],
    ) -> Result<Vec<ExprId>, ExprError> {
        let m = unknowns.len();
        if equations.len() != m {
            return Err(ExprError::SingularSystem);
        }
        let mut rows: Vec<(Vec<ExprId>, ExprId)> = Vec::with_capacity(m);
        for &g in equations {
            let (coeffs, rest) = self.linear_coefficients(g, unknowns)?;
            let rhs = self.neg(rest)?;
            rows.push((coeffs, rhs));
        }
        for col in 0..m {
            let pivot = (col..m).find(|&r| !self.is_zero(rows[r].0[col])).ok_or(ExprError::SingularSystem)?;
            rows.swap(col, pivot);
            let p = rows[col].0[col];
            for r in 0..m {
                if r == col || self.is_zero(rows[r].0[col]) {
                    continue;
                }
                let factor = self.div(rows[r].0[col], p)?;
                for k in 0..m {
                    let t = self.mul(&[factor, rows[col].0[k]])?;
                    rows[r].0[k] = self.sub(rows[r].0[k], t)?;
                }
                let t = self.mul(&[factor, rows[col].1])?;
                rows[r].1 = self.sub(rows[r].1, t)?;
            }
        }
        (0..m).map(|i| self.div(rows[i].1, rows[i].0[i])).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_off_coefficients() {
        let mut ar = Arena::new();
        let [a, x, y] = ["a", "x", "y"].map(|n| ar.constant(n).unwrap());
        let sx = ar.as_symbol(x).unwrap();
        let sy = ar.as_symbol(y).unwrap();
        let sa = ar.sin(a).unwrap();
        let t1 = ar.mul(&[sa, x]).unwrap();
        let three = ar.integer(3);
        let t2 = ar.mul(&[three, y]).unwrap();
        let e = ar.add(&[t1, t2, a]).unwrap();
        let (c, r) = ar.linear_coefficients(e, &[sx, sy]).unwrap();
        assert_eq!(c, vec![sa, three]);
        assert_eq!(r, a);
    }

    #[test]
    fn solves_a_linear_system() {
        let mut ar = Arena::new();
        let [a, b, x, y] = ["a", "b", "x", "y"].map(|n| ar.constant(n).unwrap());
        let (sx, sy) = (ar.as_symbol(x).unwrap(), ar.as_symbol(y).unwrap());
        // a x + b y - 1 = 0, x - y = 0  =>  x = y = 1 / (a + b)
        let ax = ar.mul(&[a, x]).unwrap();
        let by = ar.mul(&[b, y]).unwrap();
        let m1 = ar.minus_one();
        let e1 = ar.add(&[ax, by, m1]).unwrap();
        let e2 = ar.sub(x, y).unwrap();
        let sol = ar.solve_linear(&[e1, e2], &[sx, sy]).unwrap();
        let v = ar.eval_named(sol[0], &[("a", 2.0), ("b", 3.0)]).unwrap();
        assert!((v - 0.2).abs() < 1e-15);
        let z = ar.zero();
        assert_eq!(ar.solve_linear(&[z, e2], &[sx, sy]), Err(ExprError::SingularSystem));
    }

    #[test]
    fn nonlinear_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let sx = ar.as_symbol(x).unwrap();
        let e = ar.powi(x, 2).unwrap();
        assert!(matches!(ar.linear_coefficients(e, &[sx]), Err(ExprError::NotLinear { .. })));
    }
}
