//! The models a simulator knows: in come generated models (types implementing
//! [`GeneratedModel`]); out goes a [`Registry`] that finds each by name as a [`ModelEntry`]
//! with its metadata and the solver instantiated for it (`ModelEntry::of`, here because it
//! names the generic solver). A user's crate builds its own with [`Registry::with`].

use std::sync::Arc;

use kane_model::runtime::GeneratedModel;

use crate::problem::{Engine, MechanicsSource, ModelEntry, ProgramSource};
use crate::solve::solve_model;

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
            drawing: None,
        }
    }

    /// This entry with its lowered program made, when asked, from `source`, the text of the
    /// model file at `path` it was generated from.
    pub fn with_source(self, path: &'static str, source: &'static str) -> ModelEntry {
        let program = move || {
            let file = super::model_file::ModelFile::from_source(
                std::path::Path::new(path),
                source.to_string(),
                false,
            );
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
