//! The models a simulator knows: in come models (generated model types, model files on an
//! engine); out goes a [`Registry`] that finds each by name as a [`SharedModel`]. A user's crate
//! builds its own with [`Registry::with`].

use kane_model::runtime::GeneratedModel;

use crate::problem::SharedModel;

/// Models by name.
#[derive(Clone, Default)]
pub struct Registry {
    entries: Vec<(String, SharedModel)>,
}

impl Registry {
    /// An empty registry.
    pub fn new() -> Registry {
        Registry::default()
    }

    /// This registry with the generated model `M` added.
    pub fn with<M: GeneratedModel + 'static>(self) -> Registry {
        self.with_entry(M::INFO.name, super::generated::generated::<M>())
    }

    /// This registry with `model` found under `key` (a model's name, or the model file a
    /// scene names); an earlier model under the same key is replaced.
    pub fn with_entry(mut self, key: &str, model: SharedModel) -> Registry {
        self.entries.retain(|(k, _)| !k.eq_ignore_ascii_case(key));
        self.entries.push((key.to_string(), model));
        self
    }

    /// The model under `key` (case-insensitive).
    pub fn find(&self, key: &str) -> Option<&SharedModel> {
        self.entries.iter().find(|(k, _)| k.eq_ignore_ascii_case(key)).map(|(_, e)| e)
    }

    /// The keys of the models.
    pub fn names(&self) -> Vec<&str> {
        self.entries.iter().map(|(k, _)| k.as_str()).collect()
    }
}
