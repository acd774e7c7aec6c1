//! Autolev's algebra on matrices and series: INV (a symbolic inverse by cofactors), EIG (the
//! eigenvalues of a matrix of numbers) and TAYLOR (a truncated series about a point).
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
            "INV" => self.inverse(args, e),
            "EIG" => self.eigenvalues(args, e),
            _ => self.taylor(args, e),
        }
    }

    /// A square matrix argument as rows.
    fn square_rows(
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

    /// `EIG(M)` of a matrix of numbers: its eigenvalues, ascending, when they are all real.
    fn eigenvalues(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        if args.len() > 1 {
            return Err(Diagnostic::error(
                e.span.clone(),
                "EIG with output names (EIG(M, VALUES, VECTORS)) is not supported",
            )
            .with_help("write VALUES = EIG(M) for the eigenvalues"));
        }
        let rows = self.square_rows("EIG", args, e, usize::MAX)?;
        let n = rows.len();
        let mut m = nalgebra::DMatrix::zeros(n, n);
        for (i, row) in rows.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                m[(i, j)] = self.model.ar.as_number(*x).map(|v| v.to_f64()).ok_or_else(|| {
                    Diagnostic::error(args[0].span.clone(), "EIG needs a matrix of numbers; this one has symbols")
                        .with_help("evaluate it first (EVALUATE(M, X = value, ...)); for the equations' eigenvalues use `kane linearize`")
                })?;
            }
        }
        let values = m.complex_eigenvalues();
        let scale = values.iter().map(|z| z.norm()).fold(1.0, f64::max);
        if let Some(z) = values.iter().find(|z| z.im.abs() > 1e-12 * scale) {
            return Err(Diagnostic::error(
                e.span.clone(),
                format!("EIG: the matrix has complex eigenvalues ({} {:+}i and more), which values here cannot hold", z.re, z.im),
            ));
        }
        let mut real: Vec<f64> = values.iter().map(|z| z.re).collect();
        real.sort_by(f64::total_cmp);
        let data = real.into_iter().map(|x| self.model.ar.float(x)).collect::<Result<_, _>>().at(&e.span)?;
        Ok(Value::Matrix { rows: n, cols: 1, data })
    }

    /// `TAYLOR(F, lo:hi, X = a, Y = b, ...)`: the terms of total order `lo` to `hi` of `F`'s
    /// series about the point, `sum_k g^(k)(0) / k!` with `g(s) = F(a + s (x - a))`.
    fn taylor(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let usage = || Diagnostic::error(e.span.clone(), "TAYLOR takes (F, lo:hi, X = a, ...)");
        let (Some(f), Some(Expr { kind: ExprKind::Range(lo, hi), .. })) = (args.first(), args.get(1)) else {
            return Err(usage());
        };
        let (lo, hi) = (self.index_value(lo)?, self.index_value(hi)?);
        if lo < 0 || hi < lo || hi > 20 {
            return Err(Diagnostic::error(args[1].span.clone(), "TAYLOR orders must be 0 <= lo <= hi <= 20"));
        }
        let s = self.model.ar.constant("TAYLOR'S PARAMETER").at(&e.span)?;
        let s_symbol = self.model.ar.as_symbol(s).ok_or_else(usage)?;
        let mut along = FxHashMap::default();
        for a in &args[2..] {
            let ExprKind::NamedArg(name, value) = &a.kind else { return Err(usage()) };
            let x = self.scalar(&Expr {
                kind: ExprKind::Name { name: name.clone(), primes: 0, suffix: 0 },
                span: a.span.clone(),
            })?;
            let point = self.scalar(value)?;
            // x -> a + s (x - a)
            let ar = &mut self.model.ar;
            let offset = ar.sub(x, point).at(&a.span)?;
            let moved = ar.mul(&[s, offset]).at(&a.span)?;
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
