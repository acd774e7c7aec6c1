//! Rigid-body mechanics and Kane's method on top of [`crate::expr`].
//!
//! A [`Model`] owns the expressions and typed ids of frames, points, bodies and particles.
//! Frames form a tree of orientations; points form a tree of positions; velocities follow from
//! positions by differentiation in a frame. [`Model::kane`] derives `M u' = f` from
//! `Fr + Fr* = 0`.
//!
//! Dependencies run one way: `ids` <- `vector` <- `vector_ops` (algebra over a frame tree) <-
//! the model and the files that add its methods (`algebra`, `frame`, `point`, `derivative`,
//! `loads`, `masses`, `outputs`, `kane`, ...).

mod algebra;
mod auxiliary;
mod constraints;
mod derivative;
mod error;
mod frame;
mod ids;
mod inertia;
mod kane;
mod linearize;
mod loads;
mod masses;
mod model;
mod order_n;
mod outputs;
mod point;
mod rates;
mod symbolic_rates;
mod table;
mod vector;
mod vector_ops;

pub use error::{MechanicsError, Result};
pub use ids::{BodyId, FrameId, Mat3, ParticleId, PointId};
pub use inertia::Shape;
pub use kane::{EquationOps, KaneEquations, SolvedLoads, SpeedConstraints, COLLECT_TERMS_BUDGET};
pub use masses::{MassId, MassView};
pub use model::{Body, Load, Model, Orientation, Particle};
pub use order_n::{ldlt_operations, ORDER_N_FIRST_ABOVE};
pub use rates::{reciprocal_condition, Rates, CONSTRAINT_RCOND_LIMIT};
pub use symbolic_rates::SymbolicRates;
pub use vector::{Dyadic, Vector};
