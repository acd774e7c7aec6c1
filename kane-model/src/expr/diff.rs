//! Partial derivatives and total time derivatives.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Func, Node, SymbolId, SymbolKind};
use super::number::Number;

type Res = Result<ExprId, ExprError>;

impl Arena {
    /// The partial derivative of `e` with respect to the symbol `s` (memoised per arena).
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let s = ar.as_symbol(x).unwrap();
    /// let e = ar.sin(x).unwrap();
    /// let d = ar.diff(e, s).unwrap();
    /// assert_eq!(d, ar.cos(x).unwrap());
    /// ```
    pub fn diff(&mut self, e: ExprId, s: SymbolId) -> Res {
        if let Some(&d) = self.diff_cache.get(&(e, s)) {
            return Ok(d);
        }
        let cache = std::mem::take(&mut self.diff_cache);
        let order = self.bottom_up(&[e], |id| cache.contains_key(&(id, s)));
        let mut memo: FxHashMap<ExprId, ExprId> =
            order.iter().filter_map(|&id| cache.get(&(id, s)).map(|&d| (id, d))).collect();
        self.diff_cache = cache;
        let result = self
            .differentiate(&order, &mut memo, &mut |ar, sym| Ok(if sym == s { ar.one() } else { ar.zero() }));
        for (&id, &d) in &memo {
            self.diff_cache.insert((id, s), d);
        }
        result?;
        Ok(memo[&e])
    }

    /// Derivative of every node of `order` (children first), given the derivative of each symbol.
    fn differentiate(
        &mut self,
        order: &[ExprId],
        memo: &mut FxHashMap<ExprId, ExprId>,
        leaf: &mut dyn FnMut(&mut Arena, SymbolId) -> Res,
    ) -> Result<(), ExprError> {
        for &id in order {
            if memo.contains_key(&id) {
                continue;
            }
            let node = self.node(id).clone();
            let d = match &node {
                Node::Rational(_) | Node::Float(_) => self.zero(),
                Node::Symbol(sym) => leaf(self, *sym)?,
                Node::Sum(terms) => {
                    let ds: Vec<ExprId> = terms.iter().map(|t| memo[t]).collect();
                    self.add(&ds)?
                }
                Node::Product(f) => {
                    let mut terms = Vec::new();
                    for (i, fi) in f.iter().enumerate() {
                        let dfi = memo[fi];
                        if dfi == self.zero() {
                            continue;
                        }
                        let mut parts: Vec<ExprId> = f.to_vec();
                        parts[i] = dfi;
                        terms.push(self.mul(&parts)?);
                    }
                    self.add(&terms)?
                }
                Node::Pow([b, e]) => self.pow_derivative(id, *b, *e, memo[b], memo[e])?,
                Node::Func(f, x) => {
                    let dx = memo[x];
                    if dx == self.zero() {
                        dx
                    } else {
                        let outer = self.func_derivative(*f, *x, id)?;
                        self.mul(&[outer, dx])?
                    }
                }
                Node::Atan2([y, x]) => {
                    // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
                    let (dy, dx) = (memo[y], memo[x]);
                    let a = self.mul(&[*x, dy])?;
                    let b = self.mul(&[*y, dx])?;
                    let num = self.sub(a, b)?;
                    let x2 = self.powi(*x, 2)?;
                    let y2 = self.powi(*y, 2)?;
                    let den = self.add(&[x2, y2])?;
                    self.div(num, den)?
                }
            };
            memo.insert(id, d);
        }
        Ok(())
    }

    fn pow_derivative(&mut self, p: ExprId, b: ExprId, e: ExprId, db: ExprId, de: ExprId) -> Res {
        let zero = self.zero();
        if db == zero && de == zero {
            return Ok(zero);
        }
        if de == zero {
            // e * b^(e-1) * db
            let m1 = self.minus_one();
            let em1 = self.add(&[e, m1])?;
            let pw = self.pow(b, em1)?;
            return self.mul(&[e, pw, db]);
        }
        // b^e * (de * ln(b) + e * db / b)
        let lnb = self.func(Func::Ln, b)?;
        let t1 = self.mul(&[de, lnb])?;
        let t2 = if db == zero {
            zero
        } else {
            let q = self.div(db, b)?;
            self.mul(&[e, q])?
        };
        let s = self.add(&[t1, t2])?;
        self.mul(&[p, s])
    }

