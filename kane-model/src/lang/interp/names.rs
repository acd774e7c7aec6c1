//! Names: Autolev's built-in kinematic quantities (`P_O_P>`, `V_P_A>`, `W_B_A>`, `A_P_A>`,
//! `ALF_B_A>`, `I_B_BO>>`, `FORCE_P>`, `TORQUE_B>`), frame unit vectors (`A1>`), and
//! suggestions for unknown names.
//!
//! In: upper-cased names as written. Out: the entity or built-in quantity a name stands for,
//! its value (or its assignment to the model), or a diagnostic suggesting the nearest name.

use crate::mechanics::{FrameId, PointId, Vector};

use super::super::ast::Expr;
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::sources::KinematicSource;
use super::value::Value;
use super::{entity_key, At, Binding, IResult, Interpreter};

/// A built-in kinematic quantity named in the text.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Builtin {
    Position(PointId, PointId),
    Velocity(PointId, FrameId),
    Acceleration(PointId, FrameId),
    AngularVelocity(FrameId, FrameId),
    AngularAcceleration(FrameId, FrameId),
    Inertia(crate::mechanics::BodyId, PointId),
    ParticleInertia(crate::mechanics::ParticleId, PointId),
    Force(PointId),
    Torque(FrameId),
}

impl Interpreter {
    /// The frame of a frame or body name.
    pub(crate) fn frame_of(&self, key: &str) -> Option<FrameId> {
        match self.bindings.get(&entity_key(key)) {
            Some(Binding::Frame(f)) => Some(*f),
            Some(Binding::Body(b)) => Some(self.model.body(*b).frame),
            _ => None,
        }
    }

    /// Declares the origin point `AO` of each frame `A` (not a body: its `BO` is its mass
    /// centre) that a built-in name such as `P_NO_P>` reads and nothing declared yet; the
    /// Newtonian frame's origin is at rest in it.
    pub(crate) fn frame_origins_in(&mut self, key: &str) {
        for part in key.split('_') {
            let Some(frame_name) = part.strip_suffix('O') else { continue };
            if self.bindings.contains_key(&entity_key(part)) {
                continue;
            }
            let Some(Binding::Frame(f)) = self.bindings.get(&entity_key(frame_name)).cloned() else {
                continue;
            };
            let Ok(p) = self.model.add_point(part) else { continue };
            if f == self.model.newtonian() {
                self.model.set_velocity(p, f, crate::mechanics::Vector::zero());
            }
            self.bindings.insert(entity_key(part), Binding::Point(p));
        }
    }

    /// The point of a point, particle, or body-mass-centre name.
    pub(crate) fn point_of(&self, key: &str) -> Option<PointId> {
        match self.bindings.get(&entity_key(key)) {
            Some(Binding::Point(p)) => Some(*p),
            Some(Binding::Particle(p)) => Some(self.model.particle(*p).point),
            _ => None,
        }
    }

    /// Splits `rest` at an underscore into two names accepted by `first` and `second`.
    fn split2<A, B>(
        &self,
        rest: &str,
        first: impl Fn(&Self, &str) -> Option<A>,
        second: impl Fn(&Self, &str) -> Option<B>,
    ) -> Option<(A, B)> {
        rest.match_indices('_')
            .find_map(|(i, _)| Some((first(self, &rest[..i])?, second(self, &rest[i + 1..])?)))
    }

    /// Resolves an upper-cased vector (`suffix` 1) or dyadic (`suffix` 2) name to a built-in.
    pub(crate) fn builtin(&self, key: &str, suffix: u8) -> Option<Builtin> {
        let (prefix, rest) = key.split_once('_')?;
        let pt = |s: &Self, n: &str| s.point_of(n);
        let fr = |s: &Self, n: &str| s.frame_of(n);
        match (prefix, suffix) {
            ("P", 1) => self.split2(rest, pt, pt).map(|(a, b)| Builtin::Position(a, b)),
            ("V", 1) => self.split2(rest, pt, fr).map(|(a, b)| Builtin::Velocity(a, b)),
            ("A", 1) => self.split2(rest, pt, fr).map(|(a, b)| Builtin::Acceleration(a, b)),
            ("W", 1) => self.split2(rest, fr, fr).map(|(a, b)| Builtin::AngularVelocity(a, b)),
            ("ALF", 1) => self.split2(rest, fr, fr).map(|(a, b)| Builtin::AngularAcceleration(a, b)),
            ("I", 2) => {
                let body = |s: &Self, n: &str| match s.bindings.get(&entity_key(n)) {
                    Some(Binding::Body(b)) => Some(*b),
                    _ => None,
                };
                let particle = |s: &Self, n: &str| match s.bindings.get(&entity_key(n)) {
                    Some(Binding::Particle(p)) => Some(*p),
                    _ => None,
                };
                self.split2(rest, body, pt)
                    .map(|(a, b)| Builtin::Inertia(a, b))
                    .or_else(|| self.split2(rest, particle, pt).map(|(a, b)| Builtin::ParticleInertia(a, b)))
            }
            ("FORCE", 1) => self.point_of(rest).map(Builtin::Force),
            ("TORQUE", 1) => self.frame_of(rest).map(Builtin::Torque),
            _ => None,
        }
    }

