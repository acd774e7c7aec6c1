//! Commands: SIMPROT, V2PTS and friends, GRAVITY, FORCE/TORQUE, CONSTRAIN, SOLVE, KANE.

use crate::expr::{ExprId, SymbolId, SymbolKind};
use crate::mechanics::Orientation;

use super::super::ast::{BinOp, Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{At, Binding, IResult, Interpreter};

impl Interpreter {
    /// A statement that is a bare expression: a command, or a value shown by Autolev.
    pub(crate) fn command(&mut self, e: &Expr) -> IResult<()> {
        let ExprKind::Call { name, args } = &e.kind else {
            self.eval(e)?;
            return Ok(());
        };
        let upper = name.to_ascii_uppercase();
        let fail: &Span = &e.span;
        let arity = |n: usize| super::arity(&upper, args, n, &e.span);
        match upper.as_str() {
            "SIMPROT" => {
                arity(4)?;
                let parent = self.frame_arg(&args[0])?;
                let child = self.frame_arg(&args[1])?;
                let axis = self.axis_arg(&args[2], parent)?;
                let mut angle = self.scalar(&args[3])?;
                if self.degrees && self.model.ar.free_symbols(&[angle]).is_empty() {
                    // With DEGREES ON a numeric angle is in degrees.
                    let k = self.model.ar.float(std::f64::consts::PI / 180.0).at(fail)?;
                    angle = self.model.ar.mul(&[k, angle]).at(fail)?;
                }
                self.model.orient(child, parent, Orientation::Axis { axis, angle }).at(fail)
            }
            "V2PTS" | "A2PTS" | "V1PT" | "A1PT" => {
                arity(4)?;
                let frame = self.frame_arg(&args[0])?;
                let body = self.frame_arg(&args[1])?;
                let from = self.point_arg(&args[2])?;
                let to = self.point_arg(&args[3])?;
                match upper.as_str() {
                    "V2PTS" => self.model.v2pts(frame, body, from, to),
                    "A2PTS" => self.model.a2pts(frame, body, from, to),
                    "V1PT" => self.model.v1pt(frame, body, from, to),
                    _ => self.model.a1pt(frame, body, from, to),
                }
                .map(|_| ())
                .at(fail)
            }
            "ANGVEL" => {
                arity(2)?;
                let a = self.frame_arg(&args[0])?;
                let b = self.frame_arg(&args[1])?;
                self.model.angular_velocity(a, b).map(|_| ()).at(fail)
            }
            "GRAVITY" => {
                arity(1)?;
                self.gravity = Some(self.vector(&args[0])?);
                self.prepared = false;
                Ok(())
            }
            "FORCE" | "TORQUE" => {
                arity(2)?;
                let v = self.vector(&args[1])?;
                let (on, from) = match &args[0].kind {
                    ExprKind::Binary(BinOp::Div, a, b) => (b.as_ref(), Some(a.as_ref())),
                    _ => (&args[0], None),
                };
                self.prepared = false;
                if upper == "FORCE" {
                    let p = self.point_arg(on)?;
                    let prev =
                        self.force_names.get(&p).map(|i| self.forces[*i].1.clone()).unwrap_or_default();
                    let sum = self.model.add_vectors(&prev, &v).at(fail)?;
                    self.set_force(p, sum);
                    if let Some(from) = from {
                        let q = self.point_arg(from)?;
                        let prev =
                            self.force_names.get(&q).map(|i| self.forces[*i].1.clone()).unwrap_or_default();
                        let diff = self.model.sub_vectors(&prev, &v).at(fail)?;
                        self.set_force(q, diff);
                    }
                } else {
                    let f = self.frame_arg(on)?;
                    let prev =
                        self.torque_names.get(&f).map(|i| self.torques[*i].1.clone()).unwrap_or_default();
                    let sum = self.model.add_vectors(&prev, &v).at(fail)?;
                    self.set_torque(f, sum);
                    if let Some(from) = from {
                        let g = self.frame_arg(from)?;
                        let prev =
                            self.torque_names.get(&g).map(|i| self.torques[*i].1.clone()).unwrap_or_default();
                        let diff = self.model.sub_vectors(&prev, &v).at(fail)?;
                        self.set_torque(g, diff);
                    }
                }
                Ok(())
            }
            "CONSTRAIN" => {
                arity(1)?;
                let ExprKind::Index { name, args: speeds } = &args[0].kind else {
                    return Err(Diagnostic::error(
                        args[0].span.clone(),
                        "CONSTRAIN takes DEPENDENT[u1, ...]",
                    ));
                };
                if !name.eq_ignore_ascii_case("DEPENDENT") {
                    return Err(Diagnostic::error(
                        args[0].span.clone(),
                        format!("CONSTRAIN({name}[...]) is not supported"),
                    )
                    .with_help(
                        "write the constraints as DEPENDENT[i] = ... and call CONSTRAIN(DEPENDENT[u...])",
                    ));
                }
                let mut dep = Vec::new();
                for s in speeds {
                    dep.push(self.scalar(s)?);
                }
                self.dependent_speeds = dep;
                self.prepared = false;
                Ok(())
            }
            "SOLVE" => {
                if args.len() < 2 {
                    return Err(Diagnostic::error(e.span.clone(), "SOLVE takes (EQN, X, Y, ...)"));
                }
                let ExprKind::Name { name: arr, .. } = &args[0].kind else {
                    return Err(Diagnostic::error(
                        args[0].span.clone(),
                        "SOLVE takes the name of an equation array",
                    ));
                };
                // The equations: an array EQN[1], EQN[2], ... or a column such as ZERO.
                let eqs: Vec<ExprId> = match self.lookup_value(&arr.to_ascii_uppercase()) {
                    Some(Value::Matrix { data, .. }) => data,
                    Some(Value::Scalar(x)) => vec![x],
                    _ => {
                        let mut entries =
                            self.arrays.get(&arr.to_ascii_uppercase()).cloned().unwrap_or_default();
                        entries.sort_by(|a, b| a.0.cmp(&b.0));
                        entries
                            .into_iter()
                            .filter_map(|(_, v)| if let Value::Scalar(x) = v { Some(x) } else { None })
                            .collect()
                    }
                };
                let mut names = Vec::new();
                let mut syms = Vec::new();
                for a in &args[1..] {
                    let ExprKind::Name { name, primes, .. } = &a.kind else {
                        return Err(Diagnostic::error(a.span.clone(), "SOLVE takes unknowns by name"));
                    };
                    let x = self.scalar(a)?;
                    syms.push(
                        self.model.ar.as_symbol(x).ok_or_else(|| {
                            Diagnostic::error(a.span.clone(), "an unknown must be a symbol")
                        })?,
                    );
                    names.push(format!("{}{}", name.to_ascii_uppercase(), "'".repeat(*primes as usize)));
                }
                let sol = self.model.ar.solve_linear(&eqs, &syms).at(fail)?;
                for (n, x) in names.into_iter().zip(sol) {
                    self.solved.insert(n, x);
                }
                Ok(())
            }
            "DIRCOS" => self.dircos(args, &e.span),
            "KINDIFFS" => self.kindiffs(args, &e.span),
            // UNITSYSTEM and ENCODE choose how Autolev prints; results are unchanged.
            "UNITSYSTEM" | "ENCODE" => Ok(()),
            "KANE" => {
                self.prepare(&e.span)?;
                let eqs = self.model.kane().at(fail)?;
                self.equations = Some(eqs);
                Ok(())
            }
            "EXPAND" | "FACTOR" | "ARRANGE" | "EXPLICIT" => {
                // As a statement, the named quantity is replaced by the result.
                let v = self.call(name, args, e)?;
                if let Some(ExprKind::Name { name: target, suffix, primes: 0 }) =
                    args.first().map(|a| &a.kind)
                {
                    let key = format!("{}{}", target.to_ascii_uppercase(), ">".repeat(*suffix as usize));
                    if matches!(self.bindings.get(&key), Some(Binding::Value(_))) {
                        self.bindings.insert(key, Binding::Value(v));
                    }
                }
                Ok(())
            }
            _ => {
                self.call(name, args, e)?;
                Ok(())
            }
        }
    }

    /// The axis of SIMPROT: +/-1..3, or a unit vector of the parent frame.
    fn axis_arg(&mut self, e: &Expr, parent: crate::mechanics::FrameId) -> IResult<i8> {
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

    /// Applies the loads and decides the generalized coordinates and speeds (once per change).
    pub(crate) fn prepare(&mut self, span: &Span) -> IResult<()> {
        if self.prepared {
            return Ok(());
        }
        let fail: &Span = span;
        self.model.clear_loads();
        for (p, f) in self.forces.clone() {
            self.model.add_force(p, f);
        }
        for (fr, t) in self.torques.clone() {
            self.model.add_torque(fr, t);
        }
        if let Some(g) = self.gravity.clone() {
            let with_mass: Vec<(ExprId, crate::mechanics::PointId)> =
                self.model.bodies().iter().filter_map(|b| b.mass.map(|m| (m, b.mass_center))).collect();
            for (m, p) in with_mass {
                let f = self.model.scale(&g, m).at(fail)?;
                self.model.add_force(p, f);
            }
            for (_, b) in self.bindings.clone() {
                if let Binding::Particle(p) = b {
                    let part = self.model.particle(p).clone();
                    if let Some(m) = part.mass {
                        let f = self.model.scale(&g, m).at(fail)?;
                        self.model.add_force(part.point, f);
                    }
                }
            }
        }
        // Coordinates: variables with a kinematic equation, and variables declared to second
        // order without one (their speed is their derivative). Speeds: first-order variables
        // that are not coordinates.
        let declared: Vec<(SymbolId, u8)> = {
            let mut v: Vec<(SymbolId, u8)> = self
                .bindings
                .values()
                .filter_map(|b| match b {
                    Binding::Symbol(e, order) => self.model.ar.as_symbol(*e).map(|s| (s, *order)),
                    _ => None,
                })
                .filter(|(s, _)| {
                    matches!(self.model.ar.symbol_info(*s).kind, SymbolKind::Variable { order: 0 })
                })
                .collect();
            v.sort();
            v
        };
        let ruled: Vec<SymbolId> = self.kinematic.iter().map(|(q, _)| *q).collect();
        let mut coords = Vec::new();
        let mut speeds = Vec::new();
        for (s, order) in &declared {
            if ruled.contains(s) {
                coords.push(*s);
            } else if *order >= 2 {
                coords.push(*s);
                let d = self.model.ar.derivative_symbol(*s).at(fail)?;
                speeds.push(d);
                let (q, qd) = (self.model.ar.symbol_expr(*s), self.model.ar.symbol_expr(d));
                self.model.set_kinematics(q, qd).at(fail)?;
            } else if *order == 1 {
                speeds.push(*s);
            }
        }
        // Speeds that are kinematic right-hand sides come first in declaration order already.
        let q: Vec<ExprId> = coords.iter().map(|s| self.model.ar.symbol_expr(*s)).collect();
        let u: Vec<ExprId> = speeds.iter().map(|s| self.model.ar.symbol_expr(*s)).collect();
        self.model.set_coordinates(&q).at(fail)?;
        self.model.set_speeds(&u).at(fail)?;
        if !self.dependent.is_empty() || !self.dependent_speeds.is_empty() {
            let (c, d) = (self.dependent.clone(), self.dependent_speeds.clone());
            self.model.set_motion_constraints(&c, &d).at(fail)?;
        }
        self.prepared = true;
        Ok(())
    }
}
