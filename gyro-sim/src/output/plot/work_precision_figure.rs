//! The work-precision figure: in come measured points ([`WorkPrecisionPoint`]: method, error,
//! median time); out goes a log-log PNG of time against error, one line per method, the legend
//! beside the chart.

use std::path::Path;

use plotters::prelude::*;

use super::super::WriteError;
use super::{draw_atomically, register_font, COLORS};

/// One configuration measured (by `gyro-sim bench`): a method at one tolerance or step.
#[derive(Clone, Debug, PartialEq)]
pub struct WorkPrecisionPoint {
    /// The method's name.
    pub method: &'static str,
    /// Its tolerance (adaptive) or step (fixed).
    pub setting: f64,
    /// Largest difference from the reference over the output grid and the states, relative to
    /// max(1, |reference|).
    pub error: f64,
    /// Median wall time of the integration, milliseconds.
    pub median_ms: f64,
    /// Accepted steps.
    pub steps: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
    /// Why the run failed (then error and times are NaN), e.g. a blow-up at a loose setting.
    pub failure: Option<String>,
}

/// Writes the figure of `points` to `path` (atomically), titled `title`.
pub fn write_work_precision(
    points: &[WorkPrecisionPoint],
    title: &str,
    path: &Path,
) -> Result<(), WriteError> {
    register_font();
    let finite: Vec<&WorkPrecisionPoint> =
        points.iter().filter(|p| p.error > 0.0 && p.median_ms > 0.0).collect();
    let bounds = |f: fn(&WorkPrecisionPoint) -> f64| {
        let lo = finite.iter().map(|p| f(p)).fold(f64::INFINITY, f64::min);
        let hi = finite.iter().map(|p| f(p)).fold(0.0, f64::max);
        if lo < hi {
            (lo / 2.0, hi * 2.0)
        } else {
            (1e-16, 1.0)
        }
    };
    let ((e0, e1), (t0, t1)) = (bounds(|p| p.error), bounds(|p| p.median_ms));
    let mut methods: Vec<&str> = Vec::new();
    for p in &finite {
        if !methods.contains(&p.method) {
            methods.push(p.method);
        }
    }
    draw_atomically(path, |tmp| {
        let root = BitMapBackend::new(tmp, (900, 600)).into_drawing_area();
        root.fill(&WHITE)?;
        let (chart_area, legend) = root.split_horizontally(780);
        let mut chart = ChartBuilder::on(&chart_area)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(80)
            .build_cartesian_2d((e0..e1).log_scale(), (t0..t1).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("error (largest over states and output times, relative to max(1, |ref|))")
            .y_desc("median wall time (ms)")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .axis_desc_style(("sans-serif", 15))
            .draw()?;
        for (k, m) in methods.iter().enumerate() {
            let colour = COLORS[k % COLORS.len()];
            let series: Vec<(f64, f64)> =
                finite.iter().filter(|p| p.method == *m).map(|p| (p.error, p.median_ms)).collect();
            chart.draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?;
            chart.draw_series(series.iter().map(|&(x, y)| Circle::new((x, y), 4, colour.filled())))?;
            let y = 40 + 24 * k as i32;
            legend.draw(&PathElement::new(vec![(4, y), (24, y)], colour.stroke_width(3)))?;
            legend.draw(&Text::new(m.to_string(), (28, y - 8), ("sans-serif", 15)))?;
        }
        Ok(root.present()?)
    })
}
