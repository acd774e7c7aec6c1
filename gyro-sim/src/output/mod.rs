//! Results: in comes a trajectory; out go a CSV and a plot in display units, never
//! half-written, and put in place as one set (see `set`).

mod csv_file;
mod events_csv;
mod plot;
mod set;
mod streamed;
mod view;
mod write;

pub use csv_file::write_csv;
pub use plot::{
    write_elevation, write_plot, write_sweep_metric, write_trace, write_work_precision, MemberPoint,
    MetricAxes, WorkPrecisionPoint,
};
pub(crate) use set::{is_temporary_of, unique_temporary};
pub use streamed::StreamedSet;
pub use view::write_view;
pub(crate) use view::{page_html, script_json, view_data};
pub use write::{column_name, display_table, write, write_set, WriteError, Written};

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

/// Writes `path` through a temporary file in the same folder, named for this process and call,
/// and a rename.
pub(crate) fn write_atomically(
    path: &std::path::Path,
    write: impl FnOnce(&std::path::Path) -> Result<(), String>,
) -> Result<(), String> {
    // The temporary keeps the real extension last: encoders choose the format from it.
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("output");
    let tmp = path.with_file_name(set::unique_temporary(name));
    let result =
        write(&tmp).and_then(|_| std::fs::rename(&tmp, path).map_err(|e| format!("{}: {e}", path.display())));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
