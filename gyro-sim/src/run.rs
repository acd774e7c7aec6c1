//! A scene end to end: resolve, solve, write. In comes a scene; out go its trajectory and the
//! files written.

use std::path::Path;

use thiserror::Error;

use crate::output::{self, WriteError, Written};
use crate::registry::Registry;
use crate::resolve::resolve;
use crate::scene::{Scene, SceneError};
use crate::solve::{solve, SolveError};
use crate::trajectory::Trajectory;

/// Why a run failed.
#[derive(Debug, Error)]
pub enum RunError {
    /// The scene asks for something the model does not have.
    #[error("{0}")]
    Scene(#[from] SceneError),
    /// The integration stopped.
    #[error("{0}")]
    Solve(#[from] SolveError),
    /// Writing the results failed.
    #[error("{0}")]
    Write(#[from] WriteError),
}

/// What a run made.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// The trajectory, in model units.
    pub trajectory: Trajectory,
    /// The files, when a folder was given.
    pub written: Option<Written>,
}

/// Runs a scene with the built-in models; with `out_dir` the CSV and the plot are written there.
pub fn run(scene: &Scene, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    run_with(scene, &Registry::builtin(), out_dir)
}

/// Runs a scene with the models of `registry`.
pub fn run_with(scene: &Scene, registry: &Registry, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    let problem = resolve(scene, registry)?;
    let trajectory = solve(&problem, registry)?;
    let written = out_dir.map(|dir| output::write_set(&trajectory, scene.view.as_ref(), dir)).transpose()?;
    Ok(RunSummary { trajectory, written })
}
