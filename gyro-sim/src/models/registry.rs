//! The models a simulator knows: in come generated models (types implementing
//! [`GeneratedModel`]); out goes a [`Registry`] that finds each by name with its metadata and
//! the solver instantiated for it. A user's crate builds its own with [`Registry::with`].

use std::sync::{Arc, OnceLock};

use kane_model::codegen::ProgramModel;
use kane_model::mechanics::Model;
use kane_model::runtime::{GeneratedModel, ModelInfo};

use crate::problem::Problem;
use crate::problem::Trajectory;
use crate::solve::{solve_model, SolveError};

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
    /// Its mechanics, when known: a run's masses and inertias are checked against them.
    pub mechanics: Option<MechanicsSource>,
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
            mechanics: None,
        }
    }

    /// This entry with its mechanics from `mechanics`.
    pub fn with_mechanics(self, mechanics: MechanicsSource) -> ModelEntry {
        ModelEntry { mechanics: Some(mechanics), ..self }
    }

    /// This entry with its lowered program made, when asked, from `source`, the text of the
    /// model file at `path` it was generated from.
    pub fn with_source(self, path: &'static str, source: &'static str) -> ModelEntry {
        let program = move || {
            let file =
                super::model_file::ModelFile::from_source(std::path::Path::new(path), source.to_string());
            file.ok().map(|f| f.program)
        };
        let mechanics = move || kane_model::lang::load_for_generation(path, source).ok().map(|l| l.model);
        ModelEntry {
            program: Some(ProgramSource(Arc::new(program))),
            source: Some((path, source)),
            mechanics: Some(MechanicsSource::new(mechanics)),
            ..self
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
    entries: Vec<(String, ModelEntry)>,
}

impl Registry {
    /// An empty registry.
    pub fn new() -> Registry {
        Registry::default()
    }

    /// The models compiled into gyro-sim.
    pub fn builtin() -> Registry {
        super::builtin::register(Registry::new())
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
