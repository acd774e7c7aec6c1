//! Assignments: `X = value`, `X += value`, `Q' = rhs` (kinematic equations), `A[i] = x`
//! (arrays, DEPENDENT and CONFIG constraints), built-in quantities (`V_P_N> = ...`) and
//! direction-cosine matrices (`A_B = [...]`).
//!
//! In: an assignment target and its value. Out: a binding, an array entry, or a change to the
//! model (kinematics, constraints, orientations, positions, velocities, inertia, loads).

use crate::expr::SymbolKind;

use super::super::ast::{AssignOp, Expr, ExprKind, Target};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::{self, Value};
use super::{At, Binding, IResult, Interpreter};

impl Interpreter {
    /// `target = value` or `target += value`.
    pub(super) fn assign(&mut self, target: &Target, op: AssignOp, value: &Expr) -> IResult<()> {
        let mut v = self.eval(value)?;
        let key = target.name.to_ascii_uppercase();
        if target.index.is_none() && op != AssignOp::Add && is_kane_sum(value) {
            self.kane_sums.insert(key.clone());
        } else {
            self.kane_sums.remove(&key);
        }
        if let Some(index) = &target.index {
            let idx = index.iter().map(|e| self.index_value(e)).collect::<IResult<Vec<i64>>>()?;
            return self.assign_array(&key, idx, v, &target.span);
        }
        // DEPENDENT = M and CONFIG = M: every entry a constraint, as DEPENDENT[i] = M[i].
        if let (true, Value::Matrix { data, .. }) = (key == "DEPENDENT" || key == "CONFIG", &v) {
            for (i, x) in data.clone().into_iter().enumerate() {
                self.assign_array(&key, vec![i as i64 + 1], Value::Scalar(x), &target.span)?;
            }
            return Ok(());
        }
        if target.primes > 0 {
            return self.kinematic_equation(target, &v);
        }
        if target.suffix > 0 && self.assign_builtin(&key, target.suffix, &v, &target.span)? {
            return Ok(());
        }
        if target.suffix == 0 && !self.bindings.contains_key(&key) {
            // A_B = [...] orients B relative to A by its direction cosines.
            if let (Some((a, b)), Value::Matrix { rows: 3, cols: 3, data }) = (self.dcm_frames(&key), &v) {
                let m =
                    [[data[0], data[1], data[2]], [data[3], data[4], data[5]], [data[6], data[7], data[8]]];
                self.model.orient(b, a, crate::mechanics::Orientation::Dcm(m)).at(&target.span)?;
                self.sources.orientation(a, b, &target.span);
                return Ok(());
            }
        }
        let full_key = format!("{key}{}", ">".repeat(target.suffix as usize));
        if op == AssignOp::Add {
            if let Some(old) = self.lookup_value(&full_key) {
                v = value::add(&mut self.model, &old, &v, false).at(&target.span)?.ok_or_else(|| {
                    Diagnostic::error(target.span.clone(), "`+=` needs values of the same kind")
                })?;
            }
        }
        // T = formula for a SPECIFIED T: its formula (T stays a quantity until the end).
        if let (Some(Binding::Symbol(e, _)), 0, AssignOp::Set) =
            (self.bindings.get(&key).cloned(), target.suffix, op)
        {
            if self.is_specified(e) {
                return self.specified_formula(&key, &v, &target.span);
            }
        }
        // OMEGA = THETA' for a declared speed: the kinematic equation THETA' = OMEGA.
        if let (Some(Binding::Symbol(lhs, _)), Value::Scalar(rhs)) = (self.bindings.get(&key).cloned(), &v) {
            if let Some(s) = self.model.ar.as_symbol(*rhs) {
                if let SymbolKind::Variable { order: 1 } = self.model.ar.symbol_info(s).kind {
                    let base = self.model.ar.symbol_info(s).base;
                    self.kinematic.push((base, lhs));
                    let q = self.model.ar.symbol_expr(base);
                    self.model.set_kinematics(q, lhs).at(&target.span)?;
                    return Ok(());
                }
            }
        }
        self.bindings.insert(full_key, Binding::Value(v));
        Ok(())
    }

    /// `Q' = rhs`: a coordinate's kinematic equation; for a SPECIFIED quantity or a name
    /// assigned a value (`LH = Q4`, then `LH' = U4`), the formula of that derivative, as
    /// Autolev takes it (not checked against the rate of the other).
    fn kinematic_equation(&mut self, target: &Target, v: &Value) -> IResult<()> {
        let key = target.name.to_ascii_uppercase();
        let derivative = format!("{key}{}", "'".repeat(target.primes as usize));
        match self.bindings.get(&key).cloned() {
            Some(Binding::Value(_)) => {
                self.bindings.insert(derivative, Binding::Value(v.clone()));
                return Ok(());
            }
            Some(Binding::Symbol(q, _)) if self.is_specified(q) => {
                return self.specified_formula(&derivative, v, &target.span);
            }
            _ => {}
        }
        let Some(Binding::Symbol(q, _)) = self.bindings.get(&key).cloned() else {
            return Err(Diagnostic::error(
                target.span.clone(),
                format!("`{}'` is not the derivative of a declared variable", target.name),
            )
            .with_help(
                "declare it first: VARIABLES or MOTIONVARIABLES with a prime, e.g. MOTIONVARIABLES' Q{2}'",
            ));
        };
        let Value::Scalar(rhs) = v else {
            return Err(Diagnostic::error(
                target.span.clone(),
                format!("a kinematic equation needs a scalar, not {}", v.kind()),
            ));
        };
        if target.primes != 1 {
            // Y'' = expr defines the second derivative; later uses of Y'' read it.
            let key = format!("{key}{}", "'".repeat(target.primes as usize));
            self.bindings.insert(key, Binding::Value(v.clone()));
            return Ok(());
        }
        let s = self.model.ar.as_symbol(q).unwrap_or(crate::expr::TIME);
        self.kinematic.push((s, *rhs));
        self.model.set_kinematics(q, *rhs).at(&target.span)
    }

