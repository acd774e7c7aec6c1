//! Why a model file cannot be run: the model file's own errors, a scene's, and an error at a line
//! of a generated scene told at its [`Origin`] (kept as data, with the error as it came).

use std::path::PathBuf;

use thiserror::Error;

use super::origins::Origin;
use crate::models::ModelFileError;
use crate::scene::SceneError;

/// Why a model file's run cannot start.
#[derive(Debug, Error)]
pub enum ModelRunError {
    /// The model file cannot be read, checked or lowered.
    #[error(transparent)]
    ModelFile(#[from] ModelFileError),
    /// The model file's program cannot be compiled by the JIT engine.
    #[error(transparent)]
    Jit(#[from] kane_model::jit::JitError),
    /// The user's scene is wrong, at a line and column.
    #[error(transparent)]
    Scene(Box<SceneError>),
    /// A line of the generated scene is wrong: told at what the user gave.
    #[error("{}: error: {}\n  help: {}", origin.describe(file), error.message, error.help)]
    AtOrigin {
        /// The model file.
        file: PathBuf,
        /// What the line came from.
        origin: Origin,
        /// The error at the generated scene's line.
        error: Box<SceneError>,
    },
    /// A `--set` names neither a parameter nor a state of the model.
    #[error("--set {name}: {model} has no parameter or state `{name}`\n  help: parameters: {}; states: {}", params.join(", "), states.join(", "))]
    UnknownSet {
        /// The name given.
        name: String,
        /// The model.
        model: String,
        /// Its parameters.
        params: Vec<String>,
        /// Its states.
        states: Vec<String>,
    },
}
