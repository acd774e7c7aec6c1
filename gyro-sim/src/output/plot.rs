//! A PNG like the paper's Figures 3-5: angles against time on the left, other outputs (such as
//! |a_P|) on the right.

use std::path::Path;
use std::sync::Once;

use plotters::prelude::*;

use super::{write_atomically, Table};

static FONT: Once = Once::new();

/// DejaVu Sans, embedded (licence in gyro-sim/assets/DejaVuSans-LICENSE.txt).
fn register_font() {
    FONT.call_once(|| {
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            include_bytes!("../../assets/DejaVuSans.ttf"),
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

/// Writes the plot of `table` to `path` (atomically).
pub fn write_plot(table: &Table, path: &Path) -> Result<(), String> {
    register_font();
    let left: Vec<usize> = (0..table.columns.len()).filter(|i| table.columns[*i].angle).collect();
    // The paper's layout: angles on the left, outputs such as |a_P| on the right (speeds only
    // when there is no output).
    let mut right: Vec<usize> = (0..table.columns.len()).filter(|i| table.columns[*i].output).collect();
    if right.is_empty() {
        right = (0..table.columns.len()).filter(|i| !table.columns[*i].angle).collect();
    }
    let panels: Vec<Vec<usize>> = [left, right].into_iter().filter(|p| !p.is_empty()).collect();
    write_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (600 * panels.len().max(1) as u32, 450)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let root = root.titled(&table.title, ("sans-serif", 22)).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((1, panels.len().max(1)));
        let t_end = table.rows.last().map_or(1.0, |r| r[0]);
        for (area, cols) in areas.iter().zip(&panels) {
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for r in &table.rows {
                for c in cols {
                    lo = lo.min(r[c + 1]);
                    hi = hi.max(r[c + 1]);
                }
            }
            // A (nearly) constant series gets a visible range instead of magnified round-off.
            let scale = lo.abs().max(hi.abs()).max(1e-300);
            if hi - lo <= 1e-9 * scale || (hi - lo).is_nan() {
                let mid = 0.5 * (lo + hi);
                let half = if mid == 0.0 { 1.0 } else { 0.05 * mid.abs() };
                (lo, hi) = (mid - half, mid + half);
            }
            let pad = 0.05 * (hi - lo);
            let mut chart = ChartBuilder::on(area)
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(70)
                .build_cartesian_2d(0.0..t_end, (lo - pad)..(hi + pad))
                .map_err(|e| e.to_string())?;
            let y_desc = cols.iter().map(|c| table.columns[*c].name.as_str()).collect::<Vec<_>>().join(", ");
            chart.configure_mesh().x_desc("t (s)").y_desc(y_desc).draw().map_err(|e| e.to_string())?;
            for (k, c) in cols.iter().enumerate() {
                let color = COLORS[k % COLORS.len()];
                chart
                    .draw_series(LineSeries::new(
                        table.rows.iter().map(|r| (r[0], r[c + 1])),
                        color.stroke_width(2),
                    ))
                    .map_err(|e| e.to_string())?
                    .label(table.columns[*c].name.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| e.to_string())?;
        }
        root.present().map_err(|e| e.to_string())
    })
}
