//! A problem ready to integrate: what [`crate::resolve`](mod@crate::resolve) makes of a scene and
//! [`crate::solve`] integrates, with the model's [`ModelEntry`] (found once in the registry) and
//! what solving gives back ([`Trajectory`], [`SolveError`], rows streamed to a [`RowStream`]).
//! Every number is in model units (radians for angles); units return only when results are
//! written.
//!
//! A [`ModelEntry`] is made by the models floor (`ModelEntry::of` in `models/registry.rs`,
//! `instant_entry` in `models/instant.rs`, `jit_entry` in `models/jit.rs`); its `solve` integrates a [`Problem`] of it.

mod event_log;
mod event_spec;
mod rows;
mod solve_error;
mod trajectory;

pub use event_log::{Crowded, EventLog, EventRecord, Unsettled};
pub use event_spec::{EventSpec, Rule, Source};
pub(crate) use rows::Rows;
pub use rows::{RowError, RowSink, RowStream, MAX_KEPT_ROWS};
pub use solve_error::SolveError;
pub use trajectory::{Accuracy, Column, Conditioning, Constraints, Trajectory};

use std::sync::{Arc, OnceLock};

use kane_model::codegen::ProgramModel;
use kane_model::mechanics::Model;
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
    /// The model, found once in the registry when the scene was resolved: its metadata
    /// (`model.info`), its lowered program when known, and the solver instantiated for it.
    pub model: ModelEntry,
    /// Parameter values, in `model.info.param_names` order.
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

/// Integrates a problem of one model, streaming its rows to the sink when one is given.
pub type SolveFn = Arc<dyn Fn(&Problem, Option<&RowStream>) -> Result<Trajectory, SolveError> + Send + Sync>;
/// A vector a model gives (its initial state, its parameter defaults).
pub type ValuesFn = Arc<dyn Fn() -> Vec<f64> + Send + Sync>;
/// A model's lowered program, made when asked (to name the operation behind a failure).
#[derive(Clone)]
pub struct ProgramSource(pub Arc<dyn Fn() -> Option<Arc<ProgramModel>> + Send + Sync>);

impl ProgramSource {
    /// The program, when it can be made.
    pub fn program(&self) -> Option<Arc<ProgramModel>> {
        (self.0)()
    }
}

impl std::fmt::Debug for ProgramSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("ProgramSource")
    }
}

/// A model's mechanics (bodies, masses, inertias), made once when first asked (to check a
/// run's values for plausibility).
#[derive(Clone)]
pub struct MechanicsSource {
    made: Arc<OnceLock<Option<Arc<Model>>>>,
    make: Arc<dyn Fn() -> Option<Model> + Send + Sync>,
}

impl MechanicsSource {
    /// The mechanics `make` gives (None when it cannot), made on first use.
    pub fn new(make: impl Fn() -> Option<Model> + Send + Sync + 'static) -> MechanicsSource {
        MechanicsSource { made: Arc::new(OnceLock::new()), make: Arc::new(make) }
    }

    /// Mechanics already made.
    pub fn ready(model: Arc<Model>) -> MechanicsSource {
        MechanicsSource { made: Arc::new(OnceLock::from(Some(model))), make: Arc::new(|| None) }
    }

    /// The mechanics, when they can be made.
    pub fn get(&self) -> Option<Arc<Model>> {
        self.made.get_or_init(|| (self.make)().map(Arc::new)).clone()
    }
}

impl std::fmt::Debug for MechanicsSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("MechanicsSource")
    }
}

/// One model: its metadata and what runs it. Resolving a scene finds it in the registry once
/// and the problem carries it; solving calls its `solve`.
#[derive(Clone)]
pub struct ModelEntry {
    /// Names, units, outputs.
    pub info: &'static ModelInfo,
    /// The initial state from the model's INPUT (NaN where none), model units.
    pub initial_state: ValuesFn,
    /// The parameter defaults, in `info.param_names` order (NaN where none).
    pub default_params: ValuesFn,
    /// Integrates a problem of this model.
    pub solve: SolveFn,
    /// How it runs.
    pub engine: Engine,
    /// Its lowered program, the same operations as it runs, when known.
    pub program: Option<ProgramSource>,
    /// The path and text of the model file it was compiled from, for a built-in model.
    pub source: Option<(&'static str, &'static str)>,
    /// Its mechanics, when known: a run's masses and inertias are checked against them.
    pub mechanics: Option<MechanicsSource>,
    /// Its default drawing, when its outputs place its frames and points (a model file loaded
    /// for a view that draws the model).
    pub drawing: Option<Arc<kane_model::spec::Drawing>>,
}

impl ModelEntry {
    /// This entry with its mechanics from `mechanics`.
    pub fn with_mechanics(self, mechanics: MechanicsSource) -> ModelEntry {
        ModelEntry { mechanics: Some(mechanics), ..self }
    }
}

impl std::fmt::Debug for ModelEntry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ModelEntry")
            .field("name", &self.info.name)
            .field("engine", &self.engine)
            .finish_non_exhaustive()
    }
}
