//! Display units: in come a trajectory's columns and rows in model units; out go the written
//! columns (hidden ones left out, CSV headers naming name and unit) and rows with each value in
//! its declared unit (a model computes angles and their rates in radians). Units are this module's concern and the figures' only.

use crate::problem::Trajectory;
pub use kane_model::lang::units::column_name;
use kane_model::lang::units::size::shown_per_internal;

/// One column of results.
#[derive(Clone, Debug)]
pub struct Column {
    /// CSV header, name and unit: `q1_deg`.
    pub name: String,
    /// The quantity's name in the model.
    pub label: String,
    /// The unit the values are written in (`DEG` for angles written in degrees).
    pub unit: String,
    /// Values are written in degrees.
    pub degrees: bool,
    /// The quantity is an angle.
    pub angle: bool,
    /// The quantity is a model output (not a state).
    pub output: bool,
}

/// Rows of `t` and the columns.
#[derive(Clone, Debug)]
pub struct Table {
    /// Title for plots.
    pub title: String,
    /// The columns after `t`.
    pub columns: Vec<Column>,
    /// Each row: `t`, then one value per column.
    pub rows: Vec<Vec<f64>>,
    /// Denser rows for figures (empty: draw `rows`).
    pub plot_rows: Vec<Vec<f64>>,
}

impl Table {
    /// The rows figures are drawn from: the dense ones when there are.
    pub fn figure_rows(&self) -> &[Vec<f64>] {
        if self.plot_rows.is_empty() {
            &self.rows
        } else {
            &self.plot_rows
        }
    }
}

/// The trajectory in display units, with CSV headers naming them.
pub fn display_table(trajectory: &Trajectory) -> Table {
    let (display, columns) = DisplayRows::new(&trajectory.columns);
    let display = |rows: &[Vec<f64>]| -> Vec<Vec<f64>> { rows.iter().map(|r| display.row(r)).collect() };
    let (rows, plot_rows) = (display(&trajectory.rows), display(&trajectory.plot_rows));
    Table { title: trajectory.title.clone(), columns, rows, plot_rows }
}

/// How a run's rows (model units, hidden columns too) become written rows: the shown columns,
/// each in its declared unit (angles and their rates the model computes in radians written in
/// degrees, rpm, ... as declared).
pub(crate) struct DisplayRows {
    shown: Vec<usize>,
    scales: Vec<f64>,
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
        let scales = written.iter().map(|c| shown_per_internal(&c.unit)).collect();
        (DisplayRows { shown, scales }, written)
    }

    /// One row in display units: `t`, then the shown columns.
    pub(crate) fn row(&self, row: &[f64]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.shown.len() + 1);
        out.push(row[0]);
        let values = self.shown.iter().map(|k| row[k + 1]).zip(&self.scales);
        out.extend(values.map(|(v, scale)| v * scale));
        out
    }
}
