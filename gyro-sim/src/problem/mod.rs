//! A problem ready to integrate: what [`crate::resolve`](mod@crate::resolve) makes of a scene and
//! [`crate::solve`] integrates, with its model (a [`SharedModel`], found once in the registry)
//! and what solving gives back ([`Trajectory`], [`SolveError`], rows streamed to a
//! [`RowStream`]). Every number is in model units (radians for angles); units return only when
//! results are written.
//!
//! The models floor implements [`SimModel`] once per engine; its `solve` integrates a
//! [`Problem`] of it.

mod event_log;
mod event_spec;
mod model;
mod rows;
mod solve_error;
mod trajectory;

pub use event_log::{Crowded, EventLog, EventRecord, Unsettled};
pub use event_spec::{EventSpec, Rule, Source};
pub use model::{SharedModel, SimModel};
pub(crate) use rows::Rows;
pub use rows::{RowError, RowSink, RowStream, MAX_KEPT_ROWS};
pub use solve_error::SolveError;
pub use trajectory::{Accuracy, Column, Conditioning, Constraints, Trajectory};

use crate::ode::Method;

/// What a column of the trajectory holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pick {
    /// State `i`.
    State(usize),
    /// Output `k` (all its components).
    Output(usize),
}

/// Integrator steps per output row from which figures drawn from the rows alone may miss a
/// motion faster than the rows.
pub const STEPS_PER_ROW_DENSE: f64 = 4.0;

/// One integration to do.
#[derive(Clone, Debug)]
pub struct Problem {
    /// A title for plots.
    pub title: String,
    /// The model, found once in the registry when the scene was resolved.
    pub model: SharedModel,
    /// Parameter values, in `model.info().param_names` order.
    pub params: Vec<f64>,
    /// The initial state at `t = 0`.
    pub initial: Vec<f64>,
    /// Output times, increasing; the last is the final time.
    pub times: Vec<f64>,
    /// Further times, between output times, evaluated only for the figures (drawn from the
    /// dense output; empty when the method has none, since extra stops would change its steps).
    pub plot_times: Vec<f64>,
    /// Whether a run whose figures are written draws them from the dense output when the
    /// integrator stepped four times or more per output row (no plot points
    /// were asked for, and the method has a dense output).
    pub dense_figures: bool,
    /// The method and its tolerances or step.
    pub method: Method,
    /// Most accepted steps of one integration.
    pub max_steps: usize,
    /// The largest error asked of the trajectory (tolerances refined until it is met).
    pub accuracy: Option<f64>,
    /// The columns, in order: the first `written_picks` are written to the CSV and the
    /// figures, the rest only feed the 3-D view.
    pub picks: Vec<Pick>,
    /// How many of `picks` are written.
    pub written_picks: usize,
    /// Groups of states held at unit norm (Euler parameters), as state indices.
    pub unit_norms: Vec<Vec<usize>>,
    /// Events to find (`[[events]]`).
    pub events: Vec<EventSpec>,
    /// The 3-D view (`[view]`), its lengths numbers for these parameter values.
    pub view: Option<crate::scene::ViewSpec>,
}

/// How a model's equations run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Compiled Rust, the integrator inlined with it.
    Compiled,
    /// The lowered program evaluated directly (no compilation).
    Instant,
    /// The lowered program compiled to machine code in process.
    Jit,
}

impl Engine {
    /// Its name in messages (`compiled`, `instant`, `jit`).
    pub fn label(self) -> &'static str {
        match self {
            Engine::Compiled => "compiled",
            Engine::Instant => "instant",
            Engine::Jit => "jit",
        }
    }
}