    /// The value of a built-in quantity.
    pub(crate) fn builtin_value(&mut self, b: Builtin, span: &Span) -> IResult<Value> {
        let fail: &Span = span;
        Ok(match b {
            Builtin::Position(from, to) => Value::Vector(self.model.position(to, from).at(fail)?),
            Builtin::Velocity(p, f) => {
                self.kinematic_reads.push(p);
                Value::Vector(self.model.velocity(p, f).at(fail)?)
            }
            Builtin::Acceleration(p, f) => {
                self.kinematic_reads.push(p);
                Value::Vector(self.model.acceleration(p, f).at(fail)?)
            }
            Builtin::AngularVelocity(a, b) => Value::Vector(self.model.angular_velocity(a, b).at(fail)?),
            Builtin::AngularAcceleration(a, b) => {
                Value::Vector(self.model.angular_acceleration(a, b).at(fail)?)
            }
            Builtin::Inertia(body, point) => {
                let central = self.model.body(body).inertia.clone().unwrap_or_default();
                let cm = self.model.body(body).mass_center;
                if point == cm {
                    Value::Dyadic(central)
                } else {
                    let m = self.model.body(body).mass.ok_or_else(|| {
                        Diagnostic::error(span.clone(), format!("{} has no mass", self.model.body(body).name))
                    })?;
                    let r = self.model.position(cm, point).at(fail)?;
                    let frame = self.model.body(body).frame;
                    Value::Dyadic(self.model.parallel_axis(&central, m, &r, frame).at(fail)?)
                }
            }
            Builtin::ParticleInertia(p, point) => {
                let part = self.model.particle(p).clone();
                let m = part
                    .mass
                    .ok_or_else(|| Diagnostic::error(span.clone(), format!("{} has no mass", part.name)))?;
                let r = self.model.position(part.point, point).at(fail)?;
                // Written in the frame the position is given in.
                let frame = r.terms().first().map_or(self.model.newtonian(), |t| t.0);
                Value::Dyadic(
                    self.model.parallel_axis(&crate::mechanics::Dyadic::zero(), m, &r, frame).at(fail)?,
                )
            }
            Builtin::Force(p) => {
                Value::Vector(self.force_names.get(&p).map(|i| self.forces[*i].1.clone()).unwrap_or_default())
            }
            Builtin::Torque(f) => Value::Vector(
                self.torque_names.get(&f).map(|i| self.torques[*i].1.clone()).unwrap_or_default(),
            ),
        })
    }

    /// `W_A_N> = w`: A's angular velocity in N where the two are related directly (or not yet
    /// at all); for A oriented through a chain, A turns in its parent so that `W_A_N>` is `w`,
    /// and `w` in speeds implies the chain's kinematic equations, unless the file gives them
    /// itself before the equations are formed (see `prepare`).
    pub(crate) fn assign_angular_velocity(
        &mut self,
        a: FrameId,
        b: FrameId,
        w: &Vector,
        span: &Span,
    ) -> IResult<()> {
        let set = if self.model.frame_parent(a).is_some() && !self.model.frames_related(a, b) {
            self.model.set_angular_velocity_through(a, b, w.clone()).at(span)?;
            self.chain_speeds.push((a, b, w.clone(), span.clone()));
            self.prepared = false;
            a
        } else {
            self.model.set_angular_velocity_in(a, b, w.clone()).at(span)?
        };
        self.sources.angular_velocities.insert(set, span.clone());
        Ok(())
    }

    /// Assigns a built-in quantity; false when `key` names no built-in.
    pub(crate) fn assign_builtin(&mut self, key: &str, suffix: u8, v: &Value, span: &Span) -> IResult<bool> {
        self.frame_origins_in(key);
        let Some(b) = self.builtin(key, suffix) else { return Ok(false) };
        let fail: &Span = span;
        match (b, v) {
            (Builtin::Position(from, to), Value::Vector(r)) => {
                self.model.set_position(to, from, r.clone()).at(fail)?;
                self.sources.position(from, to, span);
            }
            (Builtin::Velocity(p, f), Value::Vector(r)) => {
                self.model.set_velocity(p, f, r.clone());
                let reads = std::mem::take(&mut self.kinematic_reads);
                let source = KinematicSource { span: span.clone(), theorem: None, reads };
                self.sources.velocities.insert((p, f), source);
            }
            (Builtin::Acceleration(p, f), Value::Vector(r)) => {
                self.model.set_acceleration(p, f, r.clone());
                let reads = std::mem::take(&mut self.kinematic_reads);
                let source = KinematicSource { span: span.clone(), theorem: None, reads };
                self.sources.accelerations.insert((p, f), source);
            }
            (Builtin::AngularVelocity(a, b), Value::Vector(w)) => {
                self.assign_angular_velocity(a, b, w, span)?
            }
            (Builtin::Inertia(body, point), Value::Dyadic(d)) => {
                if point != self.model.body(body).mass_center {
                    return Err(Diagnostic::error(
                        span.clone(),
                        "an inertia dyadic is set about the mass centre",
                    )
                    .with_help(format!("write I_{0}_{0}O>> = ...", self.model.body(body).name)));
                }
                self.model.set_inertia(body, d.clone());
                self.sources.inertial.insert(self.model.body(body).name.to_ascii_uppercase(), span.clone());
            }
            // An angular acceleration set by name is a definition, kept as a value.
            (Builtin::AngularAcceleration(..), Value::Vector(_)) => return Ok(false),
            // Assigning a load again adds to it, as SymPy's reading of Autolev does.
            (Builtin::Force(p), Value::Vector(f)) => {
                self.add_to_force(p, f, false, span)?;
                self.record_load(format!("FORCE_{}>", self.model.point_name(p)), span, true);
            }
            (Builtin::Torque(fr), Value::Vector(t)) => {
                self.add_to_torque(fr, t, false, span)?;
                self.record_load(format!("TORQUE_{}>", self.model.frame_name(fr)), span, true);
            }
            (_, other) => {
                return Err(Diagnostic::error(
                    span.clone(),
                    format!(
                        "`{key}{}` needs {}, found {}",
                        ">".repeat(suffix as usize),
                        if suffix == 2 { "a dyadic" } else { "a vector" },
                        other.kind()
                    ),
                )
                .with_help("a vector name (ending in >) needs a vector, a dyadic name (>>) a dyadic"))
            }
        }
        Ok(true)
    }

