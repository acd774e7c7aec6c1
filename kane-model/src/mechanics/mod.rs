//! Rigid-body mechanics and Kane's method on top of [`crate::expr`].
//!
//! A [`Model`] owns the expressions and typed ids of frames, points, bodies and particles.
//! Frames form a tree of orientations; points form a tree of positions; velocities follow from
//! positions by differentiation in a frame. [`Model::kane`] derives `M u' = f` from
//! `Fr + Fr* = 0`.

mod constraints;
mod error;
mod frame;
mod inertia;
mod kane;
mod linearize;
mod model;
mod outputs;
mod point;
mod table;
mod vector;
mod vector_ops;

pub use error::{MechanicsError, Result};
pub use inertia::Shape;
pub use kane::KaneEquations;
pub use model::{Body, BodyId, FrameId, Load, Mat3, Model, Orientation, Particle, ParticleId, PointId};
pub use vector::{Dyadic, Vector};
