//! What a model is to the simulator: the [`SimModel`] trait (its metadata, values and solver,
//! and what else is known of it) and the [`SharedModel`] handle a problem carries. Each engine
//! implements it once, in `models/`; a model file with its own values wraps another.

use std::sync::Arc;

use kane_model::mechanics::Model;
use kane_model::program::ProgramModel;
use kane_model::runtime::ModelInfo;
use kane_model::spec::Drawing;

use super::{Engine, Problem, RowStream, SolveError, Trajectory};

/// A model the simulator runs. Required: its metadata, engine, values and solver; optional
/// (None by default): its lowered program, mechanics and drawing.
pub trait SimModel: Send + Sync {
    /// Names, units, outputs.
    fn info(&self) -> &'static ModelInfo;
    /// How it runs.
    fn engine(&self) -> Engine;
    /// The initial state from the model's INPUT (NaN where none), model units.
    fn initial_state(&self) -> Vec<f64>;
    /// The parameter defaults, in `info().param_names` order (NaN where none).
    fn default_params(&self) -> Vec<f64>;
    /// Integrates a problem of this model, streaming its rows to `rows_to` when given.
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError>;
    /// Its lowered program, the same operations as it runs (to name the operation behind a
    /// failure).
    fn program(&self) -> Option<Arc<ProgramModel>> {
        None
    }
    /// Its mechanics: a run's masses and inertias are checked against them.
    fn mechanics(&self) -> Option<Arc<Model>> {
        None
    }
    /// Its default drawing, when its outputs place its frames and points.
    fn drawing(&self) -> Option<Arc<Drawing>> {
        None
    }
}

/// One shared handle to a model: what a registry finds and a problem carries.
pub type SharedModel = Arc<dyn SimModel>;

impl std::fmt::Debug for dyn SimModel + '_ {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SimModel")
            .field("name", &self.info().name)
            .field("engine", &self.engine())
            .finish_non_exhaustive()
    }
}