    /// Sets the resultant force at `p`.
    pub(crate) fn set_force(&mut self, p: PointId, f: Vector) {
        match self.force_names.get(&p) {
            Some(&i) => self.forces[i].1 = f,
            None => {
                self.force_names.insert(p, self.forces.len());
                self.forces.push((p, f));
            }
        }
    }

    /// Sets the resultant torque on the body of `fr`.
    pub(crate) fn set_torque(&mut self, fr: FrameId, t: Vector) {
        match self.torque_names.get(&fr) {
            Some(&i) => self.torques[i].1 = t,
            None => {
                self.torque_names.insert(fr, self.torques.len());
                self.torques.push((fr, t));
            }
        }
    }

    /// `A_B`: the two frames of a direction-cosine-matrix name.
    pub(crate) fn dcm_frames(&self, key: &str) -> Option<(FrameId, FrameId)> {
        self.split2(key, |s, n| s.frame_of(n), |s, n| s.frame_of(n))
    }

    /// `A1>`: unit vector 1 of frame (or body) A.
    pub(crate) fn unit_vector(&self, key: &str) -> Option<Vector> {
        let (frame, axis) = key.split_at(key.len().checked_sub(1)?);
        let axis: usize = axis.parse().ok().filter(|a| (1..=3).contains(a))?;
        let f = self.frame_of(frame)?;
        Some(self.model.unit(f, axis))
    }

    /// An error for an unknown name, suggesting the nearest known one.
    pub(crate) fn unknown(&self, name: &str, suffix: u8, span: &Span) -> Diagnostic {
        let key = name.to_ascii_uppercase();
        let shown = format!("{name}{}", ">".repeat(suffix as usize));
        let nearest = self
            .bindings
            .keys()
            .filter(|k| !k.starts_with('#') && k.ends_with('>') == (suffix > 0))
            .map(|k| (edit_distance(&key, k.trim_end_matches('>')), k))
            .filter(|(d, _)| *d <= 2)
            .min();
        let d = Diagnostic::error(span.clone(), format!("`{shown}` is not defined"));
        match nearest {
            Some((_, k)) => d.with_help(format!("did you mean `{k}`? Names must be declared or assigned before use")),
            None if suffix > 0 => d.with_help(
                "vectors are frame unit vectors (A1>), built-ins (P_O_P>, V_P_N>, W_B_N>, ...) or names assigned earlier",
            ),
            None => d.with_help("declare it (CONSTANTS, VARIABLES, ...) or assign it before using it"),
        }
    }

    /// A whole number from an index expression.
    pub(crate) fn index_value(&mut self, e: &Expr) -> IResult<i64> {
        let v = self.number(e)?;
        if v.fract() == 0.0 {
            Ok(v as i64)
        } else {
            Err(Diagnostic::error(e.span.clone(), format!("an index must be a whole number, not {v}")))
        }
    }
}

/// The word of `known` nearest to `word`, for a did-you-mean: at most two edits away (one when
/// either is four letters or fewer) and fewer edits than its length; case is ignored.
pub fn nearest_word<'a>(word: &str, known: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let upper = word.to_ascii_uppercase();
    known
        .into_iter()
        .map(|k| (edit_distance(&upper, &k.to_ascii_uppercase()), k))
        // Two edits turn short names into unrelated ones (EXIT -> EIG): one for four letters or fewer.
        .filter(|(d, k)| *d <= if upper.len().min(k.len()) <= 4 { 1 } else { 2 } && *d < k.len())
        .min()
        .map(|(_, k)| k)
}

/// Levenshtein distance, for "did you mean" hints.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            cur.push((prev[j] + usize::from(ca != *cb)).min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}
