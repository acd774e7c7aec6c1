//! Lowering an Autolev program onto the mechanics layer, statement by statement.
//!
//! Names are case-insensitive: every lookup goes through the upper-cased name; symbols keep the
//! spelling of their declaration for printing.

mod commands;
mod eval;
mod functions;
mod names;
mod orientation;
pub mod value;

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId, SymbolKind};
use crate::mechanics::{BodyId, FrameId, KaneEquations, Model, ParticleId, PointId, Vector};

use super::ast::{AssignOp, DeclItem, DeclKind, Stmt, StmtKind};
use super::diagnostic::Diagnostic;
use super::token::Span;
use value::Value;

/// What a name stands for.
#[derive(Clone, Debug)]
pub(crate) enum Binding {
    Frame(FrameId),
    Point(PointId),
    Body(BodyId),
    Particle(ParticleId),
    /// A declared symbol (constant, variable, specified) with its declared derivative order.
    Symbol(ExprId, u8),
    /// An assigned value.
    Value(Value),
}

/// An INPUT value, converted to radians where the input was in degrees.
#[derive(Clone, Debug, PartialEq)]
pub struct InputValue {
    /// The name as written.
    pub name: String,
    /// The value in internal units.
    pub value: f64,
    /// The unit word given after the value, if any.
    pub unit: Option<String>,
}

/// A CODE request.
#[derive(Clone, Debug, PartialEq)]
pub struct CodeRequest {
    /// DYNAMICS, ALGEBRAIC, NONLINEAR, ODE.
    pub kind: String,
    /// The file named.
    pub file: String,
}

/// The result of running a model file.
pub struct LoadedModel {
    /// The mechanics model.
    pub model: Model,
    /// Kane's equations, when the file calls KANE().
    pub equations: Option<KaneEquations>,
    /// INPUT values, in order.
    pub inputs: Vec<InputValue>,
    /// UNITS: upper-cased name to unit text.
    pub units: FxHashMap<String, String>,
    /// OUTPUT: the names asked for, with optional units.
    pub outputs: Vec<(String, Option<String>)>,
    /// CODE requests.
    pub code: Vec<CodeRequest>,
    bindings: FxHashMap<String, Binding>,
    arrays: FxHashMap<String, Vec<(Vec<i64>, Value)>>,
}

impl LoadedModel {
    /// The value a name has at the end of the file (case-insensitive; `V>` for vectors).
    pub fn value(&self, name: &str) -> Option<Value> {
        let key = name.to_ascii_uppercase();
        match self.bindings.get(&key) {
            Some(Binding::Value(v)) => Some(v.clone()),
            _ => {
                // EQN[1], EQN[2], ...: a column of scalars.
                let mut entries = self.arrays.get(&key)?.clone();
                entries.sort_by(|a, b| a.0.cmp(&b.0));
                let data = entries
                    .into_iter()
                    .map(|(i, v)| match (i.as_slice(), v) {
                        ([_], Value::Scalar(x)) => Some(x),
                        _ => None,
                    })
                    .collect::<Option<Vec<ExprId>>>()?;
                Some(Value::column(data))
            }
        }
    }

    /// The INPUT value of `name` (case-insensitive).
    pub fn input(&self, name: &str) -> Option<f64> {
        self.inputs.iter().rev().find(|i| i.name.eq_ignore_ascii_case(name)).map(|i| i.value)
    }
}

pub(crate) struct Interpreter {
    pub(crate) model: Model,
    pub(crate) bindings: FxHashMap<String, Binding>,
    pub(crate) arrays: FxHashMap<String, Vec<(Vec<i64>, Value)>>,
    pub(crate) degrees: bool,
    pub(crate) gravity: Option<Vector>,
    pub(crate) forces: Vec<(PointId, Vector)>,
    pub(crate) torques: Vec<(FrameId, Vector)>,
    pub(crate) force_names: FxHashMap<PointId, usize>,
    pub(crate) torque_names: FxHashMap<FrameId, usize>,
    pub(crate) kinematic: Vec<(SymbolId, ExprId)>,
    pub(crate) dependent: Vec<ExprId>,
    pub(crate) dependent_speeds: Vec<ExprId>,
    pub(crate) prepared: bool,
    pub(crate) equations: Option<KaneEquations>,
    pub(crate) inputs: Vec<InputValue>,
    pub(crate) units: FxHashMap<String, String>,
    pub(crate) outputs: Vec<(String, Option<String>)>,
    pub(crate) code: Vec<CodeRequest>,
    pub(crate) errors: Vec<Diagnostic>,
    pub(crate) solved: FxHashMap<String, ExprId>,
}