    /// `f'(x)`, where `fx` is `f(x)` itself.
    fn func_derivative(&mut self, f: Func, x: ExprId, fx: ExprId) -> Res {
        let one = self.one();
        Ok(match f {
            Func::Sin => self.cos(x)?,
            Func::Cos => {
                let s = self.sin(x)?;
                self.neg(s)?
            }
            Func::Tan => {
                let t2 = self.powi(fx, 2)?;
                self.add(&[one, t2])?
            }
            Func::Asin | Func::Acos => {
                let x2 = self.powi(x, 2)?;
                let nx2 = self.neg(x2)?;
                let r = self.add(&[one, nx2])?;
                let half = self.rational(-1, 2)?;
                let inv = self.pow(r, half)?;
                if f == Func::Asin {
                    inv
                } else {
                    self.neg(inv)?
                }
            }
            Func::Atan => {
                let x2 = self.powi(x, 2)?;
                let d = self.add(&[one, x2])?;
                self.powi(d, -1)?
            }
            Func::Exp => fx,
            Func::Ln => self.powi(x, -1)?,
            Func::Abs => self.func(Func::Sign, x)?,
            Func::Sign => self.zero(),
            Func::Sinh => self.func(Func::Cosh, x)?,
            Func::Cosh => self.func(Func::Sinh, x)?,
            Func::Tanh => {
                let t2 = self.powi(fx, 2)?;
                self.sub(one, t2)?
            }
        })
    }
}

/// Total time derivatives under given kinematic rules, memoised across calls.
///
/// A coordinate `q` differentiates to the expression its rule gives (for example `q' -> u`),
/// or else to the derivative symbol `q'`; time to 1; constants to 0.
#[derive(Default)]
pub struct TimeDerivative {
    rules: FxHashMap<SymbolId, ExprId>,
    memo: FxHashMap<ExprId, ExprId>,
}

impl TimeDerivative {
    /// No rules: every variable `x` differentiates to `x'`.
    pub fn new() -> TimeDerivative {
        TimeDerivative::default()
    }

    /// Sets `d(sym)/dt = value`; clears memoised results.
    pub fn set_rule(&mut self, sym: SymbolId, value: ExprId) {
        self.rules.insert(sym, value);
        self.memo.clear();
    }

    /// The total time derivative of `e`.
    pub fn dt(&mut self, ar: &mut Arena, e: ExprId) -> Res {
        if let Some(&d) = self.memo.get(&e) {
            return Ok(d);
        }
        let memo = &self.memo;
        let order = ar.bottom_up(&[e], |id| memo.contains_key(&id));
        let rules = &self.rules;
        ar.differentiate(&order, &mut self.memo, &mut |ar, sym| match rules.get(&sym) {
            Some(&v) => Ok(v),
            None => match ar.symbol_info(sym).kind {
                SymbolKind::Constant => Ok(ar.zero()),
                SymbolKind::Time => Ok(ar.one()),
                SymbolKind::Variable { .. } | SymbolKind::Specified { .. } => {
                    let d = ar.derivative_symbol(sym)?;
                    Ok(ar.symbol_expr(d))
                }
            },
        })?;
        Ok(self.memo[&e])
    }
}

impl Arena {
    /// The total time derivative of `e` with no kinematic rules (`q` -> `q'`).
    pub fn dt(&mut self, e: ExprId) -> Res {
        TimeDerivative::new().dt(self, e)
    }

    /// True when `e` is the exact number zero.
    pub fn is_zero(&self, e: ExprId) -> bool {
        self.as_number(e).is_some_and(Number::is_zero)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_and_chain_rule() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let s = ar.as_symbol(x).unwrap();
        let x2 = ar.powi(x, 2).unwrap();
        let sx2 = ar.sin(x2).unwrap();
        let e = ar.mul(&[x, sx2]).unwrap();
        let d = ar.diff(e, s).unwrap();
        // d/dx x sin(x^2) = sin(x^2) + 2 x^2 cos(x^2)
        let two = ar.integer(2);
        let c = ar.cos(x2).unwrap();
        let t = ar.mul(&[two, x2, c]).unwrap();
        let expected = ar.add(&[sx2, t]).unwrap();
        assert_eq!(d, expected);
    }

    #[test]
    fn time_derivative_uses_rules() {
        let mut ar = Arena::new();
        let q = ar.variable("q").unwrap();
        let u = ar.variable("u").unwrap();
        let qs = ar.as_symbol(q).unwrap();
        let mut td = TimeDerivative::new();
        td.set_rule(qs, u);
        let e = ar.sin(q).unwrap();
        let d = td.dt(&mut ar, e).unwrap();
        let c = ar.cos(q).unwrap();
        assert_eq!(d, ar.mul(&[c, u]).unwrap());
        let dd = td.dt(&mut ar, d).unwrap();
        let up = ar.lookup("u'").map(|s| ar.symbol_expr(s)).unwrap();
        let sq = ar.sin(q).unwrap();
        let u2 = ar.powi(u, 2).unwrap();
        let a = ar.mul(&[c, up]).unwrap();
        let b0 = ar.mul(&[sq, u2]).unwrap();
        let b = ar.neg(b0).unwrap();
        assert_eq!(dd, ar.add(&[a, b]).unwrap());
    }

    #[test]
    fn constants_and_time() {
        let mut ar = Arena::new();
        let m = ar.constant("m").unwrap();
        let t = ar.time();
        let e = ar.mul(&[m, t]).unwrap();
        assert_eq!(ar.dt(e).unwrap(), m);
    }
}
