//! The EJS second window: in comes a table with the elevation of the axle and of the angular
//! momentum (`ELEVATION`, `L_ELEVATION`); out goes a PNG of both against time.

use std::path::Path;

use plotters::prelude::*;

use super::super::{Table, WriteError};
use super::panel::{self, Panel};
use super::{draw_atomically, pretty_unit, register_font};

/// Writes the elevation plot when the table has the elevation columns; returns whether it did.
pub fn write_elevation(table: &Table, path: &Path) -> Result<bool, WriteError> {
    let find = |label: &str| table.columns.iter().position(|c| c.label.eq_ignore_ascii_case(label));
    let series: Vec<(String, usize)> = [("axle", "ELEVATION"), ("L", "L_ELEVATION")]
        .iter()
        .filter_map(|(name, label)| find(label).map(|c| (format!("elevation of {name}"), c + 1)))
        .collect();
    if series.is_empty() {
        return Ok(false);
    }
    register_font();
    let unit = pretty_unit(&table.columns[series[0].1 - 1].unit);
    let panel = Panel {
        rows: table.figure_rows(),
        series,
        x_title: "t (s)".to_string(),
        y_title: format!("elevation above the horizontal ({unit})"),
    };
    draw_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (800, 450)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(&table.title, ("sans-serif", 22))?;
        panel::draw(&root, &panel)?;
        Ok(root.present()?)
    })?;
    Ok(true)
}
