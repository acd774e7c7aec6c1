//! Statements: declarations, MASS, INERTIA, settings, UNITS, INPUT, OUTPUT, CODE, and the
//! dispatch of assignments and commands.
//!
//! In: one parsed statement. Out: the interpreter's bindings and the model changed accordingly
//! (frames, points, bodies, particles and symbols declared; masses given; requests recorded).

use super::super::ast::{expand_ranges, DeclItem, DeclKind, Expr, ExprKind, InputItem, Stmt, StmtKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::super::units::size::{internal_per_declared, unit_size, UnitSystem};
use super::super::units::unit_word;
use super::{entity_key, At, Binding, Bookkeeping, CodeRequest, IResult, InputValue, Interpreter};

/// The `NAME ON` / `NAME OFF` settings a file may give.
pub(crate) const SETTINGS: &[&str] = &["COMPLEX", "DEGREES", "ZEE_NOT"];

impl Interpreter {
    /// Runs one statement.
    pub(super) fn statement(&mut self, s: &Stmt) -> IResult<()> {
        match &s.kind {
            StmtKind::Declare { kind, items } => {
                for item in items {
                    self.declare(*kind, item)?;
                }
                Ok(())
            }
            StmtKind::Mass(items) => self.mass_statement(items),
            StmtKind::Inertia { body, body_span, frame, args } => {
                self.inertia(body, body_span, frame.as_ref(), args)
            }
            StmtKind::Setting { name, on } => self.setting(name, *on, &s.span),
            StmtKind::Units(items) => {
                for item in items {
                    for (word, at) in &item.words {
                        if unit_size(word).is_err() {
                            unit_word(word, at)?;
                        }
                    }
                    unit_size(&item.unit).map_err(|_| {
                        Diagnostic::error(item.span.clone(), "this is not a unit")
                            .with_help("a unit is unit names joined by *, / and ^ (or .), e.g. N*M, KG.M^2/S or RAD/SEC^2")
                    })?;
                    self.units.insert(item.name.to_ascii_uppercase(), item.unit.clone());
                }
                Ok(())
            }
            StmtKind::UnitSystem(words) => self.unit_system(words, &s.span),
            StmtKind::Session(command) => {
                self.bookkeeping.push(Bookkeeping {
                    command: command.clone(),
                    span: s.span.clone(),
                    applied: false,
                });
                Ok(())
            }
            StmtKind::Input(items) => self.input(items),
            StmtKind::Output(items) | StmtKind::Encode(items) => {
                let encode = matches!(s.kind, StmtKind::Encode(_));
                for item in items {
                    if let Some(u) = &item.unit {
                        unit_size(u).map_err(|e| unit_error(&item.span, e))?;
                    }
                    if let Some(e) = &item.expr {
                        // An expression is output under its text, as it stands here.
                        let v = self.eval(e)?;
                        let suffix = if matches!(v, super::value::Value::Vector(_)) { ">" } else { "" };
                        let key = format!("{}{suffix}", item.name.to_ascii_uppercase());
                        self.bindings.insert(key, Binding::Value(v));
                    }
                    if encode {
                        self.encoded.push(item.name.clone());
                    } else {
                        self.outputs.push((item.name.clone(), item.unit.clone()));
                    }
                }
                Ok(())
            }
            StmtKind::Code { kind, args, file } => {
                // CODE DYNAMICS() takes no arguments; ALGEBRAIC/NONLINEAR name equations, and
                // CODE ALGEBRAIC() with none asks for the OUTPUT quantities.
                if kind == "DYNAMICS" && self.equations.is_none() {
                    self.equations_for_code(&s.span)?;
                }
                let system = match kind.as_str() {
                    "ALGEBRAIC" if args.is_empty() => None,
                    "ALGEBRAIC" | "NONLINEAR" => Some(self.algebraic_system(kind, args, &s.span)?),
                    _ => None,
                };
                self.code.push(CodeRequest {
                    kind: kind.clone(),
                    file: file.clone(),
                    span: s.span.clone(),
                    system,
                });
                Ok(())
            }
            // A file the expansion could not run was reported there.
            StmtKind::Run(_) => Ok(()),
            StmtKind::Assign { target, op, value } => self.assign(target, *op, value),
            StmtKind::Expr(e) => self.command(e),
        }
    }

    /// Kane's equations for CODE DYNAMICS() in a file that formed `ZERO = FR() + FRSTAR()`
    /// without KANE() or SOLVE: Autolev's code solves them for the speeds' rates at each step,
    /// as KANE() does. A file that gives every rate itself (`Q' = W`, `SOLVE(EQ, W')`) needs
    /// none: its code integrates the variables whose rates it assigned.
    fn equations_for_code(&mut self, span: &Span) -> IResult<()> {
        if self.kane_sums.is_empty() && !self.model.coordinates_with_kinematics().is_empty() {
            return Ok(());
        }
        if self.kane_sums.is_empty() {
            return Err(Diagnostic::error(span.clone(), "CODE DYNAMICS() needs equations of motion")
                .with_help("form them first: ZERO = FR() + FRSTAR(), then KANE() or SOLVE(ZERO, U1', ...)"));
        }
        self.form_kane(span)
    }

    /// `MASS B = M, P = m, ...`.
    fn mass_statement(&mut self, items: &[(String, Span, Expr)]) -> IResult<()> {
        for (name, span, e) in items {
            let e = self.inline_definition(e)?;
            self.implicit_constants(e)?;
            let m = self.scalar(e)?;
            self.sources.inertial.insert(name.to_ascii_uppercase(), span.clone());
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

    /// `X = value` written where a value is expected (`MASS A = MA = 10`, `INERTIA B, IB =
    /// MB*L^2/12, 0, IB`): assigns X and stands for it; anything else stands for itself.
    pub(crate) fn inline_definition<'e>(&mut self, e: &'e Expr) -> IResult<&'e Expr> {
        let ExprKind::NamedArg(name, value) = &e.kind else { return Ok(e) };
        let ExprKind::Name { name: n, primes: 0, suffix: 0 } = &name.kind else {
            return Err(Diagnostic::error(
                e.span.clone(),
                "only a name may be defined here (`NAME = value`)",
            ));
        };
        let v = self.eval(value)?;
        self.bindings.insert(n.to_ascii_uppercase(), Binding::Value(v));
        Ok(name)
    }

    /// `DEGREES ON`, and settings that change only how Autolev computes in complex numbers or
    /// names Z variables (the session's printing settings are session commands).
    fn setting(&mut self, name: &str, on: bool, span: &Span) -> IResult<()> {
        match name {
            _ if !SETTINGS.contains(&name) => {
                Err(Diagnostic::error(span.clone(), format!("unknown setting `{name}`")).with_help(
                    "known settings: DEGREES, COMPLEX, ZEE_NOT, and the session's AUTOZ, AUTORHS, ...",
                ))
            }
            "DEGREES" => {
                self.degrees = on;
                Ok(())
            }
            // COMPLEX and ZEE_NOT change how Autolev computes in complex numbers and names Z variables.
            _ => Ok(()),
        }
    }

    /// `UNITSYSTEM KG, METER, SEC`: the units INPUT values with a unit tag are converted into.
    fn unit_system(&mut self, words: &[(String, Span)], span: &Span) -> IResult<()> {
        let names: Vec<String> = words.iter().map(|(w, _)| w.clone()).collect();
        self.unit_system = UnitSystem::from_words(&names).map_err(|(i, e)| {
            Diagnostic::error(words[i].1.clone(), e).with_help(
                "UNITSYSTEM names one unit each of mass, length and time, e.g. UNITSYSTEM KG, METER, SEC",
            )
        })?;
        self.bookkeeping.push(Bookkeeping {
            command: "UNITSYSTEM".into(),
            span: span.clone(),
            applied: true,
        });
        Ok(())
    }

    /// `INPUT a = value [unit], ...`: values kept in internal units: a value with a unit tag is
    /// converted into the unit system (angles into radians); one without is in the unit UNITS
    /// gives its name, converted where that measures an angle (DEG, DEG/S, RPM), else as written.
    fn input(&mut self, items: &[InputItem]) -> IResult<()> {
        for item in items {
            let factor = match &item.unit {
                Some(u) => self.unit_system.factor(unit_size(u).map_err(|e| unit_error(&item.span, e))?),
                None => 1.0,
            };
            let v = self.number(&item.value)?;
            let name = format!("{}{}", item.name, "'".repeat(item.primes as usize));
            let value = match (&item.unit, self.units.get(&name.to_ascii_uppercase())) {
                (None, Some(declared)) => v * internal_per_declared(declared, &self.unit_system),
                _ => v * factor,
            };
            self.inputs.push(InputValue { name, value, unit: item.unit.clone(), span: item.span.clone() });
        }
        Ok(())
    }

    /// A declaration: NEWTONIAN, FRAMES, BODIES, PARTICLES, POINTS, CONSTANTS, VARIABLES, ...
    fn declare(&mut self, kind: DeclKind, item: &DeclItem) -> IResult<()> {
        let names: Vec<String> = expand_ranges(&item.name, &item.ranges)
            .into_iter()
            .map(|n| format!("{n}{}", item.tail))
            .collect();
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
                    if kind == DeclKind::MotionVariables {
                        self.motion_variables.extend(self.model.ar.as_symbol(e));
                    }
                    self.bindings.insert(key.clone(), Binding::Symbol(e, item.primes));
                }
            }
        }
        if let Some(v) = &item.value {
            // CONSTANTS F = 3: a value is a definition for that name; SPECIFIED F1 = expr is
            // F1's formula.
            let val = self.eval(v)?;
            let key = format!("{}{}", item.name.to_ascii_uppercase(), item.tail.to_ascii_uppercase());
            if kind == DeclKind::Specified {
                self.specified_formula(&key, &val, &item.span)?;
            } else {
                self.bindings.insert(item.name.to_ascii_uppercase(), Binding::Value(val));
            }
        }
        Ok(())
    }
}

/// A unit tag that is not a unit, at `span`.
fn unit_error(span: &Span, e: String) -> Diagnostic {
    let unknown = e.strip_prefix("unknown unit `").and_then(|w| w.strip_suffix('`'));
    if let Some(Err(d)) = unknown.map(|w| unit_word(w, span)) {
        return d;
    }
    Diagnostic::error(span.clone(), e)
        .with_help("a unit is unit names joined by *, / and ^ (or .), e.g. M/S^2, KG*M^2, KG.M^2 or RAD/SEC")
}
