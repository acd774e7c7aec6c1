//! Writing a trajectory: in comes a [`Trajectory`] in model units; out go `trajectory.csv` and
//! `trajectory.png` in a folder, with each column in its display unit (angles the model gives
//! in degrees are written in degrees). Units are this module's concern and the plot's only.

use std::path::{Path, PathBuf};

use super::set::Staging;
use super::{
    display_table, write_csv, write_elevation, write_plot, write_trace, write_view, Table, WriteError,
};
use crate::problem::Trajectory;
use crate::scene::ViewSpec;

/// The files written.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    /// The CSV.
    pub csv: PathBuf,
    /// The time-series plot.
    pub plot: PathBuf,
    /// Further figures the trajectory had data for (elevation window, axle-tip trace).
    pub figures: Vec<PathBuf>,
    /// The rows in the CSV.
    pub rows: usize,
}

/// Writes `trajectory` into `dir` (made if missing): the CSV and the plots, as one set.
pub fn write(trajectory: &Trajectory, dir: &Path) -> Result<Written, WriteError> {
    write_set(trajectory, None, dir)
}

/// Writes `trajectory` into `dir` (made if missing): the CSV, the plots and, with `view`, the
/// 3-D view, staged and then put in place together (files of an earlier set this one lacks are
/// removed); on an error the folder keeps its earlier set.
pub fn write_set(
    trajectory: &Trajectory,
    view: Option<&ViewSpec>,
    dir: &Path,
) -> Result<Written, WriteError> {
    let staging = Staging::new(dir)?;
    let table = display_table(trajectory);
    write_csv(&table, &staging.path("trajectory.csv"))?;
    let rows = table.rows.len();
    finish_set(staging, trajectory, &table, view, dir, rows)
}

/// Writes the figures (from `table`, `trajectory` in display units) and the view of
/// `trajectory` beside its staged CSV of `rows` rows, and puts the set in place.
pub(crate) fn finish_set(
    staging: Staging,
    trajectory: &Trajectory,
    table: &Table,
    view: Option<&ViewSpec>,
    dir: &Path,
    rows: usize,
) -> Result<Written, WriteError> {
    if !trajectory.events.names.is_empty() {
        super::events_csv::write_events_csv(trajectory, &staging.path("events.csv"))?;
    }
    write_plot(table, &staging.path("trajectory.png"))?;
    let mut figures = Vec::new();
    if write_elevation(table, &staging.path("elevation.png"))? {
        figures.push(dir.join("elevation.png"));
    }
    if write_trace(table, &staging.path("axle_trace.png"))? {
        figures.push(dir.join("axle_trace.png"));
    }
    if let Some(view) = view {
        write_view(trajectory, view, &staging.path("view.html"))?;
        figures.push(dir.join("view.html"));
    }
    staging.commit()?;
    Ok(Written { csv: dir.join("trajectory.csv"), plot: dir.join("trajectory.png"), figures, rows })
}
