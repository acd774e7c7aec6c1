//! Autolev's algebra on matrices and series: INV (a symbolic inverse by cofactors), EIG (the
//! eigenvalues and eigenvectors of a matrix of numbers, in `eigen`) and TAYLOR (a truncated
//! series about a point).
//!
//! In: the upper-cased function name and its argument expressions. Out: a matrix or scalar
//! [`Value`], or a diagnostic that says why the call has no answer here.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::value::Value;
use super::{At, IResult, Interpreter};

/// The largest matrix INV inverts symbolically (cofactors grow factorially).
const LARGEST_INVERSE: usize = 4;

impl Interpreter {
    /// INV, EIG or TAYLOR.
    pub(super) fn algebra_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        match upper {
            "INV" | "INVERSE" => self.inverse(args, e),
            "EIG" => self.eigen(args, e),
            _ => self.taylor(args, e),
        }
    }

    /// A square matrix argument as rows.
    pub(super) fn square_rows(
        &mut self,
        name: &str,
        args: &[Expr],
        e: &Expr,
        largest: usize,
    ) -> IResult<Vec<Vec<ExprId>>> {
        let [a] = args else {
            return Err(Diagnostic::error(e.span.clone(), format!("{name} takes one square matrix")));
        };
        let (rows, cols, data) = match self.eval(a)? {
            Value::Matrix { rows, cols, data } => (rows, cols, data),
            Value::Scalar(x) => (1, 1, vec![x]),
            other => {
                return Err(Diagnostic::error(
                    a.span.clone(),
                    format!("expected a matrix, found {}", other.kind()),
                ))
            }
        };
        if rows != cols || rows > largest {
            return Err(Diagnostic::error(
                a.span.clone(),
                format!("{name} needs a square matrix of size {largest} or less, not {rows}x{cols}"),
            ));
        }
        Ok(data.chunks(cols).map(<[ExprId]>::to_vec).collect())
    }

    /// `INV(M)`: column `j` of the inverse solves `M x = e_j` by Cramer's rule.
    fn inverse(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let rows = self.square_rows("INV", args, e, LARGEST_INVERSE)?;
        let n = rows.len();
        let (zero, one) = (self.model.ar.zero(), self.model.ar.one());
        let mut data = vec![zero; n * n];
        for j in 0..n {
            let unit: Vec<ExprId> = (0..n).map(|i| if i == j { one } else { zero }).collect();
            let column = self.model.ar.solve_cramer(&rows, &unit).map_err(|_| {
                Diagnostic::error(e.span.clone(), "INV of a singular matrix: its determinant is zero")
            })?;
            for (i, x) in column.into_iter().enumerate() {
                data[i * n + j] = x;
            }
        }
        Ok(Value::Matrix { rows: n, cols: n, data })
    }

    /// `TAYLOR(F, lo:hi, X = a, Y = b, ...)`: the terms of total order `lo` to `hi` of `F`'s
    /// series about the point, `sum_k g^(k)(0) / k!` with `g(s) = F(a + s (x - a))`; an order
    /// `n` is `0:n`, and `X = a:DX` expands in the perturbation `DX` instead (`g(s) = F(a + s DX)`,
    /// as Autolev's linearisations write it); a bare `X` is `X = 0`.
    fn taylor(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let usage = || {
            Diagnostic::error(
                e.span.clone(),
                "TAYLOR takes (F, lo:hi, X = a, ...) or (F, order, X = a:DX, ...)",
            )
        };
        let (Some(f), Some(orders)) = (args.first(), args.get(1)) else { return Err(usage()) };
        let (lo, hi) = match &orders.kind {
            ExprKind::Range(lo, hi) => (self.index_value(lo)?, self.index_value(hi)?),
            _ => (0, self.index_value(orders)?),
        };
        if lo < 0 || hi < lo || hi > 20 {
            return Err(Diagnostic::error(args[1].span.clone(), "TAYLOR orders must be 0 <= lo <= hi <= 20"));
        }
        let s = self.model.ar.constant("TAYLOR'S PARAMETER").at(&e.span)?;
        let s_symbol = self.model.ar.as_symbol(s).ok_or_else(usage)?;
        let mut along = FxHashMap::default();
        let zero = Expr { kind: ExprKind::Number { value: 0.0, suffix: 0 }, span: e.span.clone() };
        for a in &args[2..] {
            // A bare name expands about 0, as `X = 0`.
            let (name, value) = match &a.kind {
                ExprKind::NamedArg(name, value) => (name.as_ref(), value.as_ref()),
                ExprKind::Name { .. } => (a, &zero),
                _ => return Err(usage()),
            };
            let x = self.substitution_key(name)?;
            let (point, step) = match &value.kind {
                ExprKind::Range(point, step) => {
                    let (point, step) = (self.scalar(point)?, self.scalar(step)?);
                    (point, step)
                }
                _ => {
                    let point = self.scalar(value)?;
                    (point, self.model.ar.sub(x, point).at(&a.span)?)
                }
            };
            // x -> a + s step
            let ar = &mut self.model.ar;
            let moved = ar.mul(&[s, step]).at(&a.span)?;
            along.insert(x, ar.add(&[point, moved]).at(&a.span)?);
        }
        let f = self.eval(f)?;
        self.map_scalars(&f, &e.span, |m, x| Ok(series(&mut m.ar, x, &along, (s_symbol, s), lo, hi)?))
    }
}

/// `sum_{k = lo..=hi} g^(k)(0) / k!` for `g(s) = x` with `along` substituted.
fn series(
    ar: &mut crate::expr::Arena,
    x: ExprId,
    along: &FxHashMap<ExprId, ExprId>,
    (s_symbol, s): (SymbolId, ExprId),
    lo: i64,
    hi: i64,
) -> Result<ExprId, crate::expr::ExprError> {
    let zero = ar.zero();
    let at_zero: FxHashMap<ExprId, ExprId> = [(s, zero)].into_iter().collect();
    let mut g = ar.subs(x, along)?;
    let mut terms = Vec::new();
    let mut factorial: i128 = 1;
    for k in 0..=hi {
        if k > 0 {
            g = ar.diff(g, s_symbol)?;
            factorial *= i128::from(k);
        }
        if k >= lo {
            let value = ar.subs(g, &at_zero)?;
            let inverse = ar.rational(1, factorial)?;
            terms.push(ar.mul(&[inverse, value])?);
        }
    }
    ar.add(&terms)
}
