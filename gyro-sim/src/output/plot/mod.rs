//! Plots of a run, PNG: in comes a [`super::Table`] in display units; out go the figures it has data
//! for: the time series like the paper's Figures 3-5 (`series`), the EJS elevation window
//! (`elevation`) and the axle tip's trace seen from above (`trace`). Each is written atomically.

mod drawable;
mod elevation;
mod panel;
mod series;
mod sweep_metric;
mod trace;
mod work_precision_figure;

use std::path::Path;
use std::sync::Once;

use plotters::backend::DrawingBackend;
use plotters::drawing::DrawingAreaErrorKind;
use plotters::prelude::{BitMapBackend, RGBColor};
use plotters::style::FontStyle;
use thiserror::Error;

use super::{write_atomically, WriteError};

pub use elevation::write_elevation;
pub use series::write_plot;
pub use sweep_metric::{write_sweep_metric, MemberPoint, MetricAxes};
pub use trace::write_trace;
pub use work_precision_figure::{write_work_precision, WorkPrecisionPoint};

/// What the drawing library reports when a figure cannot be drawn or encoded.
pub type DrawFailure = DrawingAreaErrorKind<<BitMapBackend<'static> as DrawingBackend>::ErrorType>;

/// Why a figure could not be drawn.
#[derive(Debug, Error)]
#[error("{0}")]
pub struct PlotError(#[from] pub DrawFailure);

/// Draws the figure at `path` through a temporary file (`draw` is given its path) and a rename;
/// a drawing error names `path`.
fn draw_atomically(path: &Path, draw: impl FnOnce(&Path) -> Result<(), PlotError>) -> Result<(), WriteError> {
    write_atomically(path, |tmp| {
        draw(tmp).map_err(|source| WriteError::Plot { path: path.to_path_buf(), source })
    })
}

static FONT: Once = Once::new();

/// DejaVu Sans, embedded (licence in gyro-sim/assets/DejaVuSans-LICENSE.txt).
fn register_font() {
    FONT.call_once(|| {
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            include_bytes!("../../../assets/DejaVuSans.ttf"),
        );
    });
}

const COLORS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
];

/// A unit as a reader writes it: `M/SEC^2` -> `m/s²`, `DEG` -> `deg`, `RAD/SEC` -> `rad/s`.
fn pretty_unit(unit: &str) -> String {
    unit.to_ascii_lowercase().replace("sec", "s").replace("^2", "²").replace("^3", "³").replace('*', "·")
}
