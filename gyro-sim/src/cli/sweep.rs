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

/// Runs the members of this shard not yet in `out/sweep.csv` (or its journal, after a kill),
/// journaling each as it ends, and rewrites `sweep.csv` and `timing.csv` with all of them.
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
    let (old_header, rows) = sweep::read_rows(&csv_path)?;
    if !old_header.is_empty() && old_header != header {
        return Err(format!(
            "{} holds another sweep's rows (other columns): give another --out",
            csv_path.display()
        ));
    }
    std::fs::create_dir_all(args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let journaled = sweep::read_journal(args.out, &header)?;
    let done: Vec<usize> = rows
        .iter()
        .chain(journaled.iter().map(|(r, _)| r))
        .filter_map(|r| sweep::table::member_of(r))
        .collect();
    let todo: Vec<Member> = members.into_iter().filter(|m| !done.contains(&m.index)).collect();
    let journal = sweep::Journal::open(args.out, &header)?;
    let results =
        run_journaled(&scene, args.vary, &todo, &registry, &journal, header.len() - names.len() - 4)?;
    let journaled = sweep::read_journal(args.out, &header)?;
    finish(args.out, &header, rows, &journaled)?;
    journal.remove()?;
    let failed = results.iter().filter(|(r, _)| r.status != "ok").count();
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

/// Runs `todo` with a progress bar, appending each finished member to `journal`.
fn run_journaled(
    scene: &Scene,
    vary: &[Range],
    todo: &[Member],
    registry: &Registry,
    journal: &sweep::Journal,
    n_values: usize,
) -> Result<Vec<(sweep::SweepRow, f64)>, String> {
    let bar = ProgressBar::new(todo.len() as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} members, {eta} left")
            .map_err(|e| e.to_string())?,
    );
    let journal_error = std::sync::Mutex::new(None::<String>);
    let record = |row: &sweep::SweepRow, ms: f64| {
        if let Err(e) = journal.record(&sweep::table::cells(row, n_values), ms) {
            journal_error.lock().map(|mut slot| slot.get_or_insert(e).clone()).ok();
        }
        bar.inc(1);
    };
    let results = sweep::run_members(scene, vary, todo, registry, &record);
    bar.finish_and_clear();
    match journal_error.into_inner().ok().flatten() {
        Some(e) => Err(format!("the sweep's journal could not be written: {e}")),
        None => Ok(results),
    }
}

/// Writes `sweep.csv` (the earlier rows and the journaled ones, member order) and `timing.csv`
/// (the earlier wall times and the journaled ones).
fn finish(
    out: &Path,
    header: &[String],
    mut rows: Vec<Vec<String>>,
    journaled: &sweep::Journaled,
) -> Result<(), String> {
    rows.extend(journaled.iter().map(|(r, _)| r.clone()));
    rows.sort_by_key(|r| sweep::table::member_of(r));
    rows.dedup_by_key(|r| sweep::table::member_of(r));
    sweep::write_rows(&out.join("sweep.csv"), header, &rows)?;
    let timing_path = out.join("timing.csv");
    let (_, mut timing) = sweep::read_rows(&timing_path)?;
    timing.extend(journaled.iter().map(|(r, ms)| vec![r[0].clone(), format!("{ms:.4}")]));
    timing.sort_by_key(|r| sweep::table::member_of(r));
    timing.dedup_by_key(|r| sweep::table::member_of(r));
    sweep::write_rows(&timing_path, &["member".to_string(), "wall_ms".to_string()], &timing)
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
