//! `gyro-sim sweep` and `gyro-sim sweep-merge`: in come a scene, ranges to vary and a folder (or
//! shard folders); out go `sweep.csv` (one row per member, member order, reproducible byte for
//! byte) and `timing.csv` (wall times), with a progress bar. Members already in the folder's
//! `sweep.csv` are skipped, so a killed run resumes where it stopped.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use indicatif::{ProgressBar, ProgressStyle};

use crate::registry::Registry;
use crate::scene::Scene;
use crate::sweep::{self, Member, Range};

/// What a sweep is asked.
pub struct SweepArgs<'a> {
    /// The scene.
    pub scene: &'a Path,
    /// The ranges.
    pub vary: &'a [Range],
    /// Latin-hypercube samples (a grid when absent).
    pub samples: Option<usize>,
    /// The sample's seed.
    pub seed: u64,
    /// `K/N`, 1-based.
    pub shard: Option<&'a str>,
    /// The folder.
    pub out: &'a Path,
}

/// Runs the members of this shard not yet in `out/sweep.csv` and rewrites it with them.
pub fn sweep_command(args: &SweepArgs<'_>, registry: &Registry) -> Result<ExitCode, String> {
    let scene = Scene::load(args.scene).map_err(|e| e.to_string())?;
    let registry = super::with_file_model(&scene, registry.clone())?;
    let members = match args.samples {
        Some(n) => sweep::latin_hypercube(args.vary, n, args.seed),
        None => sweep::grid(args.vary)?,
    };
    let (k, n) = shard_of(args.shard)?;
    let members = sweep::shard(members, k, n);
    let names: Vec<String> = args.vary.iter().map(|r| r.name.clone()).collect();
    let header = sweep::table::header(&names, &sweep::value_columns(&scene, &registry)?);
    let csv_path = args.out.join("sweep.csv");
    let (old_header, mut rows) = sweep::read_rows(&csv_path)?;
    if !old_header.is_empty() && old_header != header {
        return Err(format!(
            "{} holds another sweep's rows (other columns): give another --out",
            csv_path.display()
        ));
    }
    let done: Vec<usize> = rows.iter().filter_map(|r| sweep::table::member_of(r)).collect();
    let todo: Vec<Member> = members.into_iter().filter(|m| !done.contains(&m.index)).collect();
    let bar = ProgressBar::new(todo.len() as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} members, {eta} left")
            .map_err(|e| e.to_string())?,
    );
    let results = sweep::run_members(&scene, args.vary, &todo, &registry, &|| bar.inc(1));
    bar.finish_and_clear();
    let n_values = header.len() - names.len() - 4;
    let failed = results.iter().filter(|(r, _)| r.status != "ok").count();
    rows.extend(results.iter().map(|(r, _)| sweep::table::cells(r, n_values)));
    rows.sort_by_key(|r| sweep::table::member_of(r));
    std::fs::create_dir_all(args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    sweep::write_rows(&csv_path, &header, &rows)?;
    write_timing(&args.out.join("timing.csv"), &results)?;
    println!(
        "{}: {} members run ({} failed, named in their rows), {} already done; wrote {}",
        scene.title,
        results.len(),
        failed,
        done.len(),
        csv_path.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Appends the new wall times to `timing.csv` (member, wall_ms), in member order.
fn write_timing(path: &Path, results: &[(sweep::SweepRow, f64)]) -> Result<(), String> {
    let (_, mut rows) = sweep::read_rows(path)?;
    rows.extend(results.iter().map(|(r, ms)| vec![r.member.to_string(), format!("{ms:.4}")]));
    rows.sort_by_key(|r| sweep::table::member_of(r));
    sweep::write_rows(path, &["member".to_string(), "wall_ms".to_string()], &rows)
}

/// The 0-based shard and the count: `--shard K/N` (K from 1), else Slurm's array task
/// (`SLURM_ARRAY_TASK_ID` less `SLURM_ARRAY_TASK_MIN`, of `SLURM_ARRAY_TASK_COUNT`), else all.
fn shard_of(arg: Option<&str>) -> Result<(usize, usize), String> {
    if let Some(text) = arg {
        let bad = || format!("--shard {text}: write K/N with 1 <= K <= N, e.g. --shard 2/4");
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (k, n): (usize, usize) =
            (k.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if k == 0 || k > n {
            return Err(bad());
        }
        return Ok((k - 1, n));
    }
    let var = |name: &str| std::env::var(name).ok().and_then(|v| v.parse::<usize>().ok());
    match (var("SLURM_ARRAY_TASK_ID"), var("SLURM_ARRAY_TASK_COUNT")) {
        (Some(id), Some(count)) if count > 0 => {
            Ok((id - var("SLURM_ARRAY_TASK_MIN").unwrap_or(0).min(id), count))
        }
        _ => Ok((0, 1)),
    }
}

/// `gyro-sim sweep-merge`: joins the shards' rows into `out/sweep.csv`.
pub fn merge_command(out: &Path, shards: &[PathBuf]) -> Result<ExitCode, String> {
    let dirs: Vec<&Path> = shards.iter().map(PathBuf::as_path).collect();
    let n = sweep::merge(&dirs, out)?;
    println!("merged {n} members from {} shards into {}", shards.len(), out.join("sweep.csv").display());
    Ok(ExitCode::SUCCESS)
}
