//! Why an integration failed: the error solving a problem gives, each variant with the time,
//! the state or the operation that says where, and what to do.

use thiserror::Error;

use crate::ode::OdeError;

/// Why an integration failed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SolveError {
    /// A state became NaN or infinite.
    #[error("integration failed: state {name} is not finite ({value}) at t = {time}; the last good state, at t = {last_time}: {last_state}")]
    NonFiniteState {
        /// The state.
        name: String,
        /// When it happened.
        time: f64,
        /// Its value.
        value: f64,
        /// The time of the last state written (or the start).
        last_time: f64,
        /// That state, `NAME = value unit, ...`.
        last_state: String,
    },
    /// The motion constraints' matrix of dependent speeds is (nearly) singular.
    #[error("integration failed: the motion constraints lose rank at t = {time}, {configuration}: their matrix of dependent speeds has reciprocal condition number {rcond:e}, so the dependent speeds are not determined there\n  help: choose other dependent speeds in CONSTRAIN, or keep the motion away from this configuration")]
    ConstraintRankLoss {
        /// When it happened.
        time: f64,
        /// The coordinates, `Q1 = 0 deg, ...`.
        configuration: String,
        /// `A_d`'s smallest over largest singular value (NaN when an entry is not finite).
        rcond: f64,
    },
    /// The mass matrix of the speeds is singular or indefinite (a zero or negative mass or
    /// inertia, or bodies that lose a degree of freedom in this configuration).
    #[error("integration failed: mass matrix {} at t = {time}, {configuration}: its pivot for {speed} is {pivot:e}, not positive\n  help: check for zero or negative masses and inertias (parameters), or start away from this configuration (a gimbal at lock with massless gimbals)", if *pivot < 0.0 { "indefinite" } else { "singular" })]
    SingularMassMatrix {
        /// When it happened.
        time: f64,
        /// The coordinates, `Q1 = 0 deg, ...`.
        configuration: String,
        /// The speed whose pivot is not positive.
        speed: String,
        /// The pivot (zero, negative or not finite).
        pivot: f64,
    },
    /// A rate is NaN or infinite (an overflow when infinite) at a finite state.
    #[error("integration failed: the rate of {name} is {value} at t = {time}: {} at the state {state}\n  help: check the parameters and initial values for extreme magnitudes, and the model's expressions where they divide, take roots or logarithms", operation.as_deref().unwrap_or("an operation outside its domain (a division by zero, a root or logarithm of a negative number) or an overflow in the equations"))]
    RateNotFinite {
        /// The state whose rate it is.
        name: String,
        /// When it happened.
        time: f64,
        /// The rate.
        value: f64,
        /// The state, `NAME = value unit, ...`.
        state: String,
        /// The operation that made it, when the model's program is known.
        operation: Option<String>,
    },
    /// The step size collapsed where the equations approach a singularity.
    #[error("integration failed: the equations approach a singularity at t = {time}: {operation}; the step size collapsed there, at the state {state}\n  help: keep the motion away from where this divisor vanishes (parameters, initial values), or stop the run before it with an event")]
    NearSingularity {
        /// When it happened.
        time: f64,
        /// The state, `NAME = value unit, ...`.
        state: String,
        /// The quotient whose divisor nearly vanishes.
        operation: String,
    },
    /// A state or rate so large that the next steps overflow.
    #[error("integration failed: overflow: {name} is {value:e} at t = {time}, beyond what double precision can step (about 1e150)\n  help: scale the model's units or lower the initial values")]
    Overflow {
        /// The state, or the state whose rate it is (`W1'`).
        name: String,
        /// When it happened.
        time: f64,
        /// Its value.
        value: f64,
    },
    /// Writing a row as it was produced failed.
    #[error("integration stopped: writing a row failed: {0}")]
    Rows(#[source] crate::problem::RowError),
    /// An output became NaN or infinite.
    #[error("integration failed: {name} is not finite ({value}) at t = {time}")]
    NonFiniteOutput {
        /// The output column.
        name: String,
        /// When it happened.
        time: f64,
        /// Its value.
        value: f64,
    },
    /// The integrator stopped.
    #[error("integration failed: {0}")]
    Ode(#[from] OdeError),
    /// The initial state cannot be brought onto the configuration constraints.
    #[error("cannot start: {0}")]
    Assembly(#[from] kane_model::assembly::AssemblyError),
    /// Refining the tolerances could not reach the asked accuracy.
    #[error("integration failed: accuracy {goal:e} not reached: runs at rtol {rtol:e} and below still differ by more; ask a looser accuracy")]
    AccuracyNotReached {
        /// The accuracy asked.
        goal: f64,
        /// The finest relative tolerance tried.
        rtol: f64,
    },
}
