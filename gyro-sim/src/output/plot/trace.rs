//! The classic cusp / loop / wave figure: in comes a table with the axle's direction in space
//! axes (`AXLE_N1`, `AXLE_N2`, `AXLE_N3`); out goes a PNG of the axle tip's path on the unit
//! sphere seen from above (x, y), with the unit circle (the horizon).

use std::path::Path;

use plotters::prelude::*;

use super::super::{Table, WriteError};
use super::drawable::tick_labels;
use super::{draw_atomically, register_font, COLORS};

/// Writes the tip trace when the table has the axle's direction; returns whether it did.
pub fn write_trace(table: &Table, path: &Path) -> Result<bool, WriteError> {
    let find = |label: &str| table.columns.iter().position(|c| c.label.eq_ignore_ascii_case(label));
    let (Some(x), Some(y), Some(z)) = (find("AXLE_N1"), find("AXLE_N2"), find("AXLE_N3")) else {
        return Ok(false);
    };
    register_font();
    draw_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (600, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(&table.title, ("sans-serif", 20))?;
        let mut chart = ChartBuilder::on(&root)
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(-1.05..1.05, -1.05..1.05)?;
        chart
            .configure_mesh()
            .x_desc("axle tip x (unit sphere, seen from above)")
            .y_desc("axle tip y")
            .x_label_formatter(&tick_labels(-1.05, 1.05))
            .y_label_formatter(&tick_labels(-1.05, 1.05))
            .axis_desc_style(("sans-serif", 15))
            .draw()?;
        let circle = (0..=360).map(|k| {
            let a = f64::from(k).to_radians();
            (a.cos(), a.sin())
        });
        chart.draw_series(LineSeries::new(circle, BLACK.mix(0.4)))?;
        // Above the horizon solid, below it lighter: seen from above both project inside.
        let (above, below) = (COLORS[0].stroke_width(2), COLORS[3].mix(0.6).stroke_width(2));
        for w in table.figure_rows().windows(2) {
            let style = if w[0][z + 1] >= 0.0 { above } else { below };
            let seg = vec![(w[0][x + 1], w[0][y + 1]), (w[1][x + 1], w[1][y + 1])];
            chart.draw_series(LineSeries::new(seg, style))?;
        }
        Ok(root.present()?)
    })?;
    Ok(true)
}
