//! kane-model: a symbolic engine for rigid-body dynamics by Kane's method.
//!
//! - [`expr`]: hash-consed expressions with exact rationals, derivatives, simplification,
//!   CSE, numeric evaluation generic over `num_traits::Float`, and printers.
#![warn(missing_docs)]

pub mod expr;

/// Runtime helpers named by generated code; not a stable API.
#[doc(hidden)]
pub mod __private {
    /// Sign of `x`: -1, 0 or 1.
    pub fn sign<T: num_traits::Float>(x: T) -> T {
        crate::expr::Func::Sign.apply(x)
    }
}
