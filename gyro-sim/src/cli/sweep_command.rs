//! `gyro-sim sweep` and `gyro-sim sweep-merge`: in come a scene, ranges to vary and a folder (or
//! shard folders); out go `sweep.csv` (one row per member, member order, reproducible byte for
//! byte) and `timing.csv` (wall times), with a progress bar. A folder holds one sweep: its plan
//! is kept in `sweep.plan.toml`, a re-run of the same plan skips the members already done (so a
//! killed or interrupted run resumes where it stopped), another plan is refused (or, with
//! `--new`, starts over), and a lock keeps a second sweep out while one runs.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};

use indicatif::{ProgressBar, ProgressStyle};

use super::CliError;
use crate::models::Registry;
use crate::scene::Scene;
use crate::study::sweep::{self, Design, MemberSet, Members, Range, Shard, SweepError, SweepPlan};

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
    /// Start over when the folder holds another sweep.
    pub new: bool,
    /// The folder.
    pub out: &'a Path,
}

/// Runs the members of this shard not yet in `out/sweep.csv` (or its journal, after a kill),
/// journaling each as it ends, and rewrites `sweep.csv` and `timing.csv` with all of them; the
/// folder must hold this sweep (or none) and no other sweep may be running in it.
pub fn sweep_command(args: &SweepArgs<'_>, registry: &Registry) -> Result<ExitCode, CliError> {
    // A sweep writes no view: neither its columns nor a model's drawing are computed.
    let scene = Scene {
        view: None,
        ..Scene::load_with(args.scene, &Default::default(), &|m| {
            crate::model_run::file_defaults(args.scene, m)
        })?
    };
    let (registry, warnings) = crate::model_run::with_file_model(&scene, registry.clone())?;
    eprint!("{warnings}");
    let design = match args.samples {
        Some(count) => Design::Samples { count, seed: args.seed },
        None => Design::Grid,
    };
    let members = Members::new(args.vary, &design)?;
    let shard = Shard::resolve(args.shard, &|name| std::env::var(name).ok())?;
    let plan = plan_of(&scene, args.vary, &design, members.len(), shard)?;
    let names: Vec<String> = args.vary.iter().map(|r| r.name.clone()).collect();
    let header = sweep::table::header(&names, &sweep::value_columns(&scene, &registry)?);
    std::fs::create_dir_all(args.out)
        .map_err(|source| CliError::Io { path: args.out.to_path_buf(), source })?;
    let _lock = sweep::lock::FolderLock::take(args.out)?;
    sweep::identity::bind(args.out, &plan, args.new)?;
    let fingerprint = plan.fingerprint();
    let mut done = MemberSet::new(members.len());
    let journal = sweep::Journal::open(args.out, &fingerprint, &header, &mut |e| {
        done.insert(e.member);
        Ok(())
    })?;
    add_rows(args.out, &header, &mut done)?;
    let shard_len = (shard.index..members.len()).step_by(shard.count).len();
    let todo = sweep::todo(members.len(), shard, &done);
    let run =
        Run { scene: &scene, vary: args.vary, members: &members, registry: &registry, journal: &journal };
    let (ran, failed) =
        run.journaled(todo, shard_len.saturating_sub(done.len()), header.len() - names.len() - 4)?;
    if let Some(by) = crate::ode::interrupt::requested() {
        let kept = sweep::scan_journal(args.out, &fingerprint, &header, &mut |_| Ok(()))?;
        return Err(CliError::Interrupted { by, kept, journal: args.out.join(sweep::JOURNAL_FILE) });
    }
    sweep::finish(args.out, &fingerprint, &header)?;
    journal.remove()?;
    println!(
        "{}: {ran} members run ({failed} failed, named in their rows), {} already done; wrote {}",
        scene.title,
        done.len(),
        args.out.join("sweep.csv").display()
    );
    Ok(ExitCode::SUCCESS)
}

