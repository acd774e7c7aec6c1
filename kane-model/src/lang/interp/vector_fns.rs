//! Vector functions: DOT, CROSS, MAG, UNITVEC, EXPRESS, and the derivatives DT, D and PARTIALS.
//!
//! In: the upper-cased function name and its argument expressions. Out: a scalar or vector
//! [`Value`]; the vector work itself is done by the mechanics layer's [`crate::mechanics::Model`]
//! methods (`dot`, `cross`, `dt_in`, `partial_in`, ...).

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{At, IResult, Interpreter};
use crate::expr::ExprId;

impl Interpreter {
    /// DOT, CROSS, MAG, UNITVEC, EXPRESS, DT, D, PARTIALS.
    pub(super) fn vector_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        let arity = |n: usize| super::arity(upper, args, n, &e.span);
        match upper {
            "DOT" => {
                arity(2)?;
                self.dot_product(&args[0], &args[1], e)
            }
            "CROSS" => {
                arity(2)?;
                match (self.eval(&args[0])?, self.eval(&args[1])?) {
                    (Value::Vector(v), Value::Dyadic(d)) => {
                        Ok(Value::Dyadic(self.model.cross_dyadic(&v, &d, true).at(fail)?))
                    }
                    (Value::Dyadic(d), Value::Vector(v)) => {
                        Ok(Value::Dyadic(self.model.cross_dyadic(&v, &d, false).at(fail)?))
                    }
                    (a, b) => {
                        let (a, b) = (self.vector_of(a, &args[0])?, self.vector_of(b, &args[1])?);
                        Ok(Value::Vector(self.model.cross(&a, &b).at(fail)?))
                    }
                }
            }
            "MAG" => {
                arity(1)?;
                let v = self.vector(&args[0])?;
                Ok(Value::Scalar(self.model.magnitude(&v).at(fail)?))
            }
            "UNITVEC" => {
                arity(1)?;
                let v = self.vector(&args[0])?;
                let m = self.model.magnitude(&v).at(fail)?;
                let one = self.model.ar.one();
                let inv = self.model.ar.div(one, m).at(fail)?;
                Ok(Value::Vector(self.model.scale(&v, inv).at(fail)?))
            }
            "EXPRESS" => {
                arity(2)?;
                let v = self.eval(&args[0])?;
                let f = self.frame_arg(&args[1])?;
                Ok(match v {
                    Value::Vector(v) => Value::Vector(self.model.express_vector(&v, f).at(fail)?),
                    other => other,
                })
            }
            "DT" => self.time_derivative(args, e),
            "D" => self.derivative(args, e),
            _ => {
                arity(2)?;
                let v = self.vector(&args[0])?;
                let u = self.scalar(&args[1])?;
                let s = self
                    .model
                    .ar
                    .as_symbol(u)
                    .ok_or_else(|| Diagnostic::error(args[1].span.clone(), "PARTIALS takes a speed"))?;
                Ok(Value::Vector(self.model.partial(&v, s).at(fail)?))
            }
        }
    }

    /// `DT(x)` for the scalars of any value, `DT(v>, A)` for a vector as seen in frame A.
    fn time_derivative(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        match args.len() {
            1 => {
                let v = self.eval(&args[0])?;
                self.map_scalars(&v, &e.span, |m, x| m.dt(x))
            }
            2 => {
                let f = self.frame_arg(&args[1])?;
                match self.eval(&args[0])? {
                    // A scalar's rate is the same in every frame.
                    v @ (Value::Scalar(_) | Value::Matrix { .. }) => {
                        self.map_scalars(&v, &e.span, |m, x| m.dt(x))
                    }
                    v => {
                        let v = self.vector_of(v, &args[0])?;
                        Ok(Value::Vector(self.model.dt_in(&v, f).at(&e.span)?))
                    }
                }
            }
            _ => Err(Diagnostic::error(e.span.clone(), "DT takes (x) or (v>, frame)")),
        }
    }

    /// `D(x, y)` for the scalars of any value, `D(v>, y, A)` for a vector as seen in frame A.
    fn derivative(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        if args.len() < 2 {
            return Err(Diagnostic::error(e.span.clone(), "D takes (x, y) or (v>, y, frame)"));
        }
        if let (2, ExprKind::Matrix(list)) = (args.len(), &args[1].kind) {
            let list: Vec<Expr> = list.iter().flatten().cloned().collect();
            return self.jacobian(&args[0], &list, e);
        }
        let y = match self.eval(&args[1])? {
            // D(F, Q) with Q a column or row of symbols: the Jacobian.
            Value::Matrix { data, .. } if args.len() == 2 => {
                return self.jacobian_by(&args[0], &data, &args[1], e)
            }
            Value::Scalar(y) => y,
            other => {
                return Err(Diagnostic::error(
                    args[1].span.clone(),
                    format!("D differentiates with respect to a symbol, not {}", other.kind()),
                ))
            }
        };
        let s = self.model.ar.as_symbol(y).ok_or_else(|| {
            Diagnostic::error(args[1].span.clone(), "D differentiates with respect to a symbol")
        })?;
        let v = self.eval(&args[0])?;
        if let (3, Value::Vector(vec)) = (args.len(), &v) {
            let f = self.frame_arg(&args[2])?;
            return Ok(Value::Vector(self.model.partial_in(vec, s, f).at(&e.span)?));
        }
        self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.diff(x, s)?))
    }

    /// `D(F, [x, y, ...])`: the Jacobian, a row per entry of `F` (a scalar or a matrix's
    /// entries row by row) and a column per variable.
    fn jacobian(&mut self, f: &Expr, list: &[Expr], e: &Expr) -> IResult<Value> {
        let mut vars = Vec::new();
        for x in list {
            vars.push(self.substitution_key(x)?);
        }
        self.jacobian_by(f, &vars, &list.first().map_or_else(|| e.clone(), Clone::clone), e)
    }

    /// The Jacobian of `f` by the symbols `vars` (`at` is where they are written).
    fn jacobian_by(&mut self, f: &Expr, vars: &[ExprId], at: &Expr, e: &Expr) -> IResult<Value> {
        let vars = vars
            .iter()
            .map(|v| {
                self.model.ar.as_symbol(*v).ok_or_else(|| {
                    Diagnostic::error(at.span.clone(), "D differentiates with respect to symbols")
                })
            })
            .collect::<IResult<Vec<_>>>()?;
        let entries = match self.eval(f)? {
            Value::Scalar(x) => vec![x],
            Value::Matrix { data, .. } => data,
            other => {
                return Err(Diagnostic::error(
                    f.span.clone(),
                    format!("D(F, [x, ...]) needs a scalar or a matrix F, not {}", other.kind()),
                ))
            }
        };
        let mut data = Vec::with_capacity(entries.len() * vars.len());
        for &x in &entries {
            for &v in &vars {
                data.push(self.model.ar.diff(x, v).at(&e.span)?);
            }
        }
        Ok(Value::Matrix { rows: entries.len(), cols: vars.len(), data })
    }

    /// `DOT(a, b)` of two vectors (a scalar), or of a dyadic and a vector either way round (a
    /// vector: `D . v`, or `v . D = D^T . v`).
    fn dot_product(&mut self, a: &Expr, b: &Expr, e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        // A matrix of vectors written out (`DOT(V1>, [V2>; 2*V2>])`): the matrix of the dots.
        for (list, other, list_first) in [(b, a, false), (a, b, true)] {
            let ExprKind::Matrix(rows) = &list.kind else { continue };
            let cols = rows.first().map_or(0, Vec::len);
            if rows.iter().any(|r| r.len() != cols) {
                return Err(Diagnostic::error(list.span.clone(), "matrix rows have different lengths"));
            }
            let mut data = Vec::with_capacity(rows.len() * cols);
            for entry in rows.iter().flatten() {
                let (x, y) = if list_first { (entry, other) } else { (other, entry) };
                match self.dot_product(x, y, e)? {
                    Value::Scalar(d) => data.push(d),
                    v => {
                        return Err(Diagnostic::error(
                            entry.span.clone(),
                            format!("DOT of a matrix of vectors gives scalars, not {}", v.kind()),
                        ))
                    }
                }
            }
            return Ok(Value::Matrix { rows: rows.len(), cols, data });
        }
        match (self.eval(a)?, self.eval(b)?) {
            // A matrix of vectors named (`DOT(VCA, F>)`): the matrix of the dots.
            (Value::Vectors { rows, cols, data }, other) | (other, Value::Vectors { rows, cols, data }) => {
                let w = self.vector_of(other, e)?;
                let data =
                    data.iter().map(|v| self.model.dot(v, &w)).collect::<Result<Vec<_>, _>>().at(fail)?;
                Ok(Value::Matrix { rows, cols, data })
            }
            (Value::Dyadic(d), Value::Vector(v)) => {
                Ok(Value::Vector(self.model.dyadic_dot(&d, &v).at(fail)?))
            }
            (Value::Vector(v), Value::Dyadic(d)) => {
                Ok(Value::Vector(self.model.dyadic_dot(&d.transpose(), &v).at(fail)?))
            }
            (Value::Dyadic(_), Value::Dyadic(_)) => {
                Err(Diagnostic::error(e.span.clone(), "DOT of two dyadics is not supported"))
            }
            (va, vb) => {
                let (va, vb) = (self.vector_of(va, a)?, self.vector_of(vb, b)?);
                Ok(Value::Scalar(self.model.dot(&va, &vb).at(fail)?))
            }
        }
    }
}
