//! The model: frames, points, bodies, particles, loads and generalized coordinates and speeds,
//! all typed indices into one [`Model`] that owns the expression arena.
//!
//! In: names, masses and inertias, coordinates, speeds and kinematic equations. Out: the
//! registry of entities and the time derivative under the kinematic equations. It builds on the
//! ids and vector types only; frames, points, loads, masses and the equations add their methods
//! from their own files.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, SymbolId, SymbolKind, TimeDerivative};

use super::error::{MechanicsError, Result};
use super::ids::{BodyId, FrameId, Mat3, ParticleId, PointId};
use super::vector::{Dyadic, Vector};

/// How a frame is oriented relative to its parent.
#[derive(Clone, Debug, PartialEq)]
pub enum Orientation {
    /// Simple rotation by `angle` about the parent's axis `axis` (1, 2, 3; negative for the
    /// negative of that axis), as Autolev's SIMPROT.
    Axis {
        /// +/-1, +/-2 or +/-3.
        axis: i8,
        /// The angle.
        angle: ExprId,
    },
    /// Three successive rotations about the axes of the rotating frame (for example BODY123).
    BodyFixed {
        /// The axes, each 1, 2 or 3.
        axes: [u8; 3],
        /// The angles.
        angles: [ExprId; 3],
    },
    /// Three successive rotations about the parent's fixed axes (for example SPACE123).
    SpaceFixed {
        /// The axes, each 1, 2 or 3.
        axes: [u8; 3],
        /// The angles.
        angles: [ExprId; 3],
    },
    /// Euler parameters `(e0, e1, e2, e3)`, scalar first, mapping child to parent components.
    EulerParameters([ExprId; 4]),
    /// Rodrigues parameters `tan(angle/2)` times the rotation axis, mapping child to parent
    /// components.
    Rodrigues([ExprId; 3]),
    /// A direction-cosine matrix with entries `parent_i . child_j`.
    Dcm(Mat3),
}

#[derive(Clone, Debug)]
pub(crate) struct Frame {
    pub(crate) name: String,
    pub(crate) parent: Option<FrameId>,
    pub(crate) orientation: Option<Orientation>,
    /// Angular velocity relative to the parent, when set explicitly.
    pub(crate) ang_vel: Option<Vector>,
}

#[derive(Clone, Debug)]
pub(crate) struct Point {
    pub(crate) name: String,
    /// Position from another point.
    pub(crate) position: Option<(PointId, Vector)>,
    pub(crate) velocity: FxHashMap<FrameId, Vector>,
    pub(crate) acceleration: FxHashMap<FrameId, Vector>,
}

/// A rigid body: a frame, a mass centre, a mass and a central inertia dyadic.
#[derive(Clone, Debug)]
pub struct Body {
    /// Name (the body's frame has the same name).
    pub name: String,
    /// Frame fixed in the body.
    pub frame: FrameId,
    /// Mass centre.
    pub mass_center: PointId,
    /// The body's mass, once given.
    pub mass: Option<ExprId>,
    /// Inertia dyadic about the mass centre.
    pub inertia: Option<Dyadic>,
}

/// A particle: a point with a mass.
#[derive(Clone, Debug)]
pub struct Particle {
    /// The particle's name as declared.
    pub name: String,
    /// Where it is.
    pub point: PointId,
    /// The particle's mass, once given.
    pub mass: Option<ExprId>,
}

/// An applied load.
#[derive(Clone, Debug, PartialEq)]
pub enum Load {
    /// A force applied at a point.
    Force {
        /// Point of application.
        point: PointId,
        /// The force.
        force: Vector,
    },
    /// A torque (couple) applied to the body fixed in a frame.
    Torque {
        /// The frame of the body acted on.
        frame: FrameId,
        /// The torque.
        torque: Vector,
    },
}

/// Velocities and accelerations derived from positions, valid for the current kinematics.
#[derive(Clone, Debug, Default)]
pub(crate) struct KinematicsCache {
    pub(crate) velocity: FxHashMap<(PointId, FrameId), Vector>,
    pub(crate) acceleration: FxHashMap<(PointId, FrameId), Vector>,
    /// Partial velocities of a vector (its terms) with respect to the speeds listed.
    pub(crate) partials: FxHashMap<PartialsKey, Vec<Vector>>,
}

/// A vector's terms and the speeds its partial velocities are taken with respect to.
pub(crate) type PartialsKey = (Vec<(FrameId, [ExprId; 3])>, Vec<SymbolId>);

