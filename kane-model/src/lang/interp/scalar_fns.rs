//! Scalar functions: elementary functions (SIN, SQRT, LOG10, ...), substitution (EVALUATE,
//! REPLACE), rewriting (EXPAND; EXPLICIT, FACTOR, ARRANGE as identities), coefficients (COEF)
//! and solved unknowns (RHS).
//!
//! In: the upper-cased function name and its argument expressions. Out: a [`Value`] (scalars,
//! or the same kind as the argument where the function maps over its scalars).

use rustc_hash::FxHashMap;

use crate::expr::{ExprError, ExprId, Func, Node, SymbolId};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{At, Binding, IResult, Interpreter};

/// Autolev's name, in EXCLUDE's and INCLUDE's lists, for the independent speeds.
const INDEPENDENT_SPEEDS: &str = "U_INDEPENDENT";

/// An elementary function of one scalar.
pub(super) enum Elementary {
    Func(Func),
    Sqrt,
    Square,
    Log10,
}

/// The elementary function named `name` (upper-cased), if it is one.
pub(super) fn elementary(name: &str) -> Option<Elementary> {
    Some(match name {
        "LOG" | "LN" => Elementary::Func(Func::Ln),
        "SQRT" => Elementary::Sqrt,
        "SQR" => Elementary::Square,
        "LOG10" => Elementary::Log10,
        _ => Elementary::Func(Func::from_name(name).filter(|f| *f != Func::Ln)?),
    })
}

impl Interpreter {
    /// `SIN(x)`, `SQRT(x)`, `SQR(x)`, `LOG10(x)`, ...
    pub(super) fn elementary_function(
        &mut self,
        f: Elementary,
        upper: &str,
        args: &[Expr],
        e: &Expr,
    ) -> IResult<Value> {
        let fail: &Span = &e.span;
        super::arity(upper, args, 1, &e.span)?;
        let x = self.scalar(&args[0])?;
        let ar = &mut self.model.ar;
        Ok(Value::Scalar(match f {
            Elementary::Func(f) => ar.func(f, x).at(fail)?,
            Elementary::Sqrt => ar.sqrt(x).at(fail)?,
            Elementary::Square => ar.powi(x, 2).at(fail)?,
            Elementary::Log10 => {
                let ln = ar.func(Func::Ln, x).at(fail)?;
                let ln10 = ar.float(std::f64::consts::LN_10).at(fail)?;
                ar.div(ln, ln10).at(fail)?
            }
        }))
    }

    /// `ATAN2(y, x)`: the angle of the point `(x, y)`, in (-pi, pi]; defined (zero) at the origin.
    pub(super) fn atan2_function(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity("ATAN2", args, 2, &e.span)?;
        let y = self.scalar(&args[0])?;
        let x = self.scalar(&args[1])?;
        Ok(Value::Scalar(self.model.ar.atan2(y, x).at(&e.span)?))
    }

