//! `gyro-sim sweep-plot`: in come a sweep's folder, a metric (a `sweep.csv` column) and the
//! varied names to draw it over (one or two; the sweep's first ones by default); out goes a PNG
//! of the metric over them, failed members marked (`output::plot::write_sweep_metric`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::CliError;
use crate::output::{write_sweep_metric, MemberPoint, MetricAxes};
use crate::study::sweep;

/// What a metric plot is asked.
pub struct SweepPlotArgs<'a> {
    /// The sweep's folder (holding sweep.csv).
    pub dir: &'a Path,
    /// The column to draw.
    pub metric: &'a str,
    /// The varied names on the axes (empty: the sweep's first one or two).
    pub over: &'a [String],
    /// The PNG (default DIR/METRIC.png).
    pub out: Option<&'a Path>,
}

/// Draws the metric of `args.dir/sweep.csv` over the varied values.
pub fn sweep_plot_command(args: &SweepPlotArgs<'_>) -> Result<ExitCode, CliError> {
    let csv_path = args.dir.join("sweep.csv");
    let (header, rows) = sweep::read_rows(&csv_path)?;
    if header.is_empty() {
        return Err(CliError::NoSweep { csv: csv_path, dir: args.dir.to_path_buf() });
    }
    let status = header
        .iter()
        .position(|h| h == "status")
        .ok_or_else(|| CliError::NoStatus { csv: csv_path.clone() })?;
    let varied = &header[1..status];
    let find = |name: &str, among: &[String]| {
        among.iter().position(|h| h.eq_ignore_ascii_case(name)).ok_or_else(|| CliError::NoColumn {
            csv: csv_path.clone(),
            name: name.to_string(),
            columns: among.to_vec(),
        })
    };
    let metric = find(args.metric, &header)?;
    let over: Vec<String> =
        if args.over.is_empty() { varied.iter().take(2).cloned().collect() } else { args.over.to_vec() };
    if over.is_empty() || over.len() > 2 {
        return Err(CliError::Over { varied: varied.to_vec() });
    }
    let axes: Vec<usize> = over.iter().map(|n| find(n, varied).map(|k| k + 1)).collect::<Result<_, _>>()?;
    let number = |r: &[String], k: usize| r.get(k).and_then(|c| c.parse::<f64>().ok());
    let points: Vec<MemberPoint> = rows
        .iter()
        .map(|r| MemberPoint {
            x: number(r, axes[0]).unwrap_or(f64::NAN),
            y: axes.get(1).and_then(|&k| number(r, k)).unwrap_or(0.0),
            metric: number(r, metric).filter(|m| m.is_finite() && r[status] == "ok"),
        })
        .collect();
    let out: PathBuf =
        args.out.map(Path::to_path_buf).unwrap_or_else(|| args.dir.join(format!("{}.png", header[metric])));
    let title = format!("{} over {} ({} members)", header[metric], over.join(" and "), rows.len());
    let names: Vec<String> = axes.iter().map(|&k| header[k].clone()).collect();
    write_sweep_metric(&points, &MetricAxes { varied: &names, metric: &header[metric] }, &title, &out)?;
    let failed = points.iter().filter(|p| p.metric.is_none()).count();
    println!(
        "wrote {} ({} members, {failed} failed or without a value, drawn as crosses)",
        out.display(),
        rows.len()
    );
    Ok(ExitCode::SUCCESS)
}