/// Nonholonomic constraints `A_d u_d + A_i u_i + b = 0`, kept as their coefficients: the
/// dependent speeds are solved numerically wherever the equations are evaluated.
#[derive(Clone, Debug)]
pub(crate) struct MotionConstraints {
    /// The dependent speeds `u_d`.
    pub(crate) dependent: Vec<SymbolId>,
    /// The constraints, each `= 0`, with the kinematic equations applied.
    pub(crate) residuals: Vec<ExprId>,
    /// `A_d`, one row per constraint.
    pub(crate) a_dependent: Vec<Vec<ExprId>>,
    /// `A_i`, one row per constraint, a column per independent speed.
    pub(crate) a_independent: Vec<Vec<ExprId>>,
    /// `b`.
    pub(crate) b: Vec<ExprId>,
}

/// Auxiliary speeds (zero in every motion; their equations bring loads into evidence) and the
/// unknown loads solved from them.
#[derive(Clone, Debug, Default)]
pub(crate) struct Auxiliary {
    pub(crate) speeds: Vec<SymbolId>,
    pub(crate) loads: Vec<SymbolId>,
}

/// A multibody model: owner of the expressions and of every frame, point, body and load.
pub struct Model {
    /// The expressions of the model.
    pub ar: Arena,
    pub(crate) newtonian: FrameId,
    pub(crate) frames: Vec<Frame>,
    pub(crate) points: Vec<Point>,
    pub(crate) bodies: Vec<Body>,
    pub(crate) particles: Vec<Particle>,
    pub(crate) loads: Vec<Load>,
    pub(crate) coordinates: Vec<SymbolId>,
    pub(crate) speeds: Vec<SymbolId>,
    pub(crate) kinematics: FxHashMap<SymbolId, ExprId>,
    pub(crate) time_derivative: TimeDerivative,
    pub(crate) dcm_cache: FxHashMap<(FrameId, FrameId), Mat3>,
    pub(crate) ang_vel_cache: FxHashMap<(FrameId, FrameId), Vector>,
    pub(crate) kinematics_cache: KinematicsCache,
    pub(crate) constraints: Option<MotionConstraints>,
    pub(crate) configuration_constraints: Vec<ExprId>,
    /// Auxiliary speeds and the loads their equations determine (KANE's arguments).
    pub(crate) auxiliary: Auxiliary,
    /// Position relations `(from, to, r)`, for position queries along the shortest chain.
    pub(crate) position_edges: Vec<(PointId, PointId, Vector)>,
    frame_names: FxHashMap<String, FrameId>,
    point_names: FxHashMap<String, PointId>,
}

impl Model {
    /// A model whose Newtonian frame is named `newtonian`.
    pub fn new(newtonian: &str) -> Model {
        Model {
            ar: Arena::new(),
            newtonian: FrameId(0),
            frames: vec![Frame {
                name: newtonian.to_string(),
                parent: None,
                orientation: None,
                ang_vel: None,
            }],
            points: Vec::new(),
            bodies: Vec::new(),
            particles: Vec::new(),
            loads: Vec::new(),
            coordinates: Vec::new(),
            speeds: Vec::new(),
            kinematics: FxHashMap::default(),
            time_derivative: TimeDerivative::new(),
            dcm_cache: FxHashMap::default(),
            ang_vel_cache: FxHashMap::default(),
            kinematics_cache: KinematicsCache::default(),
            constraints: None,
            configuration_constraints: Vec::new(),
            auxiliary: Auxiliary::default(),
            position_edges: Vec::new(),
            frame_names: [(newtonian.to_string(), FrameId(0))].into_iter().collect(),
            point_names: FxHashMap::default(),
        }
    }

    /// The Newtonian frame.
    pub fn newtonian(&self) -> FrameId {
        self.newtonian
    }

    /// Renames the Newtonian frame (a model file may declare it after other frames).
    pub fn rename_newtonian(&mut self, name: &str) -> Result<()> {
        if self.frame_names.contains_key(name) {
            return Err(MechanicsError::Duplicate(name.to_string()));
        }
        let old = std::mem::replace(&mut self.frames[0].name, name.to_string());
        self.frame_names.remove(&old);
        self.frame_names.insert(name.to_string(), self.newtonian);
        Ok(())
    }

    /// A new frame, not yet oriented.
    pub fn add_frame(&mut self, name: &str) -> Result<FrameId> {
        if self.frame_names.contains_key(name) {
            return Err(MechanicsError::Duplicate(name.to_string()));
        }
        let id = FrameId(self.frames.len() as u32);
        self.frames.push(Frame { name: name.to_string(), parent: None, orientation: None, ang_vel: None });
        self.frame_names.insert(name.to_string(), id);
        Ok(id)
    }

    /// A new point, not yet located.
    pub fn add_point(&mut self, name: &str) -> Result<PointId> {
        if self.point_names.contains_key(name) {
            return Err(MechanicsError::Duplicate(name.to_string()));
        }
        let id = PointId(self.points.len() as u32);
        self.points.push(Point {
            name: name.to_string(),
            position: None,
            velocity: FxHashMap::default(),
            acceleration: FxHashMap::default(),
        });
        self.point_names.insert(name.to_string(), id);
        Ok(id)
    }

