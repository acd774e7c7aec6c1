//! Numeric evaluation of expressions, generic over the float type.

use num_traits::Float;
use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId};
use super::number::Number;

/// `x ^ e` for a numeric exponent, using `powi` and `sqrt` where they are exact.
pub(crate) fn pow_number<T: Float>(x: T, e: Number) -> T {
    match e {
        Number::Rational(r) if r.is_integer() => match r.as_i64().and_then(|k| i32::try_from(k).ok()) {
            Some(k) => x.powi(k),
            None => x.powf(T::from(r.to_f64()).unwrap_or_else(T::nan)),
        },
        Number::Rational(r) if r.denom() == 2 && r.numer() == 1 => x.sqrt(),
        Number::Rational(r) if r.denom() == 2 && r.numer() == -1 => x.sqrt().recip(),
        _ => x.powf(T::from(e.to_f64()).unwrap_or_else(T::nan)),
    }
}

/// A number as `T`.
pub(crate) fn number_as<T: Float>(n: Number) -> T {
    match n {
        Number::Rational(r) => {
            let (p, q) = (T::from(r.numer()), T::from(r.denom()));
            match (p, q) {
                (Some(p), Some(q)) => p / q,
                _ => T::from(r.to_f64()).unwrap_or_else(T::nan),
            }
        }
        Number::Float(x) => T::from(x).unwrap_or_else(T::nan),
    }
}

impl Arena {
    /// Evaluates `roots` with symbol values from `value_of`; errors on a missing value or a
    /// non-finite result.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let sx = ar.as_symbol(x).unwrap();
    /// let e = ar.sin(x).unwrap();
    /// let v = ar.eval::<f64>(&[e], |s| (s == sx).then_some(0.5)).unwrap();
    /// assert_eq!(v[0], 0.5f64.sin());
    /// ```
    pub fn eval<T: Float>(
        &self,
        roots: &[ExprId],
        value_of: impl Fn(SymbolId) -> Option<T>,
    ) -> Result<Vec<T>, ExprError> {
        let order = self.bottom_up(roots, |_| false);
        let mut vals: FxHashMap<ExprId, T> = FxHashMap::default();
        for id in order {
            let v = match self.node(id) {
                Node::Rational(_) | Node::Float(_) => number_as(self.as_number(id).unwrap_or(Number::ZERO)),
                Node::Symbol(s) => value_of(*s)
                    .ok_or_else(|| ExprError::MissingBinding(self.symbol_info(*s).name.clone()))?,
                Node::Sum(t) => t.iter().fold(T::zero(), |acc, c| acc + vals[c]),
                Node::Product(f) => f.iter().fold(T::one(), |acc, c| acc * vals[c]),
                Node::Pow([b, e]) => match self.as_number(*e) {
                    Some(n) => pow_number(vals[b], n),
                    None => vals[b].powf(vals[e]),
                },
                Node::Func(f, x) => f.apply(vals[x]),
                Node::Atan2([y, x]) => vals[y].atan2(vals[x]),
            };
            vals.insert(id, v);
        }
        roots
            .iter()
            .map(|r| {
                let v = vals[r];
                if v.is_finite() {
                    Ok(v)
                } else {
                    Err(ExprError::NotFinite {
                        expr: self.to_text(*r),
                        value: v.to_f64().unwrap_or(f64::NAN),
                    })
                }
            })
            .collect()
    }

    /// Evaluates one expression in `f64` with values given by name.
    pub fn eval_named(&self, e: ExprId, values: &[(&str, f64)]) -> Result<f64, ExprError> {
        let by_sym: FxHashMap<SymbolId, f64> =
            values.iter().filter_map(|(n, v)| self.lookup(n).map(|s| (s, *v))).collect();
        Ok(self.eval(&[e], |s| by_sym.get(&s).copied())?[0])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_binding_is_named() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let y = ar.constant("y").unwrap();
        let e = ar.add(&[x, y]).unwrap();
        assert_eq!(ar.eval_named(e, &[("x", 1.0)]), Err(ExprError::MissingBinding("y".into())));
        assert_eq!(ar.eval_named(e, &[("x", 1.0), ("y", 2.0)]), Ok(3.0));
    }

    #[test]
    fn non_finite_result_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let e = ar.func(super::super::node::Func::Ln, x).unwrap();
        assert!(matches!(ar.eval_named(e, &[("x", -1.0)]), Err(ExprError::NotFinite { .. })));
    }
}
