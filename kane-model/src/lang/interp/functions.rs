//! Autolev functions that return values: the dispatch by name to a family of functions, and the
//! argument helpers the families share.
//!
//! In: a call `NAME(args)` as parsed. Out: its [`Value`], or a diagnostic for a function that
//! is unknown or not supported. The families are `scalar_fns` (elementary functions,
//! substitution, coefficients), `vector_fns` (vector algebra and derivatives), `mass_fns`
//! (generalized forces and mass properties), `matrix_fns` (matrices), `algebra_fns` and `eigen`
//! (INV, EIG, TAYLOR) and `polynomial` (POLYNOMIAL, ROOTS).

use crate::expr::ExprId;
use crate::mechanics::{FrameId, Model, PointId};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::scalar_fns::elementary;
use super::value::Value;
use super::{At, IResult, Interpreter};

impl Interpreter {
    /// Evaluates `NAME(args)`.
    pub(crate) fn call(&mut self, name: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let upper = name.to_ascii_uppercase();
        if !KNOWN_CALLS.contains(&upper.as_str()) {
            return Err(unknown_function(name, &upper, &e.span));
        }
        if let Some(f) = elementary(&upper) {
            return self.elementary_function(f, &upper, args, e);
        }
        match upper.as_str() {
            "DOT" | "CROSS" | "MAG" | "UNITVEC" | "EXPRESS" | "DT" | "D" | "PARTIALS" => {
                self.vector_function(&upper, args, e)
            }
            "ATAN2" => self.atan2_function(args, e),
            "INV" | "INVERSE" | "EIG" | "TAYLOR" => self.algebra_function(&upper, args, e),
            "POLYNOMIAL" | "ROOTS" => self.polynomial_function(&upper, args, e),
            "SPLINE" => self.spline(args, e),
            "INT" | "FLOOR" | "CEIL" | "ROUND" | "FACTORIAL" => self.whole_number_function(&upper, args, e),
            "EVALUATE" | "REPLACE" | "EXPLICIT" | "FACTOR" | "ARRANGE" | "EXPAND" | "COEF" | "RHS" => {
                self.scalar_function(&upper, args, e)
            }
            // Autolev's Z variables name parts of an expression; its value is unchanged.
            "EXCLUDE" | "INCLUDE" => self.select_terms(&upper, args, e),
            "ZEE" => {
                let x = args
                    .first()
                    .ok_or_else(|| Diagnostic::error(e.span.clone(), "ZEE takes an expression"))?;
                self.eval(x)
            }
            "INPUT" => self.input_value(args, e),
            "NICHECK" => self.energy_check(args, e),
            "FR" | "FRSTAR" | "KE" | "MOMENTUM" | "MASS" | "CM" | "INERTIA" => {
                self.mass_function(&upper, args, e)
            }
            "TRANSPOSE" | "TRACE" | "DET" | "ELEMENT" | "DIAGMAT" | "ROWS" | "COLS" | "MATRIX" | "VECTOR" => {
                self.matrix_function(&upper, args, e)
            }
            _ => Err(unknown_function(name, &upper, &e.span)),
        }
    }

