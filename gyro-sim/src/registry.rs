//! The models a simulator knows: in come generated models (types implementing
//! [`GeneratedModel`]); out goes a [`Registry`] that finds each by name with its metadata and
//! the solver instantiated for it. A user's crate builds its own with [`Registry::with`].

use kane_model::runtime::{GeneratedModel, ModelInfo};

use crate::problem::Problem;
use crate::solve::{solve_model, SolveError};
use crate::trajectory::Trajectory;

/// One model: its metadata and what runs it.
#[derive(Clone, Copy)]
pub struct ModelEntry {
    /// Names, units, outputs.
    pub info: &'static ModelInfo,
    /// The initial state from the model's INPUT (NaN where none), model units.
    pub initial_state: fn() -> Vec<f64>,
    /// The parameter defaults, in `info.param_names` order (NaN where none).
    pub default_params: fn() -> Vec<f64>,
    /// Integrates a problem of this model.
    pub solve: fn(&Problem) -> Result<Trajectory, SolveError>,
}

impl ModelEntry {
    /// The entry of `M`.
    pub fn of<M: GeneratedModel>() -> ModelEntry {
        ModelEntry {
            info: &M::INFO,
            initial_state: M::initial_state,
            default_params: default_params::<M>,
            solve: solve_model::<M>,
        }
    }
}

fn default_params<M: GeneratedModel>() -> Vec<f64> {
    let p = M::Params::default();
    M::INFO.param_names.iter().map(|n| M::param(&p, n).unwrap_or(f64::NAN)).collect()
}

/// Models by name.
#[derive(Clone, Default)]
pub struct Registry {
    entries: Vec<ModelEntry>,
}

impl Registry {
    /// An empty registry.
    pub fn new() -> Registry {
        Registry::default()
    }

    /// The models compiled into gyro-sim.
    pub fn builtin() -> Registry {
        crate::models::register(Registry::new())
    }

    /// This registry with `M` added.
    pub fn with<M: GeneratedModel>(mut self) -> Registry {
        self.entries.push(ModelEntry::of::<M>());
        self
    }

    /// The model named `name` (case-insensitive).
    pub fn find(&self, name: &str) -> Option<&ModelEntry> {
        self.entries.iter().find(|e| e.info.name.eq_ignore_ascii_case(name))
    }

    /// The names of the models.
    pub fn names(&self) -> Vec<&'static str> {
        self.entries.iter().map(|e| e.info.name).collect()
    }
}
