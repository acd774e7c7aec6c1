//! The models a simulator knows: in come generated models (types implementing
//! [`GeneratedModel`]); out goes a [`Registry`] that finds each by name with its metadata and
//! the solver instantiated for it. A user's crate builds its own with [`Registry::with`].

use std::sync::Arc;

use kane_model::codegen::ProgramModel;
use kane_model::runtime::{GeneratedModel, ModelInfo};

use crate::problem::Problem;
use crate::solve::{solve_model, SolveError};
use crate::trajectory::Trajectory;

/// How a model's equations run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Compiled Rust, the integrator inlined with it.
    Compiled,
    /// The lowered program evaluated directly (no compilation).
    Instant,
}

impl Engine {
    /// Its name in messages (`compiled`, `instant`).
    pub fn label(self) -> &'static str {
        match self {
            Engine::Compiled => "compiled",
            Engine::Instant => "instant",
        }
    }
}

/// Integrates a problem of one model.
pub type SolveFn = Arc<dyn Fn(&Problem) -> Result<Trajectory, SolveError> + Send + Sync>;
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

/// One model: its metadata and what runs it.
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
}

impl ModelEntry {
    /// The entry of `M`.
    pub fn of<M: GeneratedModel + 'static>() -> ModelEntry {
        ModelEntry {
            info: &M::INFO,
            initial_state: Arc::new(M::initial_state),
            default_params: Arc::new(default_params::<M>),
            solve: Arc::new(solve_model::<M>),
            engine: Engine::Compiled,
            program: None,
            source: None,
        }
    }

    /// This entry with its lowered program made, when asked, from `source`, the text of the
    /// model file at `path` it was generated from.
    pub fn with_source(self, path: &'static str, source: &'static str) -> ModelEntry {
        let program = move || {
            let file =
                crate::model_file::ModelFile::from_source(std::path::Path::new(path), source.to_string());
            file.ok().map(|f| f.program)
        };
        ModelEntry { program: Some(ProgramSource(Arc::new(program))), source: Some((path, source)), ..self }
    }
}

fn default_params<M: GeneratedModel>() -> Vec<f64> {
    let p = M::Params::default();
    M::INFO.param_names.iter().map(|n| M::param(&p, n).unwrap_or(f64::NAN)).collect()
}

/// Models by name.
#[derive(Clone, Default)]
pub struct Registry {
    entries: Vec<(String, ModelEntry)>,
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
    pub fn with<M: GeneratedModel + 'static>(self) -> Registry {
        self.with_entry(M::INFO.name, ModelEntry::of::<M>())
    }

    /// This registry with `M` added, with its model file's path and text when it has one.
    pub fn with_entry_of<M: GeneratedModel + 'static>(
        self,
        file: Option<(&'static str, &'static str)>,
    ) -> Registry {
        let entry = ModelEntry::of::<M>();
        let entry = match file {
            Some((path, source)) => entry.with_source(path, source),
            None => entry,
        };
        self.with_entry(M::INFO.name, entry)
    }

    /// This registry with `entry` found under `key` (a model's name, or the model file a
    /// scene names); an earlier entry under the same key is replaced.
    pub fn with_entry(mut self, key: &str, entry: ModelEntry) -> Registry {
        self.entries.retain(|(k, _)| !k.eq_ignore_ascii_case(key));
        self.entries.push((key.to_string(), entry));
        self
    }

    /// The model under `key` (case-insensitive).
    pub fn find(&self, key: &str) -> Option<&ModelEntry> {
        self.entries.iter().find(|(k, _)| k.eq_ignore_ascii_case(key)).map(|(_, e)| e)
    }

    /// The keys of the models.
    pub fn names(&self) -> Vec<&str> {
        self.entries.iter().map(|(k, _)| k.as_str()).collect()
    }
}
