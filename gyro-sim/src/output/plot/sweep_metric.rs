//! A sweep's metric figure: in come members as points (one or two varied values, the metric, or
//! none when the member failed); out goes a PNG: the metric against one varied value (line and
//! markers), or over two (each member a disc coloured by the metric, with a colour bar).
//! Failed members are drawn as crosses, so a failure region shows.

use std::path::Path;

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::super::WriteError;
use super::drawable::{padded_range, tick_labels};
use super::{draw_atomically, register_font, PlotError};

/// One member: its varied values on the axes (`y` unused with one axis) and the metric (None
/// when it failed or has no value).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MemberPoint {
    /// The first varied value.
    pub x: f64,
    /// The second varied value (two axes).
    pub y: f64,
    /// The metric.
    pub metric: Option<f64>,
}

/// Axis titles: the varied names (one or two) and the metric's.
pub struct MetricAxes<'a> {
    /// The varied names drawn: one or two.
    pub varied: &'a [String],
    /// The metric's column name.
    pub metric: &'a str,
}

/// Writes the figure of `points` to `path` (atomically), titled `title`.
pub fn write_sweep_metric(
    points: &[MemberPoint],
    axes: &MetricAxes<'_>,
    title: &str,
    path: &Path,
) -> Result<(), WriteError> {
    register_font();
    draw_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (900, 640)).into_drawing_area();
        root.fill(&WHITE)?;
        let root = root.titled(title, ("sans-serif", 20))?;
        if axes.varied.len() == 1 {
            draw_line(&root, points, axes)?;
        } else {
            draw_map(&root, points, axes)?;
        }
        Ok(root.present()?)
    })
}

/// A chart over `x` and `y` on `area`, its mesh drawn with the axis `titles`.
fn framed<'a, 'b>(
    area: &'a DrawingArea<BitMapBackend<'b>, Shift>,
    x: (f64, f64),
    y: (f64, f64),
    titles: (&str, &str),
) -> Result<ChartContext<'a, BitMapBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>, PlotError> {
    let mut chart = ChartBuilder::on(area)
        .margin(16)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    chart
        .configure_mesh()
        .x_desc(titles.0)
        .y_desc(titles.1)
        .x_label_formatter(&tick_labels(x.0, x.1))
        .y_label_formatter(&tick_labels(y.0, y.1))
        .axis_desc_style(("sans-serif", 16))
        .draw()?;
    Ok(chart)
}

/// The metric against one varied value.
fn draw_line(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    points: &[MemberPoint],
    axes: &MetricAxes<'_>,
) -> Result<(), PlotError> {
    let mut ok: Vec<(f64, f64)> = points.iter().filter_map(|p| p.metric.map(|m| (p.x, m))).collect();
    ok.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (x0, x1) = padded_range(points.iter().map(|p| p.x));
    let (y0, y1) = padded_range(ok.iter().map(|p| p.1));
    let mut chart = framed(area, (x0, x1), (y0, y1), (&axes.varied[0], axes.metric))?;
    let blue = RGBColor(31, 119, 180);
    // A line only through distinct x (a projection of a two-way sweep is markers alone).
    if ok.windows(2).all(|w| w[0].0 < w[1].0) {
        chart.draw_series(LineSeries::new(ok.clone(), blue.stroke_width(2)))?;
    }
    chart.draw_series(ok.iter().map(|&p| Circle::new(p, 3, blue.filled())))?;
    let failed =
        points.iter().filter(|p| p.metric.is_none()).map(|p| Cross::new((p.x, y0), 6, RED.stroke_width(2)));
    chart.draw_series(failed)?;
    Ok(())
}

/// The metric over two varied values, with a colour bar on the right.
fn draw_map(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    points: &[MemberPoint],
    axes: &MetricAxes<'_>,
) -> Result<(), PlotError> {
    let (w, _) = area.dim_in_pixel();
    let (chart_area, bar_area) = area.split_horizontally(w.saturating_sub(130));
    let (x0, x1) = padded_range(points.iter().map(|p| p.x));
    let (y0, y1) = padded_range(points.iter().map(|p| p.y));
    let values = points.iter().filter_map(|p| p.metric);
    let (lo, hi) = values.clone().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let shade = |m: f64| viridis(if hi > lo { (m - lo) / (hi - lo) } else { 0.5 });
    let mut chart = framed(&chart_area, (x0, x1), (y0, y1), (&axes.varied[0], &axes.varied[1]))?;
    let discs = points.iter().filter_map(|p| p.metric.map(|m| Circle::new((p.x, p.y), 5, shade(m).filled())));
    chart.draw_series(discs)?;
    let failed =
        points.iter().filter(|p| p.metric.is_none()).map(|p| Cross::new((p.x, p.y), 6, RED.stroke_width(2)));
    chart.draw_series(failed)?;
    draw_colour_bar(&bar_area, axes.metric, lo, hi, shade)
}

/// Viridis at `frac` in [0, 1], linear between five of its published colours.
fn viridis(frac: f64) -> RGBColor {
    const ANCHORS: [(u8, u8, u8); 5] =
        [(0x44, 0x01, 0x54), (0x3b, 0x52, 0x8b), (0x21, 0x91, 0x8c), (0x5e, 0xc9, 0x62), (0xfd, 0xe7, 0x25)];
    let x = frac.clamp(0.0, 1.0) * (ANCHORS.len() - 1) as f64;
    let k = (x.floor() as usize).min(ANCHORS.len() - 2);
    let (a, b, f) = (ANCHORS[k], ANCHORS[k + 1], x - k as f64);
    let mix = |p: u8, q: u8| (p as f64 + f * (q as f64 - p as f64)).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A vertical colour bar from `lo` (bottom) to `hi` (top), labelled.
fn draw_colour_bar(
    area: &DrawingArea<BitMapBackend<'_>, Shift>,
    metric: &str,
    lo: f64,
    hi: f64,
    shade: impl Fn(f64) -> RGBColor,
) -> Result<(), PlotError> {
    let (top, bottom, steps) = (60, 520, 92);
    let font = ("sans-serif", 14);
    area.draw(&Text::new(metric.to_string(), (4, top - 30), font))?;
    if !(lo.is_finite() && hi.is_finite()) {
        return Ok(());
    }
    for k in 0..steps {
        let frac = k as f64 / (steps - 1) as f64;
        let y = bottom - ((bottom - top) as f64 * frac) as i32;
        let colour = shade(lo + frac * (hi - lo));
        area.draw(&Rectangle::new([(10, y - 5), (34, y)], colour.filled()))?;
    }
    for (v, y) in [(hi, top), (0.5 * (lo + hi), (top + bottom) / 2), (lo, bottom)] {
        let label =
            if v != 0.0 && !(1e-3..1e5).contains(&v.abs()) { format!("{v:.3e}") } else { format!("{v:.4}") };
        area.draw(&Text::new(label, (40, y - 12), font))?;
    }
    Ok(())
}
