//! kane-model: a symbolic engine for rigid-body dynamics by Kane's method.
//!
//! - [`expr`]: hash-consed expressions with exact rationals, derivatives, simplification,
//!   CSE, numeric evaluation generic over `num_traits::Float`, and printers.
//! - [`mechanics`]: frames, points, bodies, loads and Kane's equations `M u' = f`.
//! - [`spec`]: what to generate from a model: equations, defaults, units, typed outputs.
//! - [`program`]: a spec lowered to one straight-line program, with its evaluator, Taylor
//!   recurrences, events, faults and linearisation.
//! - [`codegen`]: the program printed as Rust.
//! - [`standalone`]: the program as a C, Fortran, MATLAB/Octave or Python program with its own driver.
//! - `jit` (feature `jit`): the program compiled to machine code in process.
//! - [`runtime`]: what generated code reaches (the model traits and metadata, Taylor
//!   recurrences, dual numbers implementing `num_traits::Float`); a leaf.
//! - [`lang`]: the Autolev-compatible model language, building models and specs.
//! - [`models`]: canonical systems (the paper's gimbal, the heavy top, n-link pendulums).
//! - [`plausibility`]: masses, inertias and Euler parameters checked at given values.

pub mod assembly;
pub mod codegen;
pub mod expr;
pub mod generate;
#[cfg(feature = "jit")]
pub mod jit;
pub mod lang;
pub mod mechanics;
pub mod models;
pub mod plausibility;
pub mod program;
pub mod runtime;
pub mod spec;
pub mod standalone;

/// Runtime helpers named by generated code; not a stable API.
#[doc(hidden)]
pub mod __private {
    pub use num_traits;

    /// The Taylor-coefficient recurrences and the scalar helpers generated code calls.
    pub use crate::runtime::{cast, sign, taylor};
}

#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;
