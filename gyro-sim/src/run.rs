//! A scene end to end: resolve, solve, write. In comes a scene; out go its trajectory and the
//! files written.

use std::path::Path;

use thiserror::Error;

use crate::models::Registry;
use crate::output::{self, WriteError, Written};
use crate::problem::{Problem, SolveError, Trajectory};
use crate::resolve::resolve;
use crate::scene::{Scene, SceneError};
use crate::solve::solve;

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
    /// The integration stopped after some rows were written: they are kept, marked partial.
    #[error("{error}\n  rows computed before it: {rows}, in {} (partial; the folder's earlier results are unchanged)", path.display())]
    Partial {
        /// Why it stopped.
        error: SolveError,
        /// The partial CSV.
        path: std::path::PathBuf,
        /// Its rows.
        rows: usize,
    },
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

/// Runs a scene with the models of `registry`. With `out_dir` (and no accuracy asked) rows are
/// written as they are produced and the trajectory keeps a bounded, thinned set of them (see
/// `RowStream`); a run that fails after some rows keeps them as `trajectory.partial.csv`.
pub fn run_with(scene: &Scene, registry: &Registry, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    run_problem(&resolve(scene, registry)?, out_dir)
}

/// Runs a resolved problem, written to `out_dir` as [`run_with`] writes it.
pub fn run_problem(problem: &Problem, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    let Some(dir) = out_dir else {
        return Ok(RunSummary { trajectory: solve(problem, None)?, written: None });
    };
    if problem.accuracy.is_some() {
        // Refinement compares whole runs in memory; the run chosen is written at the end.
        let trajectory = solve(problem, None)?;
        let written = output::write_set(&trajectory, problem.view.as_ref(), dir)?;
        return Ok(RunSummary { trajectory, written: Some(written) });
    }
    let set = output::StreamedSet::begin(dir, &crate::solve::columns(problem))?;
    match solve(problem, Some(&set.stream())) {
        Ok(trajectory) => {
            let written = set.finish(&trajectory, problem.view.as_ref())?;
            Ok(RunSummary { trajectory, written: Some(written) })
        }
        Err(error) => match set.keep_partial()? {
            Some((path, rows)) => Err(RunError::Partial { error, path, rows }),
            None => Err(error.into()),
        },
    }
}
