//! A problem ready to integrate: what [`crate::resolve`] makes of a scene and
//! [`crate::solve`] integrates. Every number is in model units (radians for angles); units
//! return only when results are written.

mod event_log;
mod event_spec;
mod rows;
mod trajectory;

pub use event_log::{Crowded, EventLog, EventRecord, Unsettled};
pub use event_spec::{EventSpec, Rule, Source};
pub(crate) use rows::Rows;
pub use rows::{RowSink, RowStream, MAX_KEPT_ROWS};
pub use trajectory::{Accuracy, Column, Conditioning, Constraints, Trajectory};

use kane_model::runtime::ModelInfo;

use crate::ode::Method;

/// What a column of the trajectory holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pick {
    /// State `i`.
    State(usize),
    /// Output `k` (all its components).
    Output(usize),
}

/// One integration to do.
#[derive(Clone, Debug)]
pub struct Problem {
    /// A title for plots.
    pub title: String,
    /// The model.
    pub model: &'static ModelInfo,
    /// Where the registry has it (its name, or the model file a scene names).
    pub model_key: String,
    /// Parameter values, in `model.param_names` order.
    pub params: Vec<f64>,
    /// The initial state at `t = 0`.
    pub initial: Vec<f64>,
    /// Output times, increasing; the last is the final time.
    pub times: Vec<f64>,
    /// Further times, between output times, evaluated only for the figures (drawn from the
    /// dense output; empty when the method has none, since extra stops would change its steps).
    pub plot_times: Vec<f64>,
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
    /// Where the rows go as they are produced (then only a bounded set stays in memory); none:
    /// every row is kept. Leave it none when an accuracy is asked: refinement compares runs.
    pub rows_to: Option<RowStream>,
    /// The model's lowered program, to name the operation behind a failure (when known).
    pub program: Option<crate::models::ProgramSource>,
}
