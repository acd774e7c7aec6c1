//! Commands: SIMPROT, V2PTS and friends, ANGVEL, GRAVITY, FORCE/TORQUE, CONSTRAIN, SOLVE, KANE,
//! and the rewriting commands (EXPAND, ...) used as statements.
//!
//! In: a statement that is a bare expression. Out: changes to the interpreter and its model
//! (orientations, loads, constraints, solutions, Kane's equations); a call that is no command is
//! evaluated as a function and its value dropped.

use crate::expr::{ExprId, SymbolKind};
use crate::mechanics::{FrameId, Orientation, PointId, Vector};

use super::super::ast::{BinOp, Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::sources::{KinematicSource, Theorem};
use super::value::Value;
use super::{At, Binding, IResult, Interpreter};

impl Interpreter {
    /// A statement that is a bare expression: a command, or a value shown by Autolev.
    pub(crate) fn command(&mut self, e: &Expr) -> IResult<()> {
        let ExprKind::Call { name, args } = &e.kind else {
            return match (self.eval(e), &e.kind) {
                (Err(d), ExprKind::Name { name, suffix: 0, primes: 0 })
                    if d.message.ends_with("is not defined") =>
                {
                    Err(unknown_command(name, &e.span))
                }
                (r, _) => r.map(|_| ()),
            };
        };
        let upper = name.to_ascii_uppercase();
        if !super::functions::KNOWN_CALLS.contains(&upper.as_str()) {
            let mut d = super::functions::unknown_function(name, &upper, &e.span);
            d.message = d.message.replacen("unknown function", "unknown command", 1);
            return Err(d);
        }
        match upper.as_str() {
            "SIMPROT" => self.simprot(args, e),
            "V2PTS" | "A2PTS" | "V1PT" | "A1PT" => self.point_theorem(&upper, args, e),
            // ANGVEL(A, B) forms W_B_A>; ANGVEL(A, B, BODY123, Q1, Q2, Q3) sets it to the
            // rates of that rotation sequence.
            "ANGVEL" if args.len() > 2 => self.angvel_by_sequence(args, &e.span),
            "ANGVEL" => {
                super::arity(&upper, args, 2, &e.span)?;
                let a = self.frame_arg(&args[0])?;
                let b = self.frame_arg(&args[1])?;
                self.model.angular_velocity(b, a).map(|_| ()).at(&e.span)
            }
            "GRAVITY" => {
                let Some((g, bodies)) = args.split_first() else {
                    return Err(Diagnostic::error(
                        e.span.clone(),
                        "GRAVITY needs the acceleration of gravity",
                    )
                    .with_help("e.g. GRAVITY(-G*N2>), or GRAVITY(-G*N2>, B, C) for some masses only"));
                };
                let only = if bodies.is_empty() { None } else { Some(self.mass_ids(bodies)?) };
                self.gravity = Some((self.vector(g)?, only));
                self.prepared = false;
                Ok(())
            }
            "FORCE" | "TORQUE" => self.load_command(&upper, args, e),
            "CONSTRAIN" => self.constrain(args, e),
            "SOLVE" => self.solve(args, e),
            "DIRCOS" => self.dircos(args, &e.span),
            "KINDIFFS" => self.kindiffs(args, &e.span),
            // UNITSYSTEM and ENCODE choose how Autolev prints; results are unchanged.
            "UNITSYSTEM" | "ENCODE" => Ok(()),
            // ANIMATE(N, O, B) writes data for Autolev's animation program: kept in the books.
            "ANIMATE" => {
                let span = e.span.clone();
                self.bookkeeping.push(super::Bookkeeping { command: upper.clone(), span, applied: false });
                Ok(())
            }
            "KANE" => {
                self.solved_loads(args, &e.span)?;
                self.form_kane(&e.span)
            }
            "EXPAND" | "FACTOR" | "ARRANGE" | "EXPLICIT" => self.rewrite_in_place(name, args, e),
            _ => match self.call(name, args, e) {
                Err(mut d) if d.message.starts_with("unknown function") => {
                    d.message = d.message.replacen("unknown function", "unknown command", 1);
                    Err(d)
                }
                other => other.map(|_| ()),
            },
        }
    }

    /// `KANE(T1, ...)`: the loads solved for with the speed rates, one per auxiliary speed;
    /// each a time-dependent quantity the forces and torques contain, with no formula.
    fn solved_loads(&mut self, args: &[Expr], span: &Span) -> IResult<()> {
        let mut loads = Vec::with_capacity(args.len());
        for a in args {
            let x = self.scalar(a)?;
            let time_dependent = self.model.ar.as_symbol(x).is_some_and(|s| {
                matches!(
                    self.model.ar.symbol_info(s).kind,
                    SymbolKind::Variable { order: 0 } | SymbolKind::Specified { order: 0 }
                )
            });
            if !time_dependent {
                return Err(Diagnostic::error(a.span.clone(), "KANE solves for time-dependent quantities (VARIABLES or SPECIFIED) by name")
                    .with_help("declare the load, for example VARIABLES T1, use it in TORQUE or FORCE, and name it in KANE(T1)"));
            }
            loads.push(x);
        }
        if loads.len() != self.auxiliary_speeds.len() {
            let span = args.first().map_or_else(|| span.clone(), |a| a.span.clone());
            return Err(Diagnostic::error(
                span,
                format!("KANE names {} loads but CONSTRAIN(AUXILIARY[...]) declared {} auxiliary speeds", loads.len(), self.auxiliary_speeds.len()),
            )
            .with_help("each auxiliary speed's equation determines one load: name as many in KANE(...) as there are auxiliary speeds"));
        }
        self.model.set_solved_loads(&loads).at(span)?;
        Ok(())
    }

    /// Kane's equations of the model as it stands (KANE()), their mass matrix left unformed
    /// when generation defers it.
    pub(super) fn form_kane(&mut self, span: &Span) -> IResult<()> {
        self.prepare(span)?;
        self.deferred_kane = None;
        let shape = if self.defer { Some(self.model.kane_unformed().at(span)?) } else { None };
        let eqs = match shape {
            Some(shape) if self.model.defers_mass_matrix(&shape) => {
                self.deferred_kane = Some(span.clone());
                shape
            }
            _ => self.model.kane().at(span)?,
        };
        self.equations = Some(eqs);
        Ok(())
    }

    /// `SIMPROT(A, B, axis, angle)`: B turned from A about one of A's axes, or about any vector
    /// fixed in A (its direction: the rotation by Rodrigues' formula).
    fn simprot(&mut self, args: &[Expr], e: &Expr) -> IResult<()> {
        let fail: &Span = &e.span;
        super::arity("SIMPROT", args, 4, &e.span)?;
        let parent = self.frame_arg(&args[0])?;
        let child = self.frame_arg(&args[1])?;
        let mut angle = self.scalar(&args[3])?;
        if self.degrees && self.model.ar.free_symbols(&[angle]).is_empty() {
            // With DEGREES ON a numeric angle is in degrees.
            let k = self.model.ar.float(std::f64::consts::PI / 180.0).at(fail)?;
            angle = self.model.ar.mul(&[k, angle]).at(fail)?;
        }
        let orientation = match self.axis_arg(&args[2], parent) {
            Ok(axis) => Orientation::Axis { axis, angle },
            Err(bad) => match self.eval(&args[2])? {
                Value::Vector(v) => self.rotation_about(&v, parent, angle, fail)?,
                _ => return Err(bad),
            },
        };
        self.model.orient(child, parent, orientation).at(fail)?;
        self.sources.orientation(child, parent, &e.span);
        Ok(())
    }

    /// `V2PTS(N, B, P, Q)`, `A2PTS`, `V1PT`, `A1PT`: the velocity or acceleration theorems.
    fn point_theorem(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<()> {
        super::arity(upper, args, 4, &e.span)?;
        let frame = self.frame_arg(&args[0])?;
        let body = self.frame_arg(&args[1])?;
        let from = self.point_arg(&args[2])?;
        let to = self.point_arg(&args[3])?;
        if matches!(
            self.model.velocity(from, frame),
            Err(crate::mechanics::MechanicsError::VelocityUndefined { .. })
        ) {
            // A point whose motion nothing gives: at rest there, said in a warning.
            let (p, f) = (self.model.point_name(from).to_string(), self.model.frame_name(frame).to_string());
            self.warnings.push(
                Diagnostic::warning(e.span.clone(), format!("{p} has no velocity in {f} (none is assigned, nor a position from a point that has one): {upper} takes it as at rest there"))
                    .with_help(format!("say so with V_{p}_{f}> = 0> (or give its motion)")),
            );
            self.model.fix_point(from, frame);
            let at_rest = KinematicSource { span: e.span.clone(), theorem: None, reads: Vec::new() };
            self.sources.velocities.insert((from, frame), at_rest);
        }
        if self.model.position(to, from).is_err() {
            let (p, q) = (self.model.point_name(from).to_string(), self.model.point_name(to).to_string());
            self.warnings.push(
                Diagnostic::warning(
                    e.span.clone(),
                    format!("{p} and {q} are related by no position: {upper} takes them as one place"),
                )
                .with_help(format!("say so with P_{p}_{q}> = 0> (or place {q} from {p})")),
            );
            self.model.set_position(to, from, Vector::zero()).at(&e.span)?;
            self.sources.position(to, from, &e.span);
        }
        match upper {
            "V2PTS" => self.model.v2pts(frame, body, from, to),
            "A2PTS" => self.model.a2pts(frame, body, from, to),
            "V1PT" => self.model.v1pt(frame, body, from, to),
            _ => self.model.a1pt(frame, body, from, to),
        }
        .at(&e.span)?;
        let theorem = if upper.contains('2') { Theorem::TwoPoints } else { Theorem::OnePoint };
        let source =
            KinematicSource { span: e.span.clone(), theorem: Some((theorem, body, from)), reads: Vec::new() };
        let set = if upper.starts_with('V') {
            &mut self.sources.velocities
        } else {
            &mut self.sources.accelerations
        };
        set.insert((to, frame), source);
        Ok(())
    }

    /// `FORCE(P, F>)`, `FORCE(Q/P, F>)` (and the opposite on Q), and likewise TORQUE on frames.
    fn load_command(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<()> {
        super::arity(upper, args, 2, &e.span)?;
        let v = self.vector(&args[1])?;
        let (on, from) = match &args[0].kind {
            ExprKind::Binary(BinOp::Div, a, b) => (b.as_ref(), Some(a.as_ref())),
            _ => (&args[0], None),
        };
        self.prepared = false;
        if upper == "FORCE" {
            let p = self.point_arg(on)?;
            self.add_to_force(p, &v, false, &e.span)?;
            self.record_load(format!("FORCE_{}>", self.model.point_name(p)), &e.span, false);
            if let Some(from) = from {
                let q = self.point_arg(from)?;
                self.add_to_force(q, &v, true, &e.span)?;
            }
        } else {
            let f = self.frame_arg(on)?;
            self.add_to_torque(f, &v, false, &e.span)?;
            self.record_load(format!("TORQUE_{}>", self.model.frame_name(f)), &e.span, false);
            if let Some(from) = from {
                let g = self.frame_arg(from)?;
                self.add_to_torque(g, &v, true, &e.span)?;
            }
        }
        Ok(())
    }

    /// Records a statement adding to the load `name` (for the duplicate-load check).
    pub(crate) fn record_load(&mut self, name: String, span: &Span, assigned: bool) {
        self.sources.loads.push(super::sources::LoadSource { name, span: span.clone(), assigned });
    }

    /// The resultant force at `p` plus `v` (minus `v` with `negate`).
    pub(crate) fn add_to_force(&mut self, p: PointId, v: &Vector, negate: bool, span: &Span) -> IResult<()> {
        let prev = self.force_names.get(&p).map(|i| self.forces[*i].1.clone()).unwrap_or_default();
        let sum = if negate { self.model.sub_vectors(&prev, v) } else { self.model.add_vectors(&prev, v) };
        let sum = sum.at(span)?;
        self.set_force(p, sum);
        Ok(())
    }

    /// The resultant torque on the body of `f` plus `v` (minus `v` with `negate`).
    pub(crate) fn add_to_torque(&mut self, f: FrameId, v: &Vector, negate: bool, span: &Span) -> IResult<()> {
        let prev = self.torque_names.get(&f).map(|i| self.torques[*i].1.clone()).unwrap_or_default();
        let sum = if negate { self.model.sub_vectors(&prev, v) } else { self.model.add_vectors(&prev, v) };
        let sum = sum.at(span)?;
        self.set_torque(f, sum);
        Ok(())
    }

    /// `CONSTRAIN(DEPENDENT[u1, ...])`: the speeds the DEPENDENT constraints are solved for;
    /// `CONSTRAIN(AUXILIARY[u1, ...])`: auxiliary speeds (either or both, in any order).
    fn constrain(&mut self, args: &[Expr], e: &Expr) -> IResult<()> {
        if args.is_empty() || args.len() > 2 {
            return Err(Diagnostic::error(
                e.span.clone(),
                "CONSTRAIN takes DEPENDENT[u1, ...] and/or AUXILIARY[u1, ...]",
            ));
        }
        for arg in args {
            let ExprKind::Index { name, args: speeds } = &arg.kind else {
                return Err(Diagnostic::error(
                    arg.span.clone(),
                    "CONSTRAIN takes DEPENDENT[u1, ...] or AUXILIARY[u1, ...]",
                ));
            };
            let list = speeds.iter().map(|s| self.scalar(s)).collect::<IResult<Vec<_>>>()?;
            match name.to_ascii_uppercase().as_str() {
                "DEPENDENT" => self.dependent_speeds = list,
                "AUXILIARY" => self.auxiliary_speeds = list,
                _ => {
                    return Err(Diagnostic::error(arg.span.clone(), format!("CONSTRAIN({name}[...]) is not supported"))
                        .with_help("write the constraints as DEPENDENT[i] = ... and call CONSTRAIN(DEPENDENT[u...]), or name auxiliary speeds with CONSTRAIN(AUXILIARY[u...])"));
                }
            }
        }
        self.prepared = false;
        Ok(())
    }

    /// `SOLVE(EQN, X, Y, ...)` or `SOLVE(EQN, [X, Y])`: the linear equations EQN solved for the
    /// unknowns, kept for RHS.
    fn solve(&mut self, args: &[Expr], e: &Expr) -> IResult<()> {
        if args.len() < 2 {
            return Err(Diagnostic::error(e.span.clone(), "SOLVE takes (EQN, X, Y, ...)"));
        }
        // The equations: an array or column by name (ZERO), or any scalar or matrix
        // (`SOLVE([EQ1, EQ2], ...)`, `SOLVE(DT(H), Q3')`).
        let (key, eqs) = match &args[0].kind {
            ExprKind::Name { name, primes: 0, suffix: 0 }
                if !self.equations_named(&name.to_ascii_uppercase()).is_empty() =>
            {
                let key = name.to_ascii_uppercase();
                let eqs = self.equations_named(&key);
                (key, eqs)
            }
            _ => match self.eval(&args[0])? {
                Value::Scalar(x) => (String::new(), vec![x]),
                Value::Matrix { data, .. } => (String::new(), data),
                other => {
                    return Err(Diagnostic::error(
                        args[0].span.clone(),
                        format!("SOLVE takes equations (scalars), not {}", other.kind()),
                    ))
                }
            },
        };
        // Unknowns one by one, in a bracketed list (SOLVE(ZERO, [U4', U6'])) or a matrix of
        // them by name (QDD = [Q1''; Q2''], SOLVE(ZERO, QDD)).
        let mut syms = Vec::new();
        for a in &args[1..] {
            let found = match &a.kind {
                ExprKind::Matrix(rows) => {
                    rows.iter().flatten().map(|x| self.substitution_key(x)).collect::<IResult<Vec<_>>>()?
                }
                ExprKind::Name { .. } => match self.eval(a) {
                    Ok(Value::Matrix { data, .. }) => data,
                    _ => vec![self.substitution_key(a)?],
                },
                _ => vec![self.substitution_key(a)?],
            };
            for x in found {
                syms.push(
                    self.model
                        .ar
                        .as_symbol(x)
                        .ok_or_else(|| Diagnostic::error(a.span.clone(), "SOLVE takes unknowns by name"))?,
                );
            }
        }
        let names: Vec<String> =
            syms.iter().map(|s| self.model.ar.symbol_info(*s).name.to_ascii_uppercase()).collect();
        let with_loads = self.equations.as_ref().is_some_and(|q| q.loads.is_some());
        if with_loads
            && eqs.len() > syms.len()
            && self.kane_sums.contains(&key)
            && self.are_speed_rates(&syms)
        {
            // KANE(F1, ...) solved its loads from the auxiliary rows, which Autolev then drops
            // from ZERO: SOLVE assigns the rates of KANE()'s equations.
            self.rates_solved = true;
            return Ok(());
        }
        if self.equations.is_none() && self.are_speed_rates(&syms) {
            // The equations of motion: formed as KANE() does when they are FR() + FRSTAR(); the
            // rates are then assigned, as Autolev's SOLVE assigns them (read by name later).
            self.rates_solved = true;
            if self.kane_sums.contains(&key) {
                return self.form_kane(&e.span);
            }
            return self.equations_of_motion(&eqs, &e.span);
        }
        let sol = self.model.ar.solve_linear(&eqs, &syms).at(&e.span)?;
        for ((n, x), s) in names.into_iter().zip(sol).zip(&syms) {
            self.solved.insert(n, x);
            self.rate_solved(*s, x, &e.span)?;
        }
        Ok(())
    }

    /// A variable's rate SOLVE gives, for a variable with no kinematic equation yet and that is
    /// not a speed: its kinematic equation (Autolev integrates a variable whose rate is
    /// assigned, as a coordinate).
    fn rate_solved(&mut self, rate: crate::expr::SymbolId, value: ExprId, span: &Span) -> IResult<()> {
        let info = self.model.ar.symbol_info(rate);
        let SymbolKind::Variable { order: 1 } = info.kind else { return Ok(()) };
        let q = info.base;
        let ruled = self.kinematic.iter().any(|(k, _)| *k == q);
        let declared_first_order = self
            .bindings
            .values()
            .any(|b| matches!(b, Binding::Symbol(e, 1) if self.model.ar.as_symbol(*e) == Some(q)));
        if ruled || !declared_first_order || self.model.speeds().contains(&q) {
            return Ok(());
        }
        self.kinematic.push((q, value));
        let q = self.model.ar.symbol_expr(q);
        self.model.set_kinematics(q, value).at(span)?;
        self.prepared = false;
        Ok(())
    }

    /// The equations under a name: an array EQN[1], EQN[2], ... or a column such as ZERO.
    pub(crate) fn equations_named(&self, key: &str) -> Vec<ExprId> {
        match self.lookup_value(key) {
            Some(Value::Matrix { data, .. }) => data,
            Some(Value::Scalar(x)) => vec![x],
            _ => {
                let mut entries = self.arrays.get(key).cloned().unwrap_or_default();
                entries.sort_by(|a, b| a.0.cmp(&b.0));
                entries
                    .into_iter()
                    .filter_map(|(_, v)| if let Value::Scalar(x) = v { Some(x) } else { None })
                    .collect()
            }
        }
    }

    /// `EXPAND(X)` and the like as a statement: the named quantity is replaced by the result.
    fn rewrite_in_place(&mut self, name: &str, args: &[Expr], e: &Expr) -> IResult<()> {
        let v = self.call(name, args, e)?;
        if let Some(ExprKind::Name { name: target, suffix, primes: 0 }) = args.first().map(|a| &a.kind) {
            let key = format!("{}{}", target.to_ascii_uppercase(), ">".repeat(*suffix as usize));
            if matches!(self.bindings.get(&key), Some(Binding::Value(_))) {
                self.bindings.insert(key, Binding::Value(v));
            }
        }
        Ok(())
    }

    /// The rotation by `angle` about the direction of `v` (fixed in `parent`), as direction
    /// cosines `parent_i . child_j = cos a d_ij + (1 - cos a) k_i k_j - sin a e_ijl k_l`.
    fn rotation_about(
        &mut self,
        v: &Vector,
        parent: FrameId,
        angle: ExprId,
        span: &Span,
    ) -> IResult<Orientation> {
        let ar_err = |e: crate::expr::ExprError| Diagnostic::error(span.clone(), e.to_string());
        let c = self.model.express(v, parent).at(span)?;
        let ar = &mut self.model.ar;
        let squares = c.iter().map(|x| ar.powi(*x, 2)).collect::<Result<Vec<_>, _>>().map_err(ar_err)?;
        let norm = ar.add(&squares).map_err(ar_err)?;
        let half = ar.rational(1, 2).map_err(ar_err)?;
        let norm = ar.pow(norm, half).map_err(ar_err)?;
        let k = c.iter().map(|x| ar.div(*x, norm)).collect::<Result<Vec<_>, _>>().map_err(ar_err)?;
        let (cos, sin) = (ar.cos(angle).map_err(ar_err)?, ar.sin(angle).map_err(ar_err)?);
        let one = ar.one();
        let versine = ar.sub(one, cos).map_err(ar_err)?;
        let mut m = [[ar.zero(); 3]; 3];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                let mut terms = vec![ar.mul(&[versine, k[i], k[j]]).map_err(ar_err)?];
                if i == j {
                    terms.push(cos);
                }
                // The cross term: -sin a (k x .)_ij, with (k x)_ij = -e_ijl k_l.
                let l = 3 - i - j;
                if i != j {
                    let sign = if (j + 3 - i) % 3 == 1 { -1 } else { 1 };
                    let s = ar.mul(&[sin, k[l]]).map_err(ar_err)?;
                    terms.push(if sign < 0 { ar.neg(s).map_err(ar_err)? } else { s });
                }
                *cell = ar.add(&terms).map_err(ar_err)?;
            }
        }
        Ok(Orientation::Dcm(m))
    }

    /// The axis of SIMPROT: +/-1..3, or a unit vector of the parent frame.
    fn axis_arg(&mut self, e: &Expr, parent: FrameId) -> IResult<i8> {
        let v = self.eval(e)?;
        let bad = || {
            Diagnostic::error(
                e.span.clone(),
                "SIMPROT's axis must be 1, 2, 3 (or negative), or a unit vector of the first frame",
            )
        };
        match v {
            Value::Scalar(x) => {
                let n = self.model.ar.as_rational(x).and_then(|r| r.as_i64()).ok_or_else(bad)?;
                if (1..=3).contains(&n.abs()) {
                    Ok(n as i8)
                } else {
                    Err(bad())
                }
            }
            Value::Vector(vec) => {
                let terms = vec.terms();
                if terms.len() != 1 || terms[0].0 != parent {
                    return Err(bad());
                }
                let m = terms[0].1;
                for (i, x) in m.iter().enumerate() {
                    let others_zero = (0..3).filter(|j| *j != i).all(|j| self.model.ar.is_zero(m[j]));
                    if others_zero && *x == self.model.ar.one() {
                        return Ok(i as i8 + 1);
                    }
                    if others_zero && *x == self.model.ar.minus_one() {
                        return Ok(-(i as i8 + 1));
                    }
                }
                Err(bad())
            }
            _ => Err(bad()),
        }
    }
}

/// The error for a statement that is one word naming neither a command nor a defined name.
fn unknown_command(name: &str, span: &Span) -> Diagnostic {
    let d = Diagnostic::error(span.clone(), format!("unknown command `{name}`"));
    match super::functions::nearest_command(&name.to_ascii_uppercase()) {
        Some(k) => d.with_help(format!("did you mean `{k}`?")),
        None => d.with_help("a statement is a declaration, an assignment or a command such as KANE()"),
    }
}
