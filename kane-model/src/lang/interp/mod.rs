//! Lowering an Autolev program onto the mechanics layer, statement by statement.
//!
//! In: parsed statements. Out: a [`LoadedModel`] (the mechanics model, Kane's equations if
//! asked for, INPUT/OUTPUT/UNITS/CODE requests, the final values of names) and the diagnostics
//! of statements that failed. This file holds the interpreter's state and the shared helpers;
//! `statements`, `assign`, `commands`, `eval` and the function families do the work.
//!
//! Names are case-insensitive: every lookup goes through the upper-cased name; symbols keep the
//! spelling of their declaration for printing.

mod algebra_fns;
mod assign;
mod cascade;
mod code_request;
mod commands;
mod deferral;
mod eigen;
mod energy_check;
mod eval;
mod functions;
pub(crate) use functions::KNOWN_CALLS;
mod inertia;
mod mass_fns;
mod matrix_fns;
mod motion_equations;
pub(crate) mod names;
mod orientation;
mod poly_roots;
mod polynomial;
mod prepare;
mod scalar_fns;
mod sources;
mod specified;
mod spline;
pub(crate) use specified::specified_formulas;
mod statements;
pub mod value;
mod vector_fns;

/// Every word the model language gives a meaning, sorted: declarations, statements, commands,
/// functions, session commands, settings and inertia shapes.
pub fn language_words() -> Vec<&'static str> {
    use super::parser::{DECLARATIONS, SESSION_COMMANDS, STATEMENT_WORDS};
    let mut words: Vec<&'static str> = DECLARATIONS.iter().map(|(w, _)| *w).collect();
    words.extend(STATEMENT_WORDS.iter().chain(SESSION_COMMANDS).chain(statements::SETTINGS));
    words.extend(functions::KNOWN_CALLS.iter().chain(inertia::SHAPES.iter().map(|(s, _)| s)));
    words.sort_unstable();
    words.dedup();
    words
}

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{BodyId, FrameId, KaneEquations, MassId, Model, ParticleId, PointId, Vector};

use super::ast::{Expr, Stmt};
use super::diagnostic::Diagnostic;
use super::token::Span;
use super::units::size::UnitSystem;
pub(crate) use names::edit_distance;
pub use names::nearest_word;
pub(crate) use sources::{KinematicSource, LoadSource, Sources};
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
    /// Where the INPUT item is in the source.
    pub span: Span,
}

/// A bookkeeping command of the file and what became of it.
#[derive(Clone, Debug, PartialEq)]
pub struct Bookkeeping {
    /// The command, upper-cased (`UNITSYSTEM`, `AUTOZ`, `ENCODE`, ...).
    pub command: String,
    /// Where it is in the source.
    pub span: Span,
    /// True when it changes the model's numbers (UNITSYSTEM converts INPUT values); false
    /// when it is ignored (it changes only how Autolev prints, saves or pauses).
    pub applied: bool,
}

/// A CODE request.
#[derive(Clone, Debug, PartialEq)]
pub struct CodeRequest {
    /// DYNAMICS, ALGEBRAIC, NONLINEAR, ODE.
    pub kind: String,
    /// The file named.
    pub file: String,
    /// Where the request is.
    pub span: Span,
    /// For ALGEBRAIC and NONLINEAR: the equations as they stood there and the unknowns.
    pub system: Option<super::algebraic::AlgebraicSystem>,
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
    /// ENCODE: the names generated code computes besides the outputs.
    pub encoded: Vec<String>,
    /// CODE requests.
    pub code: Vec<CodeRequest>,
    /// The acceleration of gravity GRAVITY gave, if any.
    pub gravity: Option<Vector>,
    /// Commands that only keep Autolev's books (UNITSYSTEM, AUTOZ, ENCODE, ...), in order.
    pub bookkeeping: Vec<Bookkeeping>,
    pub(crate) bindings: FxHashMap<String, Binding>,
    arrays: FxHashMap<String, Vec<(Vec<i64>, Value)>>,
    pub(crate) sources: Sources,
    /// The text the model ran from: the file's, then the files it runs (spans index it).
    pub(crate) text: String,
    /// Where each file's text is in `text`.
    pub(crate) parts: Vec<super::diagnostic::SourcePart>,
    /// The names statements that failed mention: checks of what they would have set up are
    /// follow-on errors.
    pub(crate) tainted: cascade::Tainted,
    /// The formulas of SPECIFIED quantities (see [`Interpreter`]'s).
    pub(crate) formulas: FxHashMap<String, ExprId>,
    /// Whether the file formed FR() or FRSTAR().
    pub(crate) forces_formed: bool,
    /// The warnings of statements that ran.
    pub(crate) warnings: Vec<Diagnostic>,
}

impl LoadedModel {
    /// A report of `diagnostics` on this model's file, `file`.
    pub(crate) fn report(&self, file: &str, diagnostics: Vec<Diagnostic>) -> super::diagnostic::Report {
        super::diagnostic::Report {
            file: file.to_string(),
            source: self.text.clone(),
            diagnostics,
            parts: self.parts.clone(),
        }
    }