type IResult<T> = Result<T, Diagnostic>;

/// Places a mechanics or expression error at a span of the source.
pub(crate) trait At<T> {
    /// The error as a diagnostic at `span`.
    fn at(self, span: &Span) -> IResult<T>;
}

impl<T> At<T> for Result<T, crate::expr::ExprError> {
    fn at(self, span: &Span) -> IResult<T> {
        self.map_err(|e| Diagnostic::error(span.clone(), e.to_string()))
    }
}

impl<T> At<T> for Result<T, crate::mechanics::MechanicsError> {
    fn at(self, span: &Span) -> IResult<T> {
        use crate::mechanics::MechanicsError as E;
        self.map_err(|e| {
            let help = match &e {
                E::FrameOrientedTwice { .. } => {
                    Some("orient each frame once; to change how it turns, edit that first SIMPROT")
                }
                E::OrientationCycle { .. } => {
                    Some("frames form a tree rooted at the Newtonian frame: orient the child from its parent")
                }
                E::MissingKinematics(_) => Some("give every coordinate a kinematic equation, e.g. Q1' = U1"),
                E::NoSpeeds => Some("declare speeds, e.g. VARIABLES U{3}' (or MOTIONVARIABLES' Q{3}'')"),
                E::MissingMass(_) => Some("masses are given with MASS NAME = value"),
                E::NoPositionPath { .. } => Some("locate one point from the other, e.g. P_O_P> = L*A1>"),
                _ => None,
            };
            let d = Diagnostic::error(span.clone(), e.to_string());
            match help {
                Some(h) => d.with_help(h),
                None => d,
            }
        })
    }
}

impl Interpreter {
    pub(crate) fn new() -> Interpreter {
        Interpreter {
            model: Model::new("__NEWTONIAN"),
            bindings: FxHashMap::default(),
            arrays: FxHashMap::default(),
            degrees: true,
            gravity: None,
            forces: Vec::new(),
            torques: Vec::new(),
            force_names: FxHashMap::default(),
            torque_names: FxHashMap::default(),
            kinematic: Vec::new(),
            dependent: Vec::new(),
            dependent_speeds: Vec::new(),
            prepared: false,
            equations: None,
            inputs: Vec::new(),
            units: FxHashMap::default(),
            outputs: Vec::new(),
            code: Vec::new(),
            errors: Vec::new(),
            solved: FxHashMap::default(),
        }
    }

