//! One panel: in come rows, the series to draw (column, colour) and axis titles; out goes a
//! chart on a drawing area with its legend in a strip to the right of the data, never over it.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::drawable::{clip, clipped, line_width, padded_range, tick_labels, DRAWABLE};
use super::{PlotError, COLORS};

/// What one panel shows.
pub(super) struct Panel<'a> {
    /// Rows: `t` (or x) first.
    pub rows: &'a [Vec<f64>],
    /// Each series: its legend label and the index in a row.
    pub series: Vec<(String, usize)>,
    /// The x-axis title.
    pub x_title: String,
    /// The y-axis title.
    pub y_title: String,
}

/// The range of the series (see [`padded_range`]).
fn y_range(panel: &Panel<'_>) -> (f64, f64) {
    padded_range(panel.rows.iter().flat_map(|r| panel.series.iter().map(|(_, c)| r[*c])))
}

/// Draws `panel` on `area`: the chart on the left, the legend in a strip on the right.
pub(super) fn draw(area: &DrawingArea<BitMapBackend<'_>, Shift>, panel: &Panel<'_>) -> Result<(), PlotError> {
    let legend_width = 30 + 9 * panel.series.iter().map(|s| s.0.chars().count()).max().unwrap_or(0) as u32;
    let (w, _) = area.dim_in_pixel();
    let (chart_area, legend_area) = area.split_horizontally(w.saturating_sub(legend_width));
    let x0 = panel.rows.first().map_or(0.0, |r| r[0]);
    let x1 = panel.rows.last().map_or(1.0, |r| r[0]).max(x0 + 1e-12);
    let (lo, hi) = y_range(panel);
    let beyond = panel.rows.iter().any(|r| panel.series.iter().any(|(_, c)| clipped(r[*c])));
    let y_title = match beyond {
        true => format!("{} (clipped at ±{DRAWABLE:e})", panel.y_title),
        false => panel.y_title.clone(),
    };
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, lo..hi)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_title.as_str())
        .y_desc(y_title.as_str())
        .x_label_formatter(&tick_labels(x0, x1))
        .y_label_formatter(&tick_labels(lo, hi))
        .axis_desc_style(("sans-serif", 16))
        .draw()?;
    let width = line_width(panel.rows.len(), w);
    for (k, (_, c)) in panel.series.iter().enumerate() {
        let color = COLORS[k % COLORS.len()];
        chart.draw_series(LineSeries::new(
            panel.rows.iter().map(|r| (r[0], clip(r[*c]))),
            color.stroke_width(width),
        ))?;
    }
    for (k, (label, _)) in panel.series.iter().enumerate() {
        let color = COLORS[k % COLORS.len()];
        let y = 30 + 22 * k as i32;
        legend_area.draw(&PathElement::new(vec![(4, y), (24, y)], color.stroke_width(3)))?;
        legend_area.draw(&Text::new(label.clone(), (28, y - 8), ("sans-serif", 15)))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panel_of_values_near_the_largest_double_is_drawn() {
        let rows: Vec<Vec<f64>> =
            (0..50).map(|i| vec![i as f64, 1.7e308 * if i % 2 == 0 { 1.0 } else { -1.0 }]).collect();
        let panel = Panel {
            rows: &rows,
            series: vec![("q1".to_string(), 1)],
            x_title: "t".into(),
            y_title: "deg".into(),
        };
        super::super::register_font();
        let mut pixels = vec![0u8; 400 * 300 * 3];
        let area = BitMapBackend::with_buffer(&mut pixels, (400, 300)).into_drawing_area();
        draw(&area, &panel).unwrap();
    }
}
