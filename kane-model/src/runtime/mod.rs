//! What generated code reaches, and nothing else: the generated-model traits and metadata
//! ([`GeneratedModel`], [`ModelInfo`]), the Taylor-coefficient recurrences ([`taylor`]), dual
//! numbers ([`dual`]), quaternion helpers and the scalar helpers generated arithmetic calls.
//!
//! A leaf: it uses nothing else in the crate (only `num_traits`), so generated code depends on
//! it alone; the code generator and the evaluators above it use it, never the reverse.

pub mod dual;
mod info;
mod model;
mod quaternion;
pub mod taylor;

pub use info::{ModelInfo, OpCounts, OutputInfo, OutputKind};
pub use model::{GeneratedModel, LaneModel, TaylorWork, TAYLOR_MAX_ORDER, TAYLOR_UNROLLED_ORDERS};
pub use quaternion::quaternion_from_dcm;

/// `x` as `T` (a float type holds every f64 value, or NaN).
pub fn cast<T: num_traits::Float>(x: f64) -> T {
    T::from(x).unwrap_or_else(T::nan)
}

/// The sign of `x`: -1, 0 or 1 (0 for NaN), as generated code and every evaluator compute it.
pub fn sign<T: num_traits::Float>(x: T) -> T {
    if x > T::zero() {
        T::one()
    } else if x < T::zero() {
        -T::one()
    } else {
        T::zero()
    }
}