    pub(crate) fn run(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            if let Err(d) = self.statement(s) {
                self.errors.push(d);
            }
        }
    }

    pub(crate) fn finish(self) -> LoadedModel {
        LoadedModel {
            model: self.model,
            equations: self.equations,
            inputs: self.inputs,
            units: self.units,
            outputs: self.outputs,
            code: self.code,
            bindings: self.bindings,
            arrays: self.arrays,
        }
    }

    fn statement(&mut self, s: &Stmt) -> IResult<()> {
        match &s.kind {
            StmtKind::Declare { kind, items } => {
                for item in items {
                    self.declare(*kind, item)?;
                }
                Ok(())
            }
            StmtKind::Mass(items) => {
                for (name, span, e) in items {
                    self.implicit_constants(e)?;
                    let m = self.scalar(e)?;
                    match self.bindings.get(&entity_key(&name.to_ascii_uppercase())) {
                        Some(Binding::Body(b)) => self.model.set_mass(*b, m),
                        Some(Binding::Particle(p)) => self.model.set_particle_mass(*p, m),
                        _ => {
                            return Err(Diagnostic::error(
                                span.clone(),
                                format!("`{name}` is not a body or particle"),
                            )
                            .with_help("declare it with BODIES or PARTICLES before giving it a mass"))
                        }
                    }
                }
                Ok(())
            }
            StmtKind::Inertia { body, body_span, args } => self.inertia(body, body_span, args),
            StmtKind::Setting { name, on } => match name.as_str() {
                "DEGREES" => {
                    self.degrees = *on;
                    Ok(())
                }
                "COMPLEX" | "AUTOZ" | "AUTOEPS" | "AUTORHS" | "ZEE_NOT" | "BEEP" | "OVERWRITE" | "PRINT" => {
                    Ok(())
                }
                _ => Err(Diagnostic::error(s.span.clone(), format!("unknown setting `{name}`"))
                    .with_help("known settings: DEGREES, COMPLEX, AUTOZ")),
            },
            StmtKind::Units(items) => {
                for (name, _, e) in items {
                    self.units.insert(name.to_ascii_uppercase(), unit_text(e));
                }
                Ok(())
            }
            StmtKind::Input(items) => {
                for item in items {
                    let v = self.number(&item.value)?;
                    let name = format!("{}{}", item.name, "'".repeat(item.primes as usize));
                    let in_degrees = item.unit.as_deref() == Some("DEG")
                        || (item.unit.is_none()
                            && self.units.get(&name.to_ascii_uppercase()).is_some_and(|u| is_degrees(u)));
                    let value = if in_degrees { v.to_radians() } else { v };
                    self.inputs.push(InputValue { name, value, unit: item.unit.clone() });
                }
                Ok(())
            }
            StmtKind::Output(items) => {
                for (n, _, u) in items {
                    self.outputs.push((n.clone(), u.clone()));
                }
                Ok(())
            }
            StmtKind::Code { kind, args, file } => {
                for a in args {
                    // CODE DYNAMICS() takes no arguments; ALGEBRAIC/NONLINEAR name equations.
                    let _ = a;
                }
                if kind == "DYNAMICS" && self.equations.is_none() {
                    return Err(Diagnostic::error(s.span.clone(), "CODE DYNAMICS() needs Kane's equations")
                        .with_help("call KANE() (after ZERO = FR() + FRSTAR()) before CODE DYNAMICS()"));
                }
                self.code.push(CodeRequest { kind: kind.clone(), file: file.clone() });
                Ok(())
            }
            StmtKind::Assign { target, op, value } => self.assign(target, *op, value),
            StmtKind::Expr(e) => self.command(e),
        }
    }

    fn declare(&mut self, kind: DeclKind, item: &DeclItem) -> IResult<()> {
        let names = expand_ranges(&item.name, &item.ranges);
        for name in names {
            let key = name.to_ascii_uppercase();
            let span = &item.span;
            let fail: &Span = span;
            match kind {
                DeclKind::Newtonian => {
                    self.model.rename_newtonian(&key).at(fail)?;
                    self.bindings.insert(entity_key(&key), Binding::Frame(self.model.newtonian()));
                }
                DeclKind::Frames => {
                    let f = self.model.add_frame(&key).at(fail)?;
                    self.bindings.insert(entity_key(&key), Binding::Frame(f));
                }
                DeclKind::Bodies => {
                    let b = self.model.add_body(&key).at(fail)?;
                    let cm = self.model.body(b).mass_center;
                    self.bindings.insert(entity_key(&format!("{key}O")), Binding::Point(cm));
                    self.bindings.insert(entity_key(&key), Binding::Body(b));
                }
                DeclKind::Particles => {
                    let p = self.model.add_particle(&key).at(fail)?;
                    self.bindings.insert(entity_key(&key), Binding::Particle(p));
                }
                DeclKind::Points => {
                    let p = self.model.add_point(&key).at(fail)?;
                    self.bindings.insert(entity_key(&key), Binding::Point(p));
                }
                DeclKind::Constants | DeclKind::Imaginary => {
                    let e = self.model.ar.constant(&name).at(fail)?;
                    self.bindings.insert(key, Binding::Symbol(e, 0));
                }
                DeclKind::Variables | DeclKind::MotionVariables | DeclKind::Specified => {
                    let e = if kind == DeclKind::Specified {
                        self.model.ar.specified(&name)
                    } else {
                        self.model.ar.variable(&name)
                    }
                    .at(fail)?;
                    self.bindings.insert(key.clone(), Binding::Symbol(e, item.primes));
                }
            }
        }
        if let Some(v) = &item.value {
            // CONSTANTS F = 3 and SPECIFIED F1 = expr: a value is a definition for that name.
            let val = self.eval(v)?;
            self.bindings.insert(item.name.to_ascii_uppercase(), Binding::Value(val));
        }
        Ok(())
    }

    fn assign(&mut self, target: &super::ast::Target, op: AssignOp, value: &super::ast::Expr) -> IResult<()> {
        let mut v = self.eval(value)?;
        let key = target.name.to_ascii_uppercase();
        if let Some(index) = &target.index {
            let idx = index.iter().map(|e| self.index_value(e)).collect::<IResult<Vec<i64>>>()?;
            return self.assign_array(&key, idx, v, &target.span);
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
                return self.model.orient(b, a, crate::mechanics::Orientation::Dcm(m)).at(&target.span);
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

    fn kinematic_equation(&mut self, target: &super::ast::Target, v: &Value) -> IResult<()> {
        let key = target.name.to_ascii_uppercase();
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

    fn assign_array(&mut self, key: &str, idx: Vec<i64>, v: Value, span: &Span) -> IResult<()> {
        if key == "AUXILIARY" {
            return Err(Diagnostic::error(
                span.clone(),
                "AUXILIARY[] (auxiliary speeds for constraint forces) is not supported",
            )
            .with_help("compute constraint forces from the equations of motion outside the model file"));
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
    pub(crate) fn implicit_constants(&mut self, e: &super::ast::Expr) -> IResult<()> {
        if let super::ast::ExprKind::Name { name, primes: 0, suffix: 0 } = &e.kind {
            let key = name.to_ascii_uppercase();
            if !self.bindings.contains_key(&key) && key != "T" && key != "PI" {
                let c = self.model.ar.constant(name).at(&e.span)?;
                self.bindings.insert(key, Binding::Symbol(c, 0));
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

/// An error unless `args` has `n` entries.
pub(crate) fn arity(name: &str, args: &[super::ast::Expr], n: usize, span: &Span) -> IResult<()> {
    if args.len() == n {
        Ok(())
    } else {
        Err(Diagnostic::error(span.clone(), format!("{name} takes {n} argument(s), got {}", args.len())))
    }
}

/// The key under which a frame, point, body or particle is bound (apart from values).
pub(crate) fn entity_key(upper: &str) -> String {
    format!("#{upper}")
}

/// `Q` with ranges `[(1,3)]` -> `Q1, Q2, Q3`; `P` with `[(1,2),(1,3)]` -> `P11, P12, ..., P23`.
fn expand_ranges(name: &str, ranges: &[(i64, i64)]) -> Vec<String> {
    let mut out = vec![name.to_string()];
    for &(lo, hi) in ranges {
        out = out.iter().flat_map(|p| (lo..=hi).map(move |i| format!("{p}{i}"))).collect();
    }
    out
}

/// The text of a unit expression (`N*m`, `RAD/SEC`), upper-cased.
fn unit_text(e: &super::ast::Expr) -> String {
    use super::ast::{BinOp, ExprKind};
    match &e.kind {
        ExprKind::Name { name, .. } => name.to_ascii_uppercase(),
        ExprKind::Number { value, .. } => format!("{value}"),
        ExprKind::Binary(op, a, b) => {
            let o = match op {
                BinOp::Mul => "*",
                BinOp::Div => "/",
                BinOp::Pow => "^",
                BinOp::Add => "+",
                BinOp::Sub => "-",
            };
            format!("{}{o}{}", unit_text(a), unit_text(b))
        }
        _ => String::new(),
    }
}

/// True for degree units (`DEG`, and the paper's OCR spelling `DFG`).
pub(crate) fn is_degrees(unit: &str) -> bool {
    matches!(unit, "DEG" | "DEGREE" | "DEGREES")
}