    /// EVALUATE, REPLACE, EXPLICIT, FACTOR, ARRANGE, EXPAND, COEF, RHS.
    pub(super) fn scalar_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        match upper {
            "EVALUATE" | "REPLACE" => self.substitute(upper, args, e),
            "EXPLICIT" | "FACTOR" | "ARRANGE" => {
                let v = self.eval(args.first().ok_or_else(|| {
                    Diagnostic::error(e.span.clone(), format!("{upper} needs an argument"))
                })?)?;
                Ok(v)
            }
            "EXPAND" => {
                let v = self.eval(
                    args.first()
                        .ok_or_else(|| Diagnostic::error(e.span.clone(), "EXPAND needs an argument"))?,
                )?;
                self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.expand(x)?))
            }
            "COEF" => self.coefficients(args, e),
            _ => self.solved_value(args, e),
        }
    }

    /// `EVALUATE(x, NAME = value, ...)` and `REPLACE(...)`: substitution in every scalar.
    fn substitute(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let v = self
            .eval(args.first().ok_or_else(|| {
                Diagnostic::error(e.span.clone(), format!("{upper} needs an expression"))
            })?)?;
        let mut map = FxHashMap::default();
        for a in &args[1..] {
            let ExprKind::NamedArg(n, value) = &a.kind else {
                return Err(Diagnostic::error(
                    a.span.clone(),
                    format!("{upper} takes substitutions NAME = value"),
                ));
            };
            let key = self.substitution_key(n)?;
            let val = self.scalar(value)?;
            map.insert(key, val);
        }
        self.map_scalars(&v, &e.span, |m, x| Ok(m.ar.subs(x, &map)?))
    }

    /// `EXCLUDE(Y, X, ...)`: the terms of `Y` (expanded) that hold none of the quantities
    /// named; `INCLUDE(Y, X, ...)`: those that hold one of them. `Y` may be a matrix; the
    /// quantities a list (`[W', G]`).
    pub(crate) fn select_terms(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let Some((y, named)) = args.split_first().filter(|(_, n)| !n.is_empty()) else {
            return Err(Diagnostic::error(e.span.clone(), format!("{upper} takes (Y, X, ...)")));
        };
        let mut syms = Vec::new();
        for a in named {
            let keys = match &a.kind {
                ExprKind::Matrix(rows) => {
                    let mut keys = Vec::new();
                    for x in rows.iter().flatten() {
                        keys.extend(self.term_selector_keys(x)?);
                    }
                    keys
                }
                _ => self.term_selector_keys(a)?,
            };
            for k in keys {
                syms.push(self.model.ar.as_symbol(k).ok_or_else(|| {
                    Diagnostic::error(a.span.clone(), format!("{upper} selects terms by quantities, named"))
                })?);
            }
        }
        let v = self.eval(y)?;
        let v = self.in_independent_speeds(&v, &e.span)?;
        let keep_with = upper == "INCLUDE";
        self.map_scalars(&v, &e.span, |m, x| {
            if m.ar.expansion_bounds(&[x])[0] > TERMS_TO_SELECT_FROM {
                if !m.ar.is_polynomial_in(x, &syms) {
                    return Err(crate::expr::ExprError::TooLarge(TERMS_TO_SELECT_FROM as usize).into());
                }
                // Too large to expand, but polynomial in the quantities: the terms without them
                // are the expression with them zero.
                let zero = m.ar.zero();
                let map = syms.iter().map(|s| (m.ar.symbol_expr(*s), zero)).collect();
                let without = m.ar.subs(x, &map)?;
                if !keep_with {
                    return Ok(without);
                }
                let minus = m.ar.neg(without)?;
                return Ok(m.ar.add(&[x, minus])?);
            }
            let expanded = m.ar.expand(x)?;
            let kept: Vec<ExprId> =
                m.ar.terms(expanded)
                    .into_iter()
                    .filter(|t| m.ar.free_symbols(&[*t]).iter().any(|s| syms.contains(s)) == keep_with)
                    .collect();
            Ok(m.ar.add(&kept)?)
        })
    }

    /// What `x = value` in EVALUATE, REPLACE or TAYLOR replaces: a declared quantity or its
    /// derivative (`Q1'`) as the symbol itself, even where `Q1'` has a kinematic equation or a
    /// solved value; any other expression as it evaluates.
    pub(crate) fn substitution_key(&mut self, x: &Expr) -> IResult<ExprId> {
        if let ExprKind::Name { name, primes, suffix: 0 } = &x.kind {
            if let Some(Binding::Symbol(e, _)) = self.bindings.get(&name.to_ascii_uppercase()).cloned() {
                let mut at = e;
                for _ in 0..*primes {
                    let Some(s) = self.model.ar.as_symbol(at) else { break };
                    if !self.model.ar.symbol_info(s).kind.depends_on_time() {
                        break;
                    }
                    let d = self.model.ar.derivative_symbol(s).at(&x.span)?;
                    at = self.model.ar.symbol_expr(d);
                }
                return Ok(at);
            }
        }
        self.scalar(x)
    }

    /// `v` with the dependent speeds and their rates written in the independent ones, as
    /// Autolev holds every expression after CONSTRAIN (so COEF of ZERO by the independent rates
    /// is the whole mass matrix), where `v` holds rates of dependent and independent speeds (as
    /// FR() + FRSTAR() does); `v` itself otherwise.
    pub(super) fn in_independent_speeds(&mut self, v: &Value, span: &Span) -> IResult<Value> {
        let dependent = self.model.dependent_speeds();
        if dependent.is_empty() {
            return Ok(v.clone());
        }
        // Rates never named are in no expression.
        let existing_rates = |ar: &crate::expr::Arena, speeds: &[crate::expr::SymbolId]| -> Vec<_> {
            speeds.iter().filter_map(|u| ar.lookup(&format!("{}'", ar.symbol_info(*u).name))).collect()
        };
        let rates = existing_rates(&self.model.ar, &dependent);
        let independent_rates = existing_rates(&self.model.ar, &self.model.independent_speeds());
        let (held, independent_held) = (std::cell::Cell::new(false), std::cell::Cell::new(false));
        self.map_scalars(v, span, |m, x| {
            held.set(held.get() || rates.iter().any(|s| m.ar.depends_on(x, *s)));
            independent_held
                .set(independent_held.get() || independent_rates.iter().any(|s| m.ar.depends_on(x, *s)));
            Ok(x)
        })?;
        if !held.get() || !independent_held.get() {
            return Ok(v.clone());
        }
        let map = self.model.dependent_speed_solution().at(span)?;
        self.map_scalars(v, span, |m, x| Ok(m.ar.subs(x, &map)?))
    }

    /// The quantities one entry of EXCLUDE's or INCLUDE's list names: the entry itself, or for
    /// Autolev's undeclared `U_INDEPENDENT'` the rates (to its primes) of the independent speeds.
    fn term_selector_keys(&mut self, x: &Expr) -> IResult<Vec<ExprId>> {
        if let ExprKind::Name { name, primes, suffix: 0 } = &x.kind {
            if name.eq_ignore_ascii_case(INDEPENDENT_SPEEDS)
                && !self.bindings.contains_key(INDEPENDENT_SPEEDS)
            {
                let mut keys = Vec::new();
                for u in self.model.independent_speeds() {
                    let mut s = u;
                    for _ in 0..*primes {
                        s = self.model.ar.derivative_symbol(s).at(&x.span)?;
                    }
                    keys.push(self.model.ar.symbol_expr(s));
                }
                return Ok(keys);
            }
        }
        Ok(vec![self.substitution_key(x)?])
    }

    /// The scalars COEF's second argument evaluates to.
    fn coefficient_values(&mut self, y: &Expr) -> IResult<Vec<ExprId>> {
        match self.eval(y)? {
            Value::Scalar(x) => Ok(vec![x]),
            Value::Matrix { data, .. } => Ok(data),
            other => {
                Err(Diagnostic::error(y.span.clone(), format!("COEF takes symbols, not {}", other.kind())))
            }
        }
    }

    /// `COEF(x, y)`: the coefficients of the symbols `y` in the scalars `x` (linear in them).
    fn coefficients(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity("COEF", args, 2, &e.span)?;
        let v = self.eval(&args[0])?;
        let v = self.in_independent_speeds(&v, &e.span)?;
        // Rates SOLVE gave (`W'`, `[U7', U8']`) named here are the rates themselves.
        let named = |s: &Self, x: &Expr| match &x.kind {
            ExprKind::Name { name, primes, suffix: 0 } => {
                let key = format!("{}{}", name.to_ascii_uppercase(), "'".repeat(*primes as usize));
                s.solved.contains_key(&key)
                    && matches!(s.bindings.get(&name.to_ascii_uppercase()), Some(Binding::Symbol(..)))
            }
            _ => false,
        };
        let wrt = match &args[1].kind {
            ExprKind::Matrix(rows) if rows.iter().flatten().all(|x| named(self, x)) => {
                rows.iter().flatten().map(|x| self.substitution_key(x)).collect::<IResult<Vec<_>>>()?
            }
            _ if named(self, &args[1]) => vec![self.substitution_key(&args[1])?],
            _ => self.coefficient_values(&args[1])?,
        };
        let powers = wrt
            .iter()
            .map(|x| {
                self.symbol_power(*x).ok_or_else(|| {
                    Diagnostic::error(args[1].span.clone(), "COEF takes symbols or their powers (X, X^2)")
                })
            })
            .collect::<IResult<Vec<_>>>()?;
        let exprs = match v {
            Value::Scalar(x) => vec![x],
            Value::Matrix { data, .. } => data,
            // COEF(v>, X): the vector of each measure number's coefficient.
            Value::Vector(vec) if powers.len() == 1 => {
                let mut out = vec.clone();
                for (_, m) in out.terms.iter_mut() {
                    for x in m.iter_mut() {
                        *x = self.coefficients_of(*x, &powers).at(&e.span)?[0];
                    }
                }
                return Ok(Value::Vector(out));
            }
            other => {
                return Err(Diagnostic::error(
                    args[0].span.clone(),
                    format!("COEF takes scalars, or a vector and one symbol, not {}", other.kind()),
                ))
            }
        };
        let mut out: Vec<ExprId> = Vec::new();
        for x in &exprs {
            out.extend(self.coefficients_of(*x, &powers).at(&e.span)?);
        }
        Ok(if out.len() == 1 {
            Value::Scalar(out[0])
        } else {
            Value::Matrix { rows: exprs.len(), cols: powers.len(), data: out }
        })
    }

    /// `(s, k)` for `x = s^k`, a symbol to a non-negative integer power (`k = 1` for the symbol).
    fn symbol_power(&self, x: ExprId) -> Option<(SymbolId, i64)> {
        let ar = &self.model.ar;
        if let Some(s) = ar.as_symbol(x) {
            return Some((s, 1));
        }
        let Node::Pow([b, n]) = *ar.node(x) else { return None };
        let k = ar.as_rational(n).and_then(|r| r.as_i64()).filter(|k| *k >= 0)?;
        Some((ar.as_symbol(b)?, k))
    }

    /// COEF's coefficients of `x`: of each symbol when `x` is linear in them all (the
    /// mass-matrix reading), otherwise of each power in `x` multiplied out, other symbols
    /// taken as constants.
    fn coefficients_of(&mut self, x: ExprId, powers: &[(SymbolId, i64)]) -> Result<Vec<ExprId>, ExprError> {
        let ar = &mut self.model.ar;
        if powers.iter().all(|(_, k)| *k == 1) {
            let syms: Vec<SymbolId> = powers.iter().map(|(s, _)| *s).collect();
            match ar.linear_coefficients(x, &syms) {
                Ok((c, _)) => return Ok(c),
                Err(ExprError::NotLinear { .. }) => {}
                Err(other) => return Err(other),
            }
        }
        powers.iter().map(|(s, k)| ar.coefficient(x, *s, *k)).collect()
    }

    /// `RHS(X)`: the solution SOLVE found for the unknown `X`.
    fn solved_value(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity("RHS", args, 1, &e.span)?;
        let ExprKind::Name { name, primes, suffix } = &args[0].kind else {
            return Err(Diagnostic::error(
                args[0].span.clone(),
                "RHS takes the name of a solved or assigned quantity",
            ));
        };
        let upper = name.to_ascii_uppercase();
        let key = format!("{upper}{}", "'".repeat(*primes as usize));
        if let Some(x) = self.solved.get(&key) {
            return Ok(Value::Scalar(*x));
        }
        if *primes == 1 {
            if let Some(x) = self.speed_rate_solved(&key, &args[0].span)? {
                return Ok(Value::Scalar(x));
            }
        }
        // A kinematic equation Q' = ...: its right-hand side.
        let coordinate = self
            .kinematic
            .iter()
            .find(|(q, _)| self.model.ar.symbol_info(*q).name.eq_ignore_ascii_case(&upper));
        if let (1, Some((_, rhs))) = (*primes, coordinate) {
            return Ok(Value::Scalar(*rhs));
        }
        // An assigned quantity: its value (a declared symbol has no right-hand side).
        let bound = format!("{key}{}", ">".repeat(*suffix as usize));
        match self.bindings.get(&bound) {
            Some(Binding::Value(v)) => Ok(v.clone()),
            _ => Err(Diagnostic::error(
                args[0].span.clone(),
                format!("`{name}` has not been solved for or assigned"),
            )
            .with_help("call SOLVE(EQN, ...) first, or assign it (X = ...)")),
        }
    }

    /// `u'` of a speed named `key` (`U2'`) from the equations of motion solved symbolically, for
    /// an unconstrained model of at most [`SYMBOLIC_RATES_UP_TO`] speeds (larger ones are solved
    /// numerically only); None for a name that is not a speed's rate.
    pub(crate) fn speed_rate_solved(&mut self, key: &str, span: &Span) -> IResult<Option<ExprId>> {
        let Some(eqs) = self.equations.clone() else { return Ok(None) };
        let ar = &self.model.ar;
        let named = |s: &crate::expr::SymbolId| ar.symbol_info(*s).name.eq_ignore_ascii_case(key);
        let dependent_rates = eqs.constraints.as_ref().map(|c| c.dependent_rates.clone()).unwrap_or_default();
        if !eqs.speed_derivatives.iter().chain(&dependent_rates).any(named) {
            return Ok(None);
        }
        if let Some(x) = self.solved.get(&key.to_ascii_uppercase()) {
            return Ok(Some(*x));
        }
        let n = eqs.speeds.len() + dependent_rates.len();
        if n > SYMBOLIC_RATES_UP_TO {
            return Err(Diagnostic::error(
                span.clone(),
                format!("{key} of a model with {n} speeds is not formed symbolically (at most {SYMBOLIC_RATES_UP_TO})"),
            )
            .with_help("evaluate the rates with `kane eval` or linearise with `kane linearize`"));
        }
        let rates = eqs.symbolic_rates(&mut self.model.ar).at(span)?;
        let ar = &self.model.ar;
        let pairs = eqs
            .speed_derivatives
            .iter()
            .zip(&rates.speeds)
            .chain(dependent_rates.iter().zip(&rates.dependent_rates));
        for (s, x) in pairs {
            self.solved.insert(ar.symbol_info(*s).name.to_ascii_uppercase(), *x);
        }
        Ok(self.solved.get(&key.to_ascii_uppercase()).copied())
    }
}

/// The most terms EXCLUDE and INCLUDE expand an expression into.
const TERMS_TO_SELECT_FROM: u64 = 200_000;

/// The most speeds (independent and dependent) whose rates are formed as expressions.
const SYMBOLIC_RATES_UP_TO: usize = 16;
