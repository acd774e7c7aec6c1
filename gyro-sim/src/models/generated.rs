//! The compiled engine's model: in comes a generated model type (`kane_derive::model!`, built
//! into gyro-sim, a user's crate or a model file's cached binary); out goes a [`SimModel`] that
//! integrates it with the solver instantiated for it. Its mechanics (every run's plausibility
//! check) and its lowered program (only to name the operation behind a failure), when known,
//! are each made once, the first time they are asked: a run that does not fail never checks
//! and lowers the file.

use std::marker::PhantomData;
use std::path::Path;
use std::sync::{Arc, OnceLock};

use kane_model::mechanics::Model;
use kane_model::program::ProgramModel;
use kane_model::runtime::{GeneratedModel, ModelInfo};

use super::model_file::ModelFile;
use crate::problem::{Engine, Problem, RowStream, SharedModel, SimModel, SolveError, Trajectory};
use crate::solve::solve_model;

/// Where a generated model's mechanics come from.
enum Origin {
    /// Nowhere known.
    Unknown,
    /// The model file it was generated from: its path and text.
    File(&'static str, &'static str),
    /// A function building them (a model built through kane-model's Rust API).
    Mechanics(fn() -> Option<Model>),
}

/// The generated model `M` on the compiled engine.
struct Generated<M> {
    origin: Origin,
    program: OnceLock<Option<Arc<ProgramModel>>>,
    mechanics: OnceLock<Option<Arc<Model>>>,
    model: PhantomData<fn() -> M>,
}

/// `M` on the compiled engine, nothing else known of it.
pub fn generated<M: GeneratedModel + 'static>() -> SharedModel {
    with_origin::<M>(Origin::Unknown)
}

/// `M` on the compiled engine, generated from the model file at `path` whose text is `source`.
pub fn generated_from_file<M: GeneratedModel + 'static>(
    path: &'static str,
    source: &'static str,
) -> SharedModel {
    with_origin::<M>(Origin::File(path, source))
}

/// `M` on the compiled engine, its mechanics built by `mechanics` when first asked.
pub fn generated_with_mechanics<M: GeneratedModel + 'static>(
    mechanics: fn() -> Option<Model>,
) -> SharedModel {
    with_origin::<M>(Origin::Mechanics(mechanics))
}

fn with_origin<M: GeneratedModel + 'static>(origin: Origin) -> SharedModel {
    Arc::new(Generated::<M> {
        origin,
        program: OnceLock::new(),
        mechanics: OnceLock::new(),
        model: PhantomData,
    })
}

impl<M: GeneratedModel + 'static> SimModel for Generated<M> {
    fn info(&self) -> &'static ModelInfo {
        &M::INFO
    }
    fn engine(&self) -> Engine {
        Engine::Compiled
    }
    fn initial_state(&self) -> Vec<f64> {
        M::initial_state()
    }
    fn default_params(&self) -> Vec<f64> {
        let p = M::Params::default();
        M::INFO.param_names.iter().map(|n| M::param(&p, n).unwrap_or(f64::NAN)).collect()
    }
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
        solve_model::<M>(problem, rows_to)
    }
    fn program(&self) -> Option<Arc<ProgramModel>> {
        let Origin::File(path, source) = self.origin else { return None };
        let lowered = || ModelFile::from_source(Path::new(path), source.to_string(), false).ok();
        self.program.get_or_init(|| lowered().map(|f| f.program)).clone()
    }
    fn mechanics(&self) -> Option<Arc<Model>> {
        let loaded = |path: &str, source: &str| kane_model::lang::load_for_generation(path, source).ok();
        let made = || match self.origin {
            Origin::Unknown => None,
            Origin::File(path, source) => loaded(path, source).map(|l| l.model),
            Origin::Mechanics(make) => make(),
        };
        self.mechanics.get_or_init(|| made().map(Arc::new)).clone()
    }
}
