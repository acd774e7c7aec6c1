//! `gyro-sim bench`: in come a scene and a folder; out go the work-precision table (printed and
//! `work_precision.csv`) and its figure (`work_precision.png`).

use std::path::Path;
use std::process::ExitCode;

use super::CliError;
use crate::models::Registry;
use crate::scene::Scene;
use crate::study::work_precision::{measure, to_csv, Options};

/// Measures every method on the scene and writes the table and the figure.
pub fn bench_command(
    scene: &Path,
    repeats: usize,
    out: &Path,
    registry: &Registry,
) -> Result<ExitCode, CliError> {
    let scene = Scene::load(scene)?;
    let problem = crate::resolve::resolve(&scene, registry)?;
    let options = Options { repeats, ..Options::default() };
    let points = measure(&problem, &options)
        .map_err(|e| CliError::Run { scene: scene.path.clone(), source: Box::new(e.into()) })?;
    std::fs::create_dir_all(out).map_err(|source| CliError::Io { path: out.to_path_buf(), source })?;
    let csv = to_csv(&points);
    let csv_path = out.join("work_precision.csv");
    crate::output::write_file_atomically(&csv_path, csv.as_bytes())?;
    let png = out.join("work_precision.png");
    crate::output::write_work_precision(&points, &format!("{}: work against precision", scene.title), &png)?;
    println!(
        "{:<8} {:>9} {:>10} {:>11} {:>8} {:>10}",
        "method", "setting", "error", "median ms", "steps", "RHS evals"
    );
    for p in &points {
        if let Some(why) = &p.failure {
            println!("{:<8} {:>9.1e} failed: {why}", p.method, p.setting);
            continue;
        }
        println!(
            "{:<8} {:>9.1e} {:>10.2e} {:>11.4} {:>8} {:>10}",
            p.method, p.setting, p.error, p.median_ms, p.steps, p.rhs_evals
        );
    }
    println!("wrote {} and {}", csv_path.display(), png.display());
    Ok(ExitCode::SUCCESS)
}