    /// INT (the integer part), FLOOR, CEIL, ROUND and FACTORIAL of a number: the argument must
    /// evaluate to a number (they have no symbolic form), FACTORIAL's to a whole one from 0 to 170.
    fn whole_number_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity(upper, args, 1, &e.span)?;
        if self.number(&args[0]).is_err() {
            // Of a symbol, only Autolev's session shows these.
            let x = self.eval(&args[0])?;
            if !matches!(x, Value::Scalar(_) | Value::Shown(_)) {
                return Err(Diagnostic::error(
                    args[0].span.clone(),
                    format!("{upper} takes a scalar, not {}", x.kind()),
                ));
            }
            return Ok(Value::Shown(format!("{upper}{}", self.shown_text(&x))));
        }
        let x = self.number(&args[0]).map_err(|_| {
            Diagnostic::error(
                args[0].span.clone(),
                format!("{upper}() of an expression in the model's symbols is not supported"),
            )
            .with_help(format!("{upper}() is evaluated when the file is read: give it a number"))
        })?;
        let v = match upper {
            "INT" => x.trunc(),
            "FLOOR" => x.floor(),
            "CEIL" => x.ceil(),
            "ROUND" => x.round(),
            _ if x.fract() == 0.0 && (0.0..=170.0).contains(&x) => (1..=x as u32).map(f64::from).product(),
            _ => {
                return Err(Diagnostic::error(
                    args[0].span.clone(),
                    format!("FACTORIAL of {x}: expected a whole number from 0 to 170"),
                ))
            }
        };
        Ok(Value::Scalar(self.number_expr(v).at(&e.span)?))
    }

    /// `INPUT(X)`: the value INPUT gave X so far; for a name assigned an expression instead
    /// (`A = PI/2`, `U1 = DOT(W_A_N>, A1>)`), its value at the INPUT values given so far (the
    /// value X has in Autolev's code).
    fn input_value(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity("INPUT", args, 1, &e.span)?;
        let ExprKind::Name { name, primes, suffix: 0 } = &args[0].kind else {
            return Err(Diagnostic::error(args[0].span.clone(), "INPUT takes a name"));
        };
        let key = format!("{name}{}", "'".repeat(*primes as usize));
        let v = match self.given_input(&key) {
            Some(v) => v,
            None => self.value_at_inputs(&args[0], &key)?,
        };
        Ok(Value::Scalar(self.number_expr(v).at(&e.span)?))
    }

    /// The last INPUT value of `name` (with its primes), if any.
    fn given_input(&self, name: &str) -> Option<f64> {
        self.inputs.iter().rev().find(|i| i.name.eq_ignore_ascii_case(name)).map(|i| i.value)
    }

    /// The value of the scalar `x` (named `key`) with the INPUT values given so far put in.
    fn value_at_inputs(&mut self, x: &Expr, key: &str) -> IResult<f64> {
        let no_value = |what: &str| {
            Diagnostic::error(x.span.clone(), format!("`{key}` has no INPUT value yet{what}"))
                .with_help("give it one in an INPUT line before this statement")
        };
        let s = self.scalar(x)?;
        if self.model.ar.as_symbol(s).is_some() {
            return Err(no_value(""));
        }
        let free = self.model.ar.free_symbols(&[s]);
        let mut missing = None;
        let mut values = rustc_hash::FxHashMap::default();
        for sym in free {
            let name = self.model.ar.symbol_info(sym).name.clone();
            match self.given_input(&name) {
                Some(v) => {
                    values.insert(sym, v);
                }
                None => missing = missing.or(Some(name)),
            }
        }
        if let Some(name) = missing {
            return Err(no_value(&format!(" (its expression holds `{name}`, which has none)")));
        }
        let v = self.model.ar.eval(&[s], |sym| values.get(&sym).copied()).map_err(|err| {
            Diagnostic::error(x.span.clone(), format!("`{key}` at the INPUT values: {err}"))
        })?;
        Ok(v[0])
    }

    /// Applies `f` to every scalar inside a value.
    pub(crate) fn map_scalars(
        &mut self,
        v: &Value,
        span: &Span,
        f: impl Fn(&mut Model, ExprId) -> crate::mechanics::Result<ExprId>,
    ) -> IResult<Value> {
        let fail: &Span = span;
        Ok(match v {
            Value::Shown(_) => {
                return Err(Diagnostic::error(span.clone(), format!("this takes {}, which a model cannot compute with", v.kind()))
                    .with_help("complex numbers and FACTORIAL of a symbol are values to show: use them in no other expression"))
            }
            Value::Scalar(x) => Value::Scalar(f(&mut self.model, *x).at(fail)?),
            Value::Matrix { rows, cols, data } => Value::Matrix {
                rows: *rows,
                cols: *cols,
                data: data.iter().map(|x| f(&mut self.model, *x)).collect::<Result<_, _>>().at(fail)?,
            },
            Value::Vector(vec) => Value::Vector(self.map_measures(vec, fail, &f)?),
            Value::Vectors { rows, cols, data } => Value::Vectors {
                rows: *rows,
                cols: *cols,
                data: data.iter().map(|v| self.map_measures(v, fail, &f)).collect::<IResult<_>>()?,
            },
            Value::Dyadic(d) => Value::Dyadic(d.clone()),
        })
    }

    /// `v` with `f` applied to each measure number.
    fn map_measures(
        &mut self,
        v: &crate::mechanics::Vector,
        fail: &Span,
        f: &impl Fn(&mut Model, ExprId) -> crate::mechanics::Result<ExprId>,
    ) -> IResult<crate::mechanics::Vector> {
        let mut out = v.clone();
        for (_, m) in out.terms.iter_mut() {
            for x in m.iter_mut() {
                *x = f(&mut self.model, *x).at(fail)?;
            }
        }
        Ok(out)
    }

    /// The frame an argument names (a frame or a body).
    pub(crate) fn frame_arg(&mut self, e: &Expr) -> IResult<FrameId> {
        if let ExprKind::Name { name, suffix: 0, primes: 0 } = &e.kind {
            if let Some(f) = self.frame_of(&name.to_ascii_uppercase()) {
                return Ok(f);
            }
        }
        Err(Diagnostic::error(e.span.clone(), "expected a frame name here")
            .with_help("frames are declared with NEWTONIAN, FRAMES or BODIES"))
    }

    /// The point an argument names (a point, a particle, or a body's mass centre).
    pub(crate) fn point_arg(&mut self, e: &Expr) -> IResult<PointId> {
        if let ExprKind::Name { name, suffix: 0, primes: 0 } = &e.kind {
            if let Some(p) = self.point_of(&name.to_ascii_uppercase()) {
                return Ok(p);
            }
        }
        Err(Diagnostic::error(e.span.clone(), "expected a point name here")
            .with_help("points are declared with POINTS or PARTICLES; a body B has mass centre BO"))
    }
}

