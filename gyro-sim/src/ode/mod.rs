//! Ordinary differential equations. In: a [`System`] `y' = f(t, y)`, a start `(t0, y0)` and a
//! [`Method`] (a Butcher tableau from [`tableau`], found by name with [`by_name`]). Out: states
//! step by step from an [`ErkStepper`], or at output times from [`integrate`], with the cost in
//! [`Stats`] or the reason in [`OdeError`].
//!
//! Files: `tableau` the coefficients as data; `methods` the table of methods by name; `stages`
//! one step's stages and error estimate (`stages/unrolled` the compile-time-unrolled steps);
//! `control` step sizes; `dense` the continuous extensions' one evaluation routine; `stepper`
//! the stepper; `integrate` output times on top of it; `events` the same with a watcher of
//! each step (events).

mod control;
mod dense;
mod events;
mod integrate;
mod methods;
mod stages;
mod stepper;
pub mod tableau;

pub(crate) use control::PiControl;
pub use dense::{DenseOutput, DenseRounding};
pub use events::{integrate_watched, Watched};
pub use integrate::{integrate, integrate_limited};
pub use methods::{by_name, default_method, methods_help, Method, MethodInfo, Tolerances, METHODS};
pub(crate) use stages::blended_norm;
pub use stepper::{ErkStepper, Stats, StopReason, DEFAULT_MAX_STEPS};
use thiserror::Error;

/// A system `y' = f(t, y)` of fixed dimension; integrators only call `rhs`.
pub trait System {
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
        /// Where.
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
    /// A slice's length is not the system's dimension (or the stepper's compile-time one).
    #[error("expected {expected} values, got {found}")]
    DimensionMismatch {
        /// The dimension.
        expected: usize,
        /// The length given.
        found: usize,
    },
}