/// The plan of a sweep of `scene`: what its rows depend on.
fn plan_of(
    scene: &Scene,
    vary: &[Range],
    design: &Design,
    members: usize,
    shard: Shard,
) -> Result<SweepPlan, CliError> {
    let (model, model_text) = match crate::model_run::model_file_of(scene) {
        Some(path) => {
            let text = std::fs::read(&path).map_err(|source| CliError::Io { path: path.clone(), source })?;
            (path.display().to_string(), sweep::identity::fnv1a64(&text))
        }
        None => (scene.model.clone(), "built-in".to_string()),
    };
    let design = match design {
        Design::Grid => "grid".to_string(),
        Design::Samples { count, seed } => {
            format!("Latin-hypercube sample of {count} from seed {seed} (members drawn from their index)")
        }
    };
    Ok(SweepPlan {
        scene: scene.path.display().to_string(),
        scene_text: sweep::identity::fnv1a64(scene.source.as_bytes()),
        model,
        model_text,
        vary: vary.iter().map(Range::to_string).collect(),
        design,
        members,
        shard: shard.index + 1,
        shards: shard.count,
    })
}

/// Adds to `done` the members of the rows of `out/sweep.csv` (whose columns must be `header`).
fn add_rows(out: &Path, header: &[String], done: &mut MemberSet) -> Result<(), CliError> {
    let csv_path = out.join("sweep.csv");
    if let Some(mut rows) = sweep::table::RowLines::open(&csv_path)? {
        if rows.header != header {
            return Err(SweepError::OtherColumns { path: csv_path }.into());
        }
        while let Some((m, _)) = rows.next_row()? {
            done.insert(m);
        }
    }
    Ok(())
}

/// What members run with.
struct Run<'a> {
    scene: &'a Scene,
    vary: &'a [Range],
    members: &'a Members,
    registry: &'a Registry,
    journal: &'a sweep::Journal,
}

impl Run<'_> {
    /// Runs `todo` (`len` members) with a progress bar, appending each finished member to the
    /// journal; how many ran and how many of them failed.
    fn journaled(
        &self,
        todo: impl Iterator<Item = usize> + Send,
        len: usize,
        n_values: usize,
    ) -> Result<(usize, usize), CliError> {
        let bar = ProgressBar::new(len as u64)
            .with_style(ProgressStyle::with_template("{bar:40} {pos}/{len} members, {eta} left")?);
        let (ran, failed) = (AtomicUsize::new(0), AtomicUsize::new(0));
        let journal_error = std::sync::Mutex::new(None::<sweep::SweepError>);
        let record = |row: &sweep::SweepRow, ms: f64| {
            match self.journal.record(&sweep::table::cells(row, n_values), ms) {
                Ok(()) => {
                    ran.fetch_add(1, Ordering::Relaxed);
                    failed.fetch_add(usize::from(row.status != "ok"), Ordering::Relaxed);
                }
                Err(e) => {
                    if let Ok(mut slot) = journal_error.lock() {
                        slot.get_or_insert(e);
                    }
                }
            }
            bar.inc(1);
        };
        sweep::run_members(self.scene, self.vary, self.members, todo, self.registry, &record);
        bar.finish_and_clear();
        match journal_error.into_inner().ok().flatten() {
            Some(e) => Err(CliError::Journal(e)),
            None => Ok((ran.into_inner(), failed.into_inner())),
        }
    }
}

/// `gyro-sim sweep-merge`: joins the shards' rows into `out/sweep.csv`.
pub fn merge_command(out: &Path, shards: &[PathBuf]) -> Result<ExitCode, CliError> {
    let dirs: Vec<&Path> = shards.iter().map(PathBuf::as_path).collect();
    let n = sweep::merge(&dirs, out)?;
    println!("merged {n} members from {} shards into {}", shards.len(), out.join("sweep.csv").display());
    Ok(ExitCode::SUCCESS)
}
