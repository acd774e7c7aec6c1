//! Ordinary differential equations. In: a [`System`] `y' = f(t, y)`, a start `(t0, y0)` and a
//! [`Method`] (a Butcher tableau from [`tableau`], found by name with [`by_name`], or the Taylor
//! method). Out: states step by step from a [`Stepper`] ([`ErkStepper`], [`TaylorStepper`]), or
//! at output times from an [`Integration`], with the cost in [`Stats`] and why it stopped in
//! [`StopReason`], or the reason it failed in [`OdeError`].
//!
//! Files: `tableau` the coefficients as data; `methods` the table of methods by name; `stages`
//! one step's stages and error estimate (`stages/unrolled` the compile-time-unrolled steps);
//! `control` step sizes; `dense` the continuous extensions' one evaluation routine; `stepper`
//! the [`Stepper`] trait, [`StopReason`] and the Runge-Kutta stepper; `taylor` the Taylor
//! method on a system's own Taylor coefficients ([`System::taylor`]); `integration` the builder
//! of a run through output times, watched (events) or not; `drive` its one loop from a stepper
//! to output times; `unit_norm` a system held on unit-norm groups (Euler parameters);
//! `interrupt` the stop signals long loops read; `test_problems` small systems with known
//! solutions for tests and benches.

mod control;
mod dense;
mod drive;
mod integration;
pub(crate) mod interrupt;
mod methods;
mod stages;
mod stepper;
pub mod tableau;
mod taylor;
pub mod test_problems;
mod unit_norm;

pub(crate) use control::PiControl;
pub use dense::DenseOutput;
pub use drive::Outcome;
pub use integration::{Integration, Unwatched};
pub use methods::{
    by_name, for_tolerances, methods_help, Method, MethodInfo, Tolerances, AUTO, METHODS, TAYLOR,
};
pub(crate) use stages::blended_norm;
pub use stages::Stats;
pub use stepper::{ErkStepper, Stepper, StopReason, DEFAULT_MAX_STEPS};
pub use taylor::TaylorStepper;
pub use unit_norm::{normalise, NormDrift, UnitNorm};

pub use kane_model::runtime::TaylorWork;
use thiserror::Error;

/// A system `y' = f(t, y)` of fixed dimension; integrators only call `rhs`.
pub trait System {
    /// The dimension every value of the type has, known when the type is (a generated model's
    /// state count): the built-in tableaux then take steps unrolled for it at compile time.
    /// 0 (the default): general steps only, so no unrolled code is compiled for the type.
    const FIXED_DIM: usize = 0;
    /// A second dimension unrolled as [`System::FIXED_DIM`] is (0: none): a generated model's
    /// state count without its cyclic coordinates, which a run that reads none of them leaves
    /// out ([`crate::Reduced`]).
    const REDUCED_DIM: usize = 0;
    /// Whether steps are unrolled for whatever dimension 1 to 8 a value has (found at run
    /// time), for a type whose dimension is known only then (a JIT-compiled model); false by
    /// default, so no unrolled code is compiled for the type.
    const UNROLL_ANY_DIM: bool = false;
    /// Number of states.
    fn dim(&self) -> usize;
    /// Writes `f(t, y)` into `dy`.
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]);
    /// Moves `y` back onto an invariant manifold when it has drifted too far (before a step);
    /// true when it moved. None by default.
    #[inline(always)]
    fn project(&self, _y: &mut [f64]) -> bool {
        false
    }
    /// The normalised Taylor coefficients of the solution through `(t, y)`, orders `0..=order`,
    /// into `out` (state `i`'s coefficient `k` at `out[i * (order + 1) + k]`, so
    /// `y_i(t + h) = sum_k out[i * (order + 1) + k] h^k`); `work` is scratch. False when the
    /// system has none (the default): the Taylor method needs them.
    #[inline(always)]
    fn taylor(&self, _t: f64, _y: &[f64], _order: usize, _out: &mut [f64], _work: &mut TaylorWork) -> bool {
        false
    }
    /// The orders whose Taylor coefficients the system computes straight-line (faster than the
    /// others); none by default.
    fn taylor_straight_line(&self) -> &[usize] {
        &[]
    }
}

/// Why an integration or a stepper's request failed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum OdeError {
    /// A state became NaN or infinite.
    #[error("state {index} is not finite ({value}) at t = {time}")]
    NonFinite {
        /// The time of the step that produced it.
        time: f64,
        /// Which state.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The step size fell below what the time's precision allows.
    #[error("step size underflow at t = {time} (h = {step:e}): the problem is too stiff or singular for the tolerances")]
    StepSizeUnderflow {
        /// Where it happened.
        time: f64,
        /// The step size.
        step: f64,
    },
    /// More steps than allowed.
    #[error("stopped at t = {time} after {max} steps, the step limit\n  help: raise max_steps under [integrator] (now {max}), or let the method take longer steps: loosen rtol and atol (adaptive methods) or raise step (fixed-step methods), or shorten t_final")]
    TooManySteps {
        /// Where it stopped.
        time: f64,
        /// The limit.
        max: usize,
    },
    /// A lock-step batch was given a method without an error estimate.
    #[error(
        "{method} has no error estimate: batch lanes need an embedded pair (dop853, dopri5, vern7, vern9)"
    )]
    NoErrorEstimate {
        /// The tableau's name.
        method: &'static str,
    },
    /// A value before the end of a step was asked of a method without a continuous extension.
    #[error("{method} has no dense output: only the state at the end of a step is known")]
    NoDenseOutput {
        /// The tableau's name.
        method: &'static str,
    },
    /// A value was asked outside the last step.
    #[error("t = {t} is outside the last step [{start}, {end}]")]
    OutsideStep {
        /// The time asked.
        t: f64,
        /// Where the last step began.
        start: f64,
        /// Where it ended.
        end: f64,
    },
    /// The Taylor method was asked of a system without Taylor coefficients.
    #[error("the taylor method needs the model's Taylor coefficients, and this system has none\n  help: use another method (dop853, vern9), or a model generated by kane-model (its right-hand side has them)")]
    NoTaylorCoefficients,
    /// A Runge-Kutta stepper was given the Taylor method.
    #[error("the taylor method has no Butcher tableau: integrate it with an Integration or a TaylorStepper")]
    NotRungeKutta,
    /// A stop signal arrived (see the `interrupt` module).
    #[error("{by} at t = {time}")]
    Interrupted {
        /// The time reached.
        time: f64,
        /// The signal.
        by: crate::ode::interrupt::Interrupted,
    },
    /// A slice's length is not the system's dimension (or the stepper's compile-time one).
    #[error("expected {expected} values, got {found}")]
    DimensionMismatch {
        /// The dimension.
        expected: usize,
        /// The length given.
        found: usize,
    },
}