/// The error for a function this implementation does not know.
pub(crate) fn unknown_function(name: &str, upper: &str, span: &Span) -> Diagnostic {
    let d = Diagnostic::error(span.clone(), format!("unknown function `{name}`"));
    match nearest_command(upper) {
        Some(k) => d.with_help(format!(
            "did you mean `{k}`? See docs/language-reference.md for the supported functions and commands"
        )),
        None => {
            d.with_help("see docs/language-reference.md for the supported Autolev functions and commands")
        }
    }
}

/// The commands and functions a file may call, elementary functions included: a call of any
/// other name is unknown.
pub(crate) const KNOWN_CALLS: &[&str] = &[
    "A1PT",
    "A2PTS",
    "ABS",
    "ACOS",
    "ANGVEL",
    "ANIMATE",
    "ARRANGE",
    "ASIN",
    "ATAN",
    "ATAN2",
    "CEIL",
    "CM",
    "COEF",
    "COLS",
    "CONSTRAIN",
    "COS",
    "COSH",
    "CROSS",
    "D",
    "DET",
    "DIAGMAT",
    "DIRCOS",
    "DOT",
    "DT",
    "EIG",
    "ELEMENT",
    "ENCODE",
    "EVALUATE",
    "EXCLUDE",
    "EXP",
    "EXPAND",
    "EXPLICIT",
    "EXPRESS",
    "FACTOR",
    "FACTORIAL",
    "FLOOR",
    "FORCE",
    "FR",
    "FRSTAR",
    "GRAVITY",
    "INCLUDE",
    "INERTIA",
    "INPUT",
    "INT",
    "INV",
    "INVERSE",
    "KANE",
    "KE",
    "KINDIFFS",
    "LN",
    "LOG",
    "LOG10",
    "MAG",
    "MASS",
    "MATRIX",
    "MOMENTUM",
    "NICHECK",
    "PARTIALS",
    "POLYNOMIAL",
    "REPLACE",
    "RHS",
    "ROOTS",
    "ROUND",
    "ROWS",
    "SIGN",
    "SIMPROT",
    "SIN",
    "SINH",
    "SOLVE",
    "SPLINE",
    "SQR",
    "SQRT",
    "TAN",
    "TANH",
    "TAYLOR",
    "TORQUE",
    "TRACE",
    "TRANSPOSE",
    "UNITSYSTEM",
    "UNITVEC",
    "V1PT",
    "V2PTS",
    "VECTOR",
    "ZEE",
];

/// The known command, function or session command nearest to `upper` (at most two edits
/// away, and fewer than its length), for a did-you-mean.
pub(crate) fn nearest_command(upper: &str) -> Option<&'static str> {
    let session = super::super::parser::SESSION_COMMANDS.iter();
    let known = KNOWN_CALLS.iter().chain(session).chain(&["UNITSYSTEM", "UNITS", "INPUT", "OUTPUT", "CODE"]);
    super::names::nearest_word(upper, known.copied())
}

#[cfg(test)]
mod tests {
    use super::KNOWN_CALLS;

    /// The report of `src` as `kane check` gives it ("" when it checks).
    fn report(src: &str) -> String {
        crate::lang::check("calls.al", src).err().map_or_else(String::new, |r| r.to_string())
    }

    #[test]
    fn every_known_call_is_dispatched_and_no_other_is() {
        for name in KNOWN_CALLS {
            let r = report(&format!("NEWTONIAN N\n{name}()\n"));
            assert!(!r.contains("unknown"), "{name}: {r}");
        }
        for name in ["SIMPORT", "FOO", "KANEE"] {
            assert!(report(&format!("NEWTONIAN N\n{name}()\n")).contains("unknown command"), "{name}");
            assert!(report(&format!("NEWTONIAN N\nX = {name}(1)\n")).contains("unknown function"), "{name}");
        }
    }

    #[test]
    fn every_elementary_function_is_a_known_call() {
        for f in crate::expr::Func::ALL {
            assert!(KNOWN_CALLS.contains(&f.name().to_ascii_uppercase().as_str()), "{}", f.name());
        }
    }
}