    /// The value a name has at the end of the file (case-insensitive; `V>` for vectors).
    pub fn value(&self, name: &str) -> Option<Value> {
        let key = name.to_ascii_uppercase();
        match self.bindings.get(&key) {
            Some(Binding::Value(v)) => Some(v.clone()),
            // A SPECIFIED quantity with a formula: the formula.
            Some(Binding::Symbol(..)) if self.formulas.contains_key(&key) => {
                Some(Value::Scalar(self.formulas[&key]))
            }
            // EQN[1], EQN[2], ...: a column of scalars (B[i, j]: a matrix).
            _ => value::array_value(self.arrays.get(&key)?),
        }
    }

    /// The VARIABLES declared without a derivative (`VARIABLES X`) that are neither coordinates
    /// nor speeds: quantities the file lets vary from outside, as parameters.
    pub(crate) fn unstated_variables(&self) -> Vec<crate::expr::SymbolId> {
        let m = &self.model;
        let states: Vec<crate::expr::SymbolId> = m.coordinates().iter().chain(m.speeds()).copied().collect();
        let mut out: Vec<_> = self
            .bindings
            .values()
            .filter_map(|b| match b {
                Binding::Symbol(e, 0) => m.ar.as_symbol(*e),
                _ => None,
            })
            .filter(|s| matches!(m.ar.symbol_info(*s).kind, crate::expr::SymbolKind::Variable { order: 0 }))
            .filter(|s| !states.contains(s) && !m.auxiliary_speeds().contains(s))
            .collect();
        out.sort();
        out.dedup();
        out
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
    /// GRAVITY's acceleration, and the bodies and particles it acts on when it names them.
    pub(crate) gravity: Option<(Vector, Option<Vec<MassId>>)>,
    pub(crate) forces: Vec<(PointId, Vector)>,
    pub(crate) torques: Vec<(FrameId, Vector)>,
    pub(crate) force_names: FxHashMap<PointId, usize>,
    pub(crate) torque_names: FxHashMap<FrameId, usize>,
    pub(crate) kinematic: Vec<(SymbolId, ExprId)>,
    pub(crate) dependent: Vec<ExprId>,
    pub(crate) dependent_speeds: Vec<ExprId>,
    /// The auxiliary speeds CONSTRAIN(AUXILIARY[...]) named.
    pub(crate) auxiliary_speeds: Vec<ExprId>,
    pub(crate) prepared: bool,
    pub(crate) equations: Option<KaneEquations>,
    pub(crate) inputs: Vec<InputValue>,
    pub(crate) units: FxHashMap<String, String>,
    pub(crate) outputs: Vec<(String, Option<String>)>,
    pub(crate) encoded: Vec<String>,
    pub(crate) code: Vec<CodeRequest>,
    pub(crate) unit_system: UnitSystem,
    pub(crate) bookkeeping: Vec<Bookkeeping>,
    pub(crate) errors: Vec<Diagnostic>,
    pub(crate) solved: FxHashMap<String, ExprId>,
    pub(crate) sources: Sources,
    /// True when work a large tree's order-n form may not need is deferred (see [`deferral`]).
    pub(crate) defer: bool,
    /// Deferred statements, in order.
    pub(crate) deferred: Vec<Stmt>,
    /// Where the KANE() is whose `M` and `f` are not yet formed.
    pub(crate) deferred_kane: Option<Span>,
    /// Names whose value is `FR() + FRSTAR()` as assigned (unchanged since): SOLVE of them for
    /// the speeds' rates forms Kane's equations as KANE() does.
    pub(crate) kane_sums: rustc_hash::FxHashSet<String>,
    /// The names failed statements mention (see [`cascade`]).
    pub(crate) tainted: cascade::Tainted,
    /// The points whose velocities or accelerations the statement running has read.
    pub(crate) kinematic_reads: Vec<PointId>,
    /// The formulas given to SPECIFIED quantities and their derivatives (`T = ...`, `DA' = ...`),
    /// by upper-cased name with its primes: put into the equations and outputs at the end, as
    /// Autolev's code evaluates them first; the names themselves stay quantities.
    pub(crate) formulas: FxHashMap<String, ExprId>,
    /// True once SOLVE(ZERO, U1', ...) solved the equations of motion: `U1'` then reads the
    /// rate solved (formed as an expression when first read).
    pub(crate) rates_solved: bool,
    /// The quantities MOTIONVARIABLES declared: where there are any, the generalized
    /// coordinates and speeds are among them (VARIABLES are other quantities of time).
    pub(crate) motion_variables: Vec<crate::expr::SymbolId>,
    /// Angular velocities assigned through chains of orientations (`W_R_N> = U1*L1> + ...`),
    /// with where: their kinematic equations are solved when the equations are formed, for the
    /// chain's coordinates the file gave none.
    pub(crate) chain_speeds: Vec<(FrameId, FrameId, Vector, Span)>,
    /// `INERTIA B_P` statements whose point P's position from BO is not known yet: the body,
    /// P, the inertia about P, its frame and where.
    pub(crate) pending_inertias: Vec<(BodyId, PointId, crate::mechanics::Dyadic, FrameId, Span)>,
    /// Whether the file formed FR() or FRSTAR() (its equations of motion are then KANE()'s,
    /// for code generation, even where it calls neither KANE() nor SOLVE).
    pub(crate) forces_formed: bool,
    /// Warnings of statements that ran (what the file leaves to a reading it may not mean).
    pub(crate) warnings: Vec<Diagnostic>,
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
                E::OrientationCycle { .. } => Some(
                    "orientations form a tree: relate each frame to one neighbour only (a frame relative to itself, or to a frame it already turns with through others, is a loop)",
                ),
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
            auxiliary_speeds: Vec::new(),
            prepared: false,
            equations: None,
            inputs: Vec::new(),
            units: FxHashMap::default(),
            outputs: Vec::new(),
            encoded: Vec::new(),
            code: Vec::new(),
            unit_system: UnitSystem::default(),
            bookkeeping: Vec::new(),
            errors: Vec::new(),
            solved: FxHashMap::default(),
            sources: Sources::default(),
            defer: false,
            deferred: Vec::new(),
            deferred_kane: None,
            kane_sums: Default::default(),
            tainted: Default::default(),
            kinematic_reads: Vec::new(),
            formulas: FxHashMap::default(),
            rates_solved: false,
            motion_variables: Vec::new(),
            chain_speeds: Vec::new(),
            pending_inertias: Vec::new(),
            forces_formed: false,
            warnings: Vec::new(),
        }
    }

    /// Runs `stmts` of `source` in order, after the parser's `parse_errors`: each failing
    /// statement's error is kept unless it follows from an earlier failure (see [`cascade`]).
    pub(crate) fn run(&mut self, stmts: &[Stmt], source: &str, parse_errors: &[Diagnostic]) {
        let mut tainted = std::mem::take(&mut self.tainted);
        let mut failed_lines = parse_errors.iter().map(|d| d.span.start).peekable();
        for s in stmts {
            while let Some(at) = failed_lines.next_if(|at| *at < s.span.start) {
                tainted.add_line_of(source, at);
            }
            self.settle_before(s);
            self.sources.executed.push(s.span.clone());
            self.kinematic_reads.clear();
            let done = match self.defers(s) {
                Ok(true) => Ok(()),
                Ok(false) => self.statement(s),
                Err(d) => Err(d),
            };
            if let Err(d) = done {
                if !tainted.explains(&d.message) && !tainted.explains_statement(source, &s.span) {
                    self.errors.push(d);
                }
                tainted.add_statement(source, s);
            }
        }
        for at in failed_lines {
            tainted.add_line_of(source, at);
        }
        self.tainted = tainted;
        // An inertia about a point the file never located BO from is an error at its line.
        if let Err(d) = self.settle_inertias() {
            self.errors.push(d);
        }
    }

    /// Puts the formulas given to SPECIFIED quantities into the equations (after the file ran).
    pub(crate) fn put_specified_formulas(&mut self) {
        let Some(eqs) = self.equations.as_mut() else { return };
        let solved: Vec<_> = eqs.loads.iter().flat_map(|l| l.loads.clone()).collect();
        let put = specified::specified_formulas(&mut self.model, &self.formulas).and_then(|map| {
            let given = solved.iter().find(|s| map.contains_key(&self.model.ar.symbol_expr(**s)));
            if let Some(s) = given {
                let name = self.model.ar.symbol_info(*s).name.clone();
                return Err(crate::mechanics::MechanicsError::LoadHasFormula(name));
            }
            eqs.substitute(&mut self.model.ar, &map)
        });
        if let Err(e) = put {
            self.errors.push(Diagnostic::error(
                0..0,
                format!("a SPECIFIED quantity's formula cannot be put into the equations: {e}"),
            ));
        }
    }

    pub(crate) fn finish(mut self, text: String, parts: Vec<super::diagnostic::SourcePart>) -> LoadedModel {
        // The systems CODE ALGEBRAIC and NONLINEAR solve read the SPECIFIED quantities' formulas.
        if let Ok(map) = specified::specified_formulas(&mut self.model, &self.formulas) {
            for system in self.code.iter_mut().filter_map(|c| c.system.as_mut()) {
                if let Ok(e) = self.model.ar.subs_many(&system.equations, &map) {
                    system.equations = e;
                }
            }
        }
        LoadedModel {
            model: self.model,
            equations: self.equations,
            inputs: self.inputs,
            units: self.units,
            outputs: self.outputs,
            encoded: self.encoded,
            code: self.code,
            gravity: self.gravity.map(|(g, _)| g),
            bookkeeping: self.bookkeeping,
            bindings: self.bindings,
            arrays: self.arrays,
            sources: self.sources,
            text,
            parts,
            tainted: self.tainted,
            formulas: self.formulas,
            forces_formed: self.forces_formed,
            warnings: self.warnings,
        }
    }
}

/// An error unless `args` has `n` entries.
pub(crate) fn arity(name: &str, args: &[Expr], n: usize, span: &Span) -> IResult<()> {
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
