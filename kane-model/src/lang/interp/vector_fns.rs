//! Vector functions: DOT, CROSS, MAG, UNITVEC, EXPRESS, and the derivatives DT, D and PARTIALS.
//!
//! In: the upper-cased function name and its argument expressions. Out: a scalar or vector
//! [`Value`]; the vector work itself is done by the mechanics layer's [`crate::mechanics::Model`]
//! methods (`dot`, `cross`, `dt_in`, `partial_in`, ...).

use super::super::ast::Expr;
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{At, IResult, Interpreter};

impl Interpreter {
    /// DOT, CROSS, MAG, UNITVEC, EXPRESS, DT, D, PARTIALS.
    pub(super) fn vector_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        let arity = |n: usize| super::arity(upper, args, n, &e.span);
        match upper {
            "DOT" => {
                arity(2)?;
                let a = self.vector(&args[0])?;
                let b = self.vector(&args[1])?;
                Ok(Value::Scalar(self.model.dot(&a, &b).at(fail)?))
            }
            "CROSS" => {
                arity(2)?;
                let a = self.vector(&args[0])?;
                let b = self.vector(&args[1])?;
                Ok(Value::Vector(self.model.cross(&a, &b).at(fail)?))
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
                let v = self.vector(&args[0])?;
                let f = self.frame_arg(&args[1])?;
                Ok(Value::Vector(self.model.dt_in(&v, f).at(&e.span)?))
            }
            _ => Err(Diagnostic::error(e.span.clone(), "DT takes (x) or (v>, frame)")),
        }
    }

    /// `D(x, y)` for the scalars of any value, `D(v>, y, A)` for a vector as seen in frame A.
    fn derivative(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        if args.len() < 2 {
            return Err(Diagnostic::error(e.span.clone(), "D takes (x, y) or (v>, y, frame)"));
        }
        let y = self.scalar(&args[1])?;
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
}