    /// A rigid body `name` with a frame `name` and a mass centre `name` + "O".
    pub fn add_body(&mut self, name: &str) -> Result<BodyId> {
        let frame = self.add_frame(name)?;
        let mass_center = self.add_point(&format!("{name}O"))?;
        let id = BodyId(self.bodies.len() as u32);
        self.bodies.push(Body { name: name.to_string(), frame, mass_center, mass: None, inertia: None });
        Ok(id)
    }

    /// A particle `name` at a new point of the same name.
    pub fn add_particle(&mut self, name: &str) -> Result<ParticleId> {
        let point = self.add_point(name)?;
        let id = ParticleId(self.particles.len() as u32);
        self.particles.push(Particle { name: name.to_string(), point, mass: None });
        Ok(id)
    }

    /// The frame named `name`.
    pub fn frame(&self, name: &str) -> Option<FrameId> {
        self.frame_names.get(name).copied()
    }

    /// The point named `name`.
    pub fn point(&self, name: &str) -> Option<PointId> {
        self.point_names.get(name).copied()
    }

    /// The name of a frame.
    pub fn frame_name(&self, f: FrameId) -> &str {
        &self.frames[f.index()].name
    }

    /// The name of a point.
    pub fn point_name(&self, p: PointId) -> &str {
        &self.points[p.index()].name
    }

    /// A body.
    pub fn body(&self, b: BodyId) -> &Body {
        &self.bodies[b.index()]
    }

    /// All bodies.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// A particle.
    pub fn particle(&self, p: ParticleId) -> &Particle {
        &self.particles[p.index()]
    }

    /// Sets a body's mass.
    pub fn set_mass(&mut self, b: BodyId, mass: ExprId) {
        self.bodies[b.index()].mass = Some(mass);
    }

    /// Sets a particle's mass.
    pub fn set_particle_mass(&mut self, p: ParticleId, mass: ExprId) {
        self.particles[p.index()].mass = Some(mass);
    }

    /// Sets a body's inertia dyadic about its mass centre.
    pub fn set_inertia(&mut self, b: BodyId, inertia: Dyadic) {
        self.bodies[b.index()].inertia = Some(inertia);
    }

    /// Declares generalized coordinates (time-dependent variables).
    pub fn set_coordinates(&mut self, q: &[ExprId]) -> Result<()> {
        self.coordinates = self.variables(q)?;
        Ok(())
    }

    /// Declares generalized speeds (time-dependent variables).
    pub fn set_speeds(&mut self, u: &[ExprId]) -> Result<()> {
        self.speeds = self.variables(u)?;
        Ok(())
    }

    fn variables(&self, v: &[ExprId]) -> Result<Vec<SymbolId>> {
        v.iter()
            .map(|&e| match self.ar.as_symbol(e) {
                Some(s) if matches!(self.ar.symbol_info(s).kind, SymbolKind::Variable { .. }) => Ok(s),
                _ => Err(MechanicsError::NotAVariable(self.ar.to_text(e))),
            })
            .collect()
    }

    /// The generalized coordinates.
    pub fn coordinates(&self) -> &[SymbolId] {
        &self.coordinates
    }

    /// The generalized speeds.
    pub fn speeds(&self) -> &[SymbolId] {
        &self.speeds
    }

    /// Sets the kinematic differential equation `q' = rhs`.
    pub fn set_kinematics(&mut self, q: ExprId, rhs: ExprId) -> Result<()> {
        let s = self.variables(&[q])?[0];
        // q' = q' (a coordinate whose own derivative is its speed) needs no rule.
        if self.ar.as_symbol(rhs).is_some_and(|r| self.ar.derivative_symbol(s).ok() == Some(r)) {
            self.kinematics.insert(s, rhs);
            return Ok(());
        }
        self.kinematics.insert(s, rhs);
        self.time_derivative.set_rule(s, rhs);
        self.clear_kinematics_caches();
        Ok(())
    }

    /// The variables given a kinematic equation `q' = ...`, whether coordinates of the
    /// equations or not.
    pub fn coordinates_with_kinematics(&self) -> Vec<SymbolId> {
        self.kinematics.keys().copied().collect()
    }

    /// The right-hand side of `q' = ...` for coordinate `q`.
    pub fn kinematics(&self, q: SymbolId) -> Option<ExprId> {
        self.kinematics.get(&q).copied()
    }

    pub(crate) fn clear_kinematics_caches(&mut self) {
        self.ang_vel_cache.clear();
        self.kinematics_cache = KinematicsCache::default();
    }

    /// The total time derivative of `e` under the kinematic differential equations.
    pub fn dt(&mut self, e: ExprId) -> Result<ExprId> {
        Ok(self.time_derivative.dt(&mut self.ar, e)?)
    }
}
