//! Writing a trajectory: in comes a [`Trajectory`] in model units; out go `trajectory.csv` and
//! `trajectory.png` in a folder, with each column in its display unit (angles the model gives
//! in degrees are written in degrees). Units are this module's concern and the plot's only.

use std::path::{Path, PathBuf};

use thiserror::Error;

use super::set::Staging;
use super::{write_csv, write_elevation, write_plot, write_trace, write_view, Column, Table};
use crate::problem::Trajectory;
use crate::scene::ViewSpec;

/// Why results could not be written.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum WriteError {
    /// The folder could not be made.
    #[error("{path}: {message}")]
    Folder {
        /// The folder.
        path: PathBuf,
        /// What the system said.
        message: String,
    },
    /// A file could not be written.
    #[error("{0}")]
    File(String),
}

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
    let folder = |message: String| WriteError::Folder { path: dir.to_path_buf(), message };
    let staging = Staging::new(dir).map_err(folder)?;
    let table = display_table(trajectory);
    write_csv(&table, &staging.path("trajectory.csv")).map_err(WriteError::File)?;
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
        super::events_csv::write_events_csv(trajectory, &staging.path("events.csv"))
            .map_err(WriteError::File)?;
    }
    write_plot(table, &staging.path("trajectory.png")).map_err(WriteError::File)?;
    let mut figures = Vec::new();
    if write_elevation(table, &staging.path("elevation.png")).map_err(WriteError::File)? {
        figures.push(dir.join("elevation.png"));
    }
    if write_trace(table, &staging.path("axle_trace.png")).map_err(WriteError::File)? {
        figures.push(dir.join("axle_trace.png"));
    }
    if let Some(view) = view {
        write_view(trajectory, view, &staging.path("view.html"))?;
        figures.push(dir.join("view.html"));
    }
    staging.commit().map_err(WriteError::File)?;
    Ok(Written { csv: dir.join("trajectory.csv"), plot: dir.join("trajectory.png"), figures, rows })
}

/// The trajectory in display units, with CSV headers naming them.
pub fn display_table(trajectory: &Trajectory) -> Table {
    let (display, columns) = DisplayRows::new(&trajectory.columns);
    let display = |rows: &[Vec<f64>]| -> Vec<Vec<f64>> { rows.iter().map(|r| display.row(r)).collect() };
    let (rows, plot_rows) = (display(&trajectory.rows), display(&trajectory.plot_rows));
    Table { title: trajectory.title.clone(), columns, rows, plot_rows }
}

/// How a run's rows (model units, hidden columns too) become written rows: the shown columns,
/// angles the model gives in degrees written in degrees.
pub(crate) struct DisplayRows {
    shown: Vec<usize>,
    degrees: Vec<bool>,
}

impl DisplayRows {
    /// The mapping for a run's `columns`, and the written columns.
    pub(crate) fn new(columns: &[crate::problem::Column]) -> (DisplayRows, Vec<Column>) {
        let shown: Vec<usize> = (0..columns.len()).filter(|k| !columns[*k].hidden).collect();
        let written: Vec<Column> = shown
            .iter()
            .map(|k| &columns[*k])
            .map(|c| Column {
                name: column_name(&c.name, &c.unit),
                label: c.name.clone(),
                unit: c.unit.clone(),
                degrees: c.unit.eq_ignore_ascii_case("DEG"),
                angle: c.is_angle(),
                output: c.output,
            })
            .collect();
        let degrees = written.iter().map(|c| c.degrees).collect();
        (DisplayRows { shown, degrees }, written)
    }

    /// One row in display units: `t`, then the shown columns.
    pub(crate) fn row(&self, row: &[f64]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.shown.len() + 1);
        out.push(row[0]);
        let values = self.shown.iter().map(|k| row[k + 1]).zip(&self.degrees);
        out.extend(values.map(|(v, d)| if *d { v.to_degrees() } else { v }));
        out
    }
}

/// `q1` + `DEG` -> `q1_deg`; `AP` + `M/SEC^2` -> `ap_m_per_s2`.
pub fn column_name(name: &str, unit: &str) -> String {
    let slug = unit
        .to_ascii_lowercase()
        .replace("sec", "s")
        .replace('/', "_per_")
        .replace(['^', ' '], "")
        .replace('*', "_");
    if slug.is_empty() {
        name.to_ascii_lowercase()
    } else {
        format!("{}_{slug}", name.to_ascii_lowercase())
    }
}
