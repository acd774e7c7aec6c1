//! A scene end to end: resolve, solve, write. In comes a scene; out go its trajectory and the
//! files written.

use std::path::Path;

use thiserror::Error;

use crate::models::Registry;
use crate::output::{self, WriteError, Written};
use crate::problem::{Problem, SolveError, Trajectory, STEPS_PER_ROW_DENSE};
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
    match solve(problem, Some(&set.stream())).and_then(|t| with_dense_figures(problem, t)) {
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

/// `trajectory` with figures from the dense output where `problem` leaves that to the run and
/// the integrator stepped several times per output row: the run again (the same steps), its
/// rows kept and about four plot points per step added between them.
fn with_dense_figures(problem: &Problem, mut trajectory: Trajectory) -> Result<Trajectory, SolveError> {
    let intervals = problem.times.len().saturating_sub(1);
    let per_row = trajectory.stats.steps as f64 / intervals.max(1) as f64;
    if !problem.dense_figures
        || !trajectory.plot_rows.is_empty()
        || intervals == 0
        || per_row < STEPS_PER_ROW_DENSE
    {
        return Ok(trajectory);
    }
    let per_interval = ((4.0 * per_row).ceil() as usize).min(1000);
    let plot_times = crate::scene::plot_times(&problem.times, per_interval, crate::resolve::MAX_PLOT_POINTS);
    let dense = Problem { plot_times, dense_figures: false, ..problem.clone() };
    trajectory.plot_rows = solve(&dense, None)?.plot_rows;
    Ok(trajectory)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run_in_folder(extra: &str, name: &str) -> Trajectory {
        let text = format!("model = \"gimbal_gyroscope\"\nt_final = 2.0\noutput_step = 0.5\n{extra}");
        let scene = Scene::parse("dense.toml", &text).unwrap();
        let dir = std::env::temp_dir().join(format!("gyro-sim-dense-{}-{name}", std::process::id()));
        let summary = run(&scene, Some(&dir)).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        summary.trajectory
    }

    #[test]
    fn figures_come_from_the_dense_output_when_the_steps_outnumber_the_rows() {
        let dense = run_in_folder("", "auto");
        assert!(dense.stats.steps >= 4 * 4, "{} steps", dense.stats.steps);
        assert!(dense.plot_rows.len() >= 4 * dense.stats.steps, "{} plot rows", dense.plot_rows.len());
        assert!(dense.plot_rows.windows(2).all(|w| w[0][0] < w[1][0]));
        // The rows are among the plot rows: the same steps.
        for row in &dense.rows {
            assert!(dense.plot_rows.contains(row), "row at t = {}", row[0]);
        }
        let rows_only = run_in_folder("plot_points = 1\n", "rows");
        assert!(rows_only.plot_rows.is_empty() && rows_only.rows == dense.rows);
    }
}
