//! kane-model: a symbolic engine for rigid-body dynamics by Kane's method.
//!
//! - [`expr`]: hash-consed expressions with exact rationals, derivatives, simplification,
//!   CSE, numeric evaluation generic over `num_traits::Float`, and printers.
//! - [`mechanics`]: frames, points, bodies, loads and Kane's equations `M u' = f`.
//! - [`spec`]: what to generate from a model: equations, defaults, units, typed outputs.
//! - [`codegen`]: a spec lowered to one straight-line program, printed as Rust.
//! - [`lang`]: the Autolev-compatible model language, building models and specs.
//! - [`models`]: canonical systems (the paper's gimbal, the heavy top, n-link pendulums).
//! - [`plausibility`]: masses, inertias and Euler parameters checked at given values.
//! - [`dual`]: dual numbers implementing `num_traits::Float`, for exact derivatives.
#![warn(missing_docs)]

pub mod assembly;
pub mod build;
pub mod codegen;
pub mod dual;
pub mod expr;
pub mod lang;
pub mod mechanics;
pub mod models;
pub mod plausibility;
pub mod runtime;
pub mod spec;

/// Runtime helpers named by generated code; not a stable API.
#[doc(hidden)]
pub mod __private {
    pub use num_traits;

    /// The Taylor-coefficient recurrences generated `taylor` functions call.
    pub use crate::codegen::taylor::recur as taylor;

    /// `x` as `T` (a float type holds every f64 value, or NaN).
    pub fn cast<T: num_traits::Float>(x: f64) -> T {
        T::from(x).unwrap_or_else(T::nan)
    }

    /// Sign of `x`: -1, 0 or 1.
    pub fn sign<T: num_traits::Float>(x: T) -> T {
        crate::expr::Func::Sign.apply(x)
    }
}

#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
struct ReadmeDoctests;