    /// Records `value` as the formula of the SPECIFIED quantity (or derivative) `key`.
    pub(crate) fn specified_formula(&mut self, key: &str, value: &Value, span: &Span) -> IResult<()> {
        let Value::Scalar(f) = value else {
            return Err(Diagnostic::error(
                span.clone(),
                format!("a SPECIFIED quantity's formula is a scalar, not {}", value.kind()),
            ));
        };
        self.formulas.insert(key.to_string(), *f);
        Ok(())
    }

    /// Whether `e` is a SPECIFIED quantity.
    fn is_specified(&self, e: crate::expr::ExprId) -> bool {
        let ar = &self.model.ar;
        ar.as_symbol(e).is_some_and(|s| matches!(ar.symbol_info(s).kind, SymbolKind::Specified { .. }))
    }

    fn assign_array(&mut self, key: &str, idx: Vec<i64>, v: Value, span: &Span) -> IResult<()> {
        if key == "AUXILIARY" {
            // Autolev lists the auxiliary speeds here; CONSTRAIN(AUXILIARY[...]) declares them.
            return match v {
                Value::Scalar(e) if self.model.ar.as_symbol(e).is_some() => Ok(()),
                _ => Err(Diagnostic::error(span.clone(), "AUXILIARY[i] names one auxiliary speed")
                    .with_help("write AUXILIARY[1] = U8, then CONSTRAIN(AUXILIARY[U8])")),
            };
        }
        if key == "DEPENDENT" {
            if let Value::Scalar(e) = v {
                self.dependent.push(e);
                return Ok(());
            }
            return Err(Diagnostic::error(span.clone(), "DEPENDENT[i] must be a scalar constraint"));
        }
        if key == "CONFIG" {
            if let Value::Scalar(e) = v {
                self.model.add_configuration_constraint(e);
            }
        }
        // M[i, j] = x on an existing matrix sets one entry.
        if let (Some(Binding::Value(Value::Matrix { rows, cols, mut data })), Value::Scalar(x)) =
            (self.bindings.get(key).cloned(), &v)
        {
            if let Some(k) = value::matrix_position(&idx, rows, cols) {
                data[k] = *x;
                self.bindings.insert(key.to_string(), Binding::Value(Value::Matrix { rows, cols, data }));
                return Ok(());
            }
            // ZERO[n + 1] = x appends a row to a column.
            if cols == 1 && idx.len() == 1 && idx[0] as usize == rows + 1 {
                data.push(*x);
                self.bindings
                    .insert(key.to_string(), Binding::Value(Value::Matrix { rows: rows + 1, cols, data }));
                return Ok(());
            }
        }
        let entries = self.arrays.entry(key.to_string()).or_default();
        entries.retain(|(i, _)| *i != idx);
        entries.push((idx, v));
        Ok(())
    }

    /// Autolev declares the bare names of MASS and INERTIA statements as constants.
    pub(crate) fn implicit_constants(&mut self, e: &Expr) -> IResult<()> {
        if let ExprKind::Name { name, primes: 0, suffix: 0 } = &e.kind {
            let key = name.to_ascii_uppercase();
            if !self.bindings.contains_key(&key) && key != "T" && key != "PI" {
                let c = self.model.ar.constant(name).at(&e.span)?;
                self.bindings.insert(key, Binding::Symbol(c, 0));
                self.sources.implicit_constants.push((name.clone(), e.span.clone()));
            }
        }
        Ok(())
    }

    pub(crate) fn lookup_value(&self, key: &str) -> Option<Value> {
        match self.bindings.get(key) {
            Some(Binding::Value(v)) => Some(v.clone()),
            Some(Binding::Symbol(e, _)) => Some(Value::Scalar(*e)),
            _ => None,
        }
    }
}

/// Whether `e` is `FR() + FRSTAR()` (either order).
fn is_kane_sum(e: &Expr) -> bool {
    let call = |e: &Expr, want: &str| matches!(&e.kind, ExprKind::Call { name, args } if args.is_empty() && name.eq_ignore_ascii_case(want));
    match &e.kind {
        ExprKind::Binary(super::super::ast::BinOp::Add, a, b) => {
            (call(a, "FR") && call(b, "FRSTAR")) || (call(a, "FRSTAR") && call(b, "FR"))
        }
        _ => false,
    }
}
