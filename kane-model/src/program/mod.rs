//! The lowered program: in comes a [`ModelSpec`](crate::spec::ModelSpec) (built from mechanics, never from the
//! language); out goes one [`ir::Program`] of SSA sections (`param_constants`, `rhs` with
//! `M u' = f` and the constraint solves inside it, each output), and what runs or reads it
//! without printing code: the evaluator ([`ProgramModel`]), Taylor-coefficient recurrences
//! ([`taylor`]), event functions ([`event`]), the operation behind a failure ([`fault`]) and
//! linearisation ([`linearize`]). The Rust printer (`codegen`) and the JIT (`jit`) consume it.
//!
//! The crate's layers, in the order data flows through them: `expr` -> `mechanics` -> `spec` ->
//! `program` (this module) -> {`codegen`, `jit`}, with [`crate::runtime`] the leaf that
//! generated code reaches. The model language, `lang`, sits above them all and is never read
//! here: event expressions arrive as expressions ([`event::lower`]), specs as specs.

pub mod event;
pub mod fault;
pub mod ir;
pub mod linearize;
mod lower;
mod meta;
mod program_model;
pub mod taylor;

use thiserror::Error;

pub use lower::{lower, Lowered};
pub use meta::{Meta, OutputMeta};
pub use program_model::ProgramModel;

/// Why a model cannot be lowered to a program.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum LowerError {
    /// A symbol the equations need is neither a state, a parameter nor time.
    #[error("`{0}` is a time-dependent quantity that is not a state and has no formula: give it one in the file (`{0} = ...`, after KANE() too) or in a gyro-sim scene's [specified] table; tables of values in time are not supported")]
    UnsupportedSymbol(String),
    /// An expression operation failed.
    #[error(transparent)]
    Expr(#[from] crate::expr::ExprError),
    /// A mechanics operation failed.
    #[error(transparent)]
    Mechanics(#[from] crate::mechanics::MechanicsError),
}
