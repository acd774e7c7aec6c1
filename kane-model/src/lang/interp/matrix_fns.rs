//! Matrix functions: TRANSPOSE, TRACE, DET, ELEMENT, DIAGMAT, ROWS, COLS, and the conversions
//! MATRIX (a dyadic's measure numbers in a frame) and VECTOR (a column of measure numbers).
//!
//! In: the upper-cased function name and its argument expressions (a scalar counts as a 1x1
//! matrix). Out: a matrix, scalar or vector [`Value`], or a diagnostic for a bad argument count,
//! size or index.

use crate::expr::ExprId;
use crate::mechanics::Vector;

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::{matrix_position, Value};
use super::{At, IResult, Interpreter};

/// A matrix argument: rows, columns and entries row by row.
type Matrix = (usize, usize, Vec<ExprId>);

impl Interpreter {
    /// TRANSPOSE, TRACE, DET, ELEMENT, DIAGMAT, ROWS, COLS, MATRIX, VECTOR.
    pub(super) fn matrix_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        check_arguments(upper, args, &e.span)?;
        let fail: &Span = &e.span;
        match upper {
            "TRANSPOSE" => {
                let (r, c, d) = self.matrix_arg(&args[0])?;
                let data =
                    (0..c).flat_map(|j| (0..r).map(move |i| (i, j))).map(|(i, j)| d[i * c + j]).collect();
                Ok(Value::Matrix { rows: c, cols: r, data })
            }
            "TRACE" => {
                let (r, c, d) = self.matrix_arg(&args[0])?;
                let diag: Vec<ExprId> = (0..r.min(c)).map(|i| d[i * c + i]).collect();
                Ok(Value::Scalar(self.model.ar.add(&diag).at(fail)?))
            }
            "DET" => {
                let (r, c, d) = self.matrix_arg(&args[0])?;
                if r != c || r > 4 {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        "DET needs a square matrix of size 4 or less",
                    ));
                }
                let rows: Vec<Vec<ExprId>> = d.chunks(c).map(<[ExprId]>::to_vec).collect();
                Ok(Value::Scalar(self.model.ar.determinant(&rows).at(fail)?))
            }
            "ELEMENT" => {
                let (r, c, d) = self.matrix_arg(&args[0])?;
                let i = self.index_value(&args[1])?;
                let j = self.index_value(&args[2])?;
                matrix_position(&[i, j], r, c).map(|k| Value::Scalar(d[k])).ok_or_else(|| {
                    Diagnostic::error(
                        e.span.clone(),
                        format!("ELEMENT({i}, {j}) is outside the {r}x{c} matrix"),
                    )
                })
            }
            "DIAGMAT" => self.diagonal_matrix(args, e),
            "ROWS" | "COLS" => self.rows_or_columns(upper, args, e),
            "MATRIX" => self.dyadic_matrix(args, e),
            _ => self.column_vector(args),
        }
    }

    /// A matrix argument (a scalar is 1x1).
    fn matrix_arg(&mut self, a: &Expr) -> IResult<Matrix> {
        match self.eval(a)? {
            Value::Matrix { rows, cols, data } => Ok((rows, cols, data)),
            Value::Scalar(x) => Ok((1, 1, vec![x])),
            other => {
                Err(Diagnostic::error(a.span.clone(), format!("expected a matrix, found {}", other.kind())))
            }
        }
    }

    /// `DIAGMAT(n, x)` or `DIAGMAT(rows, cols, x)`.
    fn diagonal_matrix(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let (n, m, x) = match args.len() {
            2 => (self.index_value(&args[0])? as usize, None, self.scalar(&args[1])?),
            3 => (
                self.index_value(&args[0])? as usize,
                Some(self.index_value(&args[1])? as usize),
                self.scalar(&args[2])?,
            ),
            _ => return Err(Diagnostic::error(e.span.clone(), "DIAGMAT takes (n, x) or (rows, cols, x)")),
        };
        let cols = m.unwrap_or(n);
        if !(1..=1000).contains(&n) || !(1..=1000).contains(&cols) {
            return Err(Diagnostic::error(e.span.clone(), "DIAGMAT sizes must be between 1 and 1000"));
        }
        let z = self.model.ar.zero();
        let data = (0..n * cols).map(|k| if k / cols == k % cols { x } else { z }).collect();
        Ok(Value::Matrix { rows: n, cols, data })
    }

    /// `ROWS(M)` / `COLS(M)`: the count; `ROWS(M, i, j:k, ...)`: the rows (or columns) picked.
    fn rows_or_columns(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let (r, c, d) = self.matrix_arg(&args[0])?;
        let rows = upper == "ROWS";
        let limit = if rows { r } else { c };
        if args.len() == 1 {
            return Ok(Value::Scalar(self.model.ar.integer(limit as i128)));
        }
        let mut picks = Vec::new();
        for a in &args[1..] {
            match &a.kind {
                ExprKind::Range(lo, hi) => {
                    let (lo, hi) = (self.index_value(lo)?, self.index_value(hi)?);
                    if lo < 1 || hi > limit as i64 || lo > hi {
                        return Err(Diagnostic::error(
                            a.span.clone(),
                            format!("{upper} range {lo}:{hi} is outside 1..{limit}"),
                        ));
                    }
                    picks.extend(lo..=hi);
                }
                _ => picks.push(self.index_value(a)?),
            }
        }
        if picks.iter().any(|p| *p < 1 || *p as usize > limit) {
            return Err(Diagnostic::error(e.span.clone(), format!("{upper} index out of range 1..{limit}")));
        }
        let picks: Vec<usize> = picks.into_iter().map(|p| p as usize - 1).collect();
        let mut data = Vec::new();
        if rows {
            for p in &picks {
                data.extend_from_slice(&d[p * c..(p + 1) * c]);
            }
            Ok(Value::Matrix { rows: picks.len(), cols: c, data })
        } else {
            for i in 0..r {
                data.extend(picks.iter().map(|p| d[i * c + p]));
            }
            Ok(Value::Matrix { rows: r, cols: picks.len(), data })
        }
    }

    /// `MATRIX(A, D>>)`: the measure numbers `A_i . D . A_j` of a dyadic; `MATRIX(A, V>)` the
    /// column of a vector's measure numbers in A.
    fn dyadic_matrix(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        let f = self.frame_arg(&args[0])?;
        let dy = match self.eval(&args[1])? {
            Value::Dyadic(dy) => dy,
            Value::Vector(v) => {
                let data = self.model.express(&v, f).at(fail)?.to_vec();
                return Ok(Value::Matrix { rows: 3, cols: 1, data });
            }
            _ => {
                return Err(Diagnostic::error(
                    args[1].span.clone(),
                    "MATRIX takes a frame and a dyadic or a vector",
                ))
            }
        };
        let mut data = Vec::with_capacity(9);
        for i in 1..=3 {
            for j in 1..=3 {
                let ui = self.model.unit(f, i);
                let uj = self.model.unit(f, j);
                let dj = self.model.dyadic_dot(&dy, &uj).at(fail)?;
                data.push(self.model.dot(&ui, &dj).at(fail)?);
            }
        }
        Ok(Value::Matrix { rows: 3, cols: 3, data })
    }

    /// `VECTOR(A, [x; y; z])` or `VECTOR(A, x, y, z)`: the vector with those measure numbers
    /// in A.
    fn column_vector(&mut self, args: &[Expr]) -> IResult<Value> {
        let f = self.frame_arg(&args[0])?;
        let d = if args.len() == 4 {
            args[1..].iter().map(|a| self.scalar(a)).collect::<IResult<Vec<_>>>()?
        } else {
            self.matrix_arg(&args[1])?.2
        };
        if d.len() != 3 {
            return Err(Diagnostic::error(args[1].span.clone(), "VECTOR needs three measure numbers"));
        }
        Ok(Value::Vector(Vector::new(f, [d[0], d[1], d[2]])))
    }
}

/// An error unless the number of arguments suits the function.
fn check_arguments(upper: &str, args: &[Expr], span: &Span) -> IResult<()> {
    let (least, most) = match upper {
        "TRANSPOSE" | "TRACE" | "DET" => (1, 1),
        "ELEMENT" => (3, 3),
        "DIAGMAT" => (2, 3),
        "MATRIX" => (2, 2),
        "VECTOR" => (2, 4),
        _ => (1, usize::MAX),
    };
    if (least..=most).contains(&args.len()) {
        return Ok(());
    }
    let range = if most == least {
        String::new()
    } else if most == usize::MAX {
        " or more".into()
    } else {
        format!(" to {most}")
    };
    Err(Diagnostic::error(
        span.clone(),
        format!("{upper} takes {least}{range} arguments, got {}", args.len()),
    ))
}
