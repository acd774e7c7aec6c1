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
    fn nonlinear_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let sx = ar.as_symbol(x).unwrap();
        let e = ar.powi(x, 2).unwrap();
        assert!(matches!(ar.linear_coefficients(e, &[sx]), Err(ExprError::NotLinear { .. })));
    }
}
