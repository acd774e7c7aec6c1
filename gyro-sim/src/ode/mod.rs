//! Ordinary differential equations: the [`System`] trait, Butcher tableaux as data, and explicit
//! Runge-Kutta integration with error control.

mod erk;
pub mod tableau;

pub use erk::{integrate, Method, Stats, Tolerances};
use thiserror::Error;

/// A system `y' = f(t, y)` of fixed dimension; integrators only call `rhs`.
pub trait System {
    /// Number of states.
    fn dim(&self) -> usize;
    /// Writes `f(t, y)` into `dy`.
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]);
}

/// Why an integration stopped early.
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
    #[error("more than {max} steps before t = {time}")]
    TooManySteps {
        /// Where it stopped.
        time: f64,
        /// The limit.
        max: usize,
    },
    /// The output callback asked to stop with an error.
    #[error("{0}")]
    Output(String),
}
