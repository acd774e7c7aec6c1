//! A compiled model run with its model file's values as they are now: the file's INPUT values
//! may have been edited since the binary was built (they do not change its equations).

use std::sync::Arc;

use kane_model::mechanics::Model;
use kane_model::program::ProgramModel;
use kane_model::runtime::ModelInfo;
use kane_model::spec::Drawing;

use crate::problem::{Engine, Problem, RowStream, SharedModel, SimModel, SolveError, Trajectory};

/// `runs` (a compiled model) with the values, program, mechanics and drawing of `current` (the
/// same equations, from the file as it is now).
struct EditedValues {
    runs: SharedModel,
    current: SharedModel,
    params: Vec<f64>,
    initial: Vec<f64>,
}

/// `runs` with its parameter defaults and initial state taken from `current` by name.
pub fn with_values_of(runs: SharedModel, current: SharedModel) -> SharedModel {
    let (info, now) = (runs.info(), current.info());
    let (params, initial) = (current.default_params(), current.initial_state());
    let params = info.param_names.iter().map(|n| now.param(n).map_or(f64::NAN, |i| params[i])).collect();
    let initial = info.state_names.iter().map(|n| now.state(n).map_or(f64::NAN, |i| initial[i])).collect();
    Arc::new(EditedValues { runs, current, params, initial })
}

impl SimModel for EditedValues {
    fn info(&self) -> &'static ModelInfo {
        self.runs.info()
    }
    fn engine(&self) -> Engine {
        self.runs.engine()
    }
    fn initial_state(&self) -> Vec<f64> {
        self.initial.clone()
    }
    fn default_params(&self) -> Vec<f64> {
        self.params.clone()
    }
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
        self.runs.solve(problem, rows_to)
    }
    fn program(&self) -> Option<Arc<ProgramModel>> {
        self.current.program()
    }
    fn mechanics(&self) -> Option<Arc<Model>> {
        self.current.mechanics()
    }
    fn drawing(&self) -> Option<Arc<Drawing>> {
        self.current.drawing()
    }
}
