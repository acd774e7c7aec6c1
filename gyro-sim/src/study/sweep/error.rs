//! Why a sweep could not go on: its members asked for (`--vary`, `--samples`: [`DesignError`]),
//! its slice (`--shard`, Slurm: [`ShardError`]), or its folder's files (plan, lock, journal,
//! sorted runs, rows, merge: [`SweepError`]). Each variant names the file or argument and keeps
//! the error beneath it as its source, and says what to do.

use std::path::PathBuf;

use thiserror::Error;

use super::identity::PLAN_FILE;
use super::plan::{Range, MAX_MEMBERS};
use crate::output::WriteError;

/// The advice for a folder whose files belong to another sweep.
const START_OVER: &str = "give --new to start over, or another --out";

/// Why the members asked for cannot be made.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum DesignError {
    /// A `--vary` argument is not of the form.
    #[error("`{text}` is not NAME=START:STOP[:N] [UNIT] (for example --vary \"U3=10:100:10 rad/s\")")]
    Range {
        /// The argument.
        text: String,
    },
    /// Two ranges vary one quantity.
    #[error("--vary {range} and --vary {first} vary the same quantity (names are case-insensitive): give one range for it")]
    Twice {
        /// The later range.
        range: Box<Range>,
        /// The earlier one.
        first: Box<Range>,
    },
    /// `--samples` is zero or past the limit.
    #[error("--samples {count}: give 1 to {MAX_MEMBERS} samples (the most members one sweep may have)")]
    Samples {
        /// The count given.
        count: usize,
    },
    /// A grid's range lacks its number of points.
    #[error("--vary {name}: a grid needs the number of points, START:STOP:N")]
    GridPoints {
        /// The range's name.
        name: String,
    },
    /// A grid has more members than one sweep may.
    #[error("the grid has {} = {} members, more than the {MAX_MEMBERS} one sweep may have: use fewer points per range (or a --samples design)", counts.iter().map(usize::to_string).collect::<Vec<_>>().join(" x "), total.map_or_else(|| "more than 2^128".to_string(), |t| t.to_string()))]
    GridTooLarge {
        /// The points per range.
        counts: Vec<usize>,
        /// Their product (`None`: past 2^128).
        total: Option<u128>,
    },
}

/// Why the shard a run takes is unknown.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum ShardError {
    /// `--shard` is not `K/N` with `1 <= K <= N`.
    #[error("--shard {text}: write K/N with 1 <= K <= N, e.g. --shard 2/4")]
    Form {
        /// The argument.
        text: String,
    },
    /// A Slurm variable is not a whole number.
    #[error("{name}={value} is not a whole number: pass --shard K/N")]
    NotANumber {
        /// The variable.
        name: String,
        /// Its value.
        value: String,
    },
    /// The Slurm array's ids are not evenly spaced, so the task's rank is unknown.
    #[error("this Slurm array's task ids are not evenly spaced (SLURM_ARRAY_TASK_ID={id}, MIN={min}, MAX={max}, STEP={step}, COUNT={count}), so this task's rank among them is unknown: submit an evenly spaced array (--array=0-{}, or START-END:STEP), or pass the shard yourself, e.g. --shard $((SLURM_ARRAY_TASK_ID+1))/{} to make each id its own shard (then every id 0..={max} must run)", count.saturating_sub(1), max.saturating_add(1))]
    Uneven {
        /// `SLURM_ARRAY_TASK_ID`.
        id: usize,
        /// `SLURM_ARRAY_TASK_MIN`.
        min: usize,
        /// `SLURM_ARRAY_TASK_MAX`.
        max: usize,
        /// `SLURM_ARRAY_TASK_STEP` (or the step implied).
        step: usize,
        /// `SLURM_ARRAY_TASK_COUNT`.
        count: usize,
    },
}

/// Why a sweep's folder could not be read, written or merged.
#[derive(Debug, Error)]
pub enum SweepError {
    /// A file or folder could not be opened, read, written or removed.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// A rows file's CSV could not be read.
    #[error("{}: {source}", path.display())]
    Csv {
        /// The file.
        path: PathBuf,
        /// What the CSV reader said.
        #[source]
        source: csv::Error,
    },
    /// A file could not be put in place.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// Cells could not be made into a CSV record.
    #[error("{0}")]
    Record(#[source] csv::Error),
    /// The folder is locked by a running sweep.
    #[error("another sweep is running in {} (it holds {}): wait for it to end, or give another --out", dir.display(), lock.display())]
    Busy {
        /// The folder.
        dir: PathBuf,
        /// Its lock file.
        lock: PathBuf,
    },
    /// The folder's lock file could not be locked.
    #[error("{}: cannot be locked: {source}", path.display())]
    Lock {
        /// The lock file.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The plan file is not a plan.
    #[error("{}: not a sweep plan ({source}): {START_OVER}", path.display())]
    NotAPlan {
        /// The plan file.
        path: PathBuf,
        /// What the TOML reader said.
        #[source]
        source: toml::de::Error,
    },
    /// The plan could not be written as TOML.
    #[error("{0}")]
    PlanText(#[source] toml::ser::Error),
    /// The folder holds another sweep.
    #[error("{} holds another sweep: the folder's sweep {}: give another --out, or --new to start over (its rows are removed)", dir.display(), differences.join("; the folder's sweep "))]
    OtherSweep {
        /// The folder.
        dir: PathBuf,
        /// What differs, one phrase each.
        differences: Vec<String>,
    },
    /// The folder holds rows without a plan.
    #[error("{} holds sweep rows without {PLAN_FILE} (written by hand or by an older gyro-sim), so which sweep they belong to is unknown: give another --out, or --new to start over (its rows are removed)", dir.display())]
    UnknownRows {
        /// The folder.
        dir: PathBuf,
    },
    /// The journal could not be read as CSV.
    #[error("{}: {source}: {START_OVER}", path.display())]
    JournalRead {
        /// The journal.
        path: PathBuf,
        /// What the CSV reader said.
        #[source]
        source: csv::Error,
    },
    /// The journal's first line is another sweep's plan.
    #[error("{}: it is another sweep's journal (its first line is not this sweep's plan): {START_OVER}", path.display())]
    OtherJournal {
        /// The journal.
        path: PathBuf,
    },
    /// A rows file's (or the journal's) columns are another sweep's.
    #[error("{}: its columns are not this sweep's: {START_OVER}", path.display())]
    OtherColumns {
        /// The file.
        path: PathBuf,
    },
    /// A journal line has the wrong number of cells or no member.
    #[error("{}: a damaged line ({cells} cells) at byte {byte}: {START_OVER}", path.display())]
    DamagedJournal {
        /// The journal.
        path: PathBuf,
        /// The line's cells.
        cells: usize,
        /// Where the line starts.
        byte: u64,
    },
    /// A journal line has no cell after its wall time.
    #[error("{}: a journal line without cells", path.display())]
    JournalLine {
        /// The journal.
        path: PathBuf,
    },
    /// The journal's lines were not visited in the file's order.
    #[error("{}: lines out of order", path.display())]
    JournalOrder {
        /// The journal.
        path: PathBuf,
    },
    /// A thread panicked while it held the journal.
    #[error("the sweep journal's lock is poisoned")]
    Poisoned,
    /// A sort's run file is cut short or out of order.
    #[error("{}: a damaged run file (cut short or out of order)", path.display())]
    DamagedRun {
        /// The run file.
        path: PathBuf,
    },
    /// A rows file's rows are not in member order.
    #[error("{}: member {member} comes after member {after}: rows must be in member order, each once", path.display())]
    RowOrder {
        /// The file.
        path: PathBuf,
        /// The member out of order.
        member: usize,
        /// The member before it.
        after: usize,
    },
    /// A rows file's row has no member index.
    #[error("{}: a row without a member index: {line}", path.display())]
    NoMember {
        /// The file.
        path: PathBuf,
        /// The row.
        line: String,
    },
    /// No shard folders were given to merge.
    #[error("give the shards' folders to merge")]
    NoShards,
    /// A folder is not a finished shard (no plan).
    #[error("{}: no sweep.plan.toml: not a finished shard of a gyro-sim sweep (run it again to finish it)", dir.display())]
    NotAShard {
        /// The folder.
        dir: PathBuf,
    },
    /// A shard folder has no rows.
    #[error("{}: no sweep.csv (is it a finished shard's --out folder?)", dir.display())]
    NoRows {
        /// The folder.
        dir: PathBuf,
    },
    /// The first shard's plan says an implausible number of shards.
    #[error("{}: {shards} shards is not a plausible split", dir.display())]
    Split {
        /// The folder.
        dir: PathBuf,
        /// Its plan's shards.
        shards: usize,
    },
    /// A shard belongs to another sweep than the first.
    #[error("{} is another sweep's shard than {}: the first {}: refusing to merge", dir.display(), first.display(), differences.join("; the first "))]
    OtherShard {
        /// The folder.
        dir: PathBuf,
        /// The first shard's folder.
        first: PathBuf,
        /// What differs, one phrase each.
        differences: Vec<String>,
    },
    /// Two folders hold the same shard.
    #[error("{} and {} are both shard {shard}/{shards}: give each shard once", first.display(), dir.display())]
    ShardTwice {
        /// The earlier folder.
        first: PathBuf,
        /// The later one.
        dir: PathBuf,
        /// The shard, from 1.
        shard: usize,
        /// Of how many.
        shards: usize,
    },
    /// A plan's shard is out of its range.
    #[error("{}: shard {shard}/{shards} is not a shard", dir.display())]
    NotInSplit {
        /// The folder.
        dir: PathBuf,
        /// The shard, from 1.
        shard: usize,
        /// Of how many.
        shards: usize,
    },
    /// Shards are missing.
    #[error("shard{} {} of the {} missing ({given} of {shards} shards given): give their folders, or run them (gyro-sim sweep ... --shard K/N); refusing to merge", if missing.len() > 1 { "s" } else { "" }, missing.join(", "), if missing.len() > 1 { "sweep are" } else { "sweep is" })]
    MissingShards {
        /// The missing shards, each `K/N (its members)`.
        missing: Vec<String>,
        /// The shards given.
        given: usize,
        /// The shards the sweep has.
        shards: usize,
    },
    /// A shard's columns differ from the first's.
    #[error("{}: its columns differ from the first shard's", dir.display())]
    ShardColumns {
        /// The folder.
        dir: PathBuf,
    },
    /// Members are missing from the shards or in the wrong shard.
    #[error("refusing to merge: {}", member_problems(*missing_count, *members, missing, strays, *stray_count))]
    Members {
        /// Members missing in all.
        missing_count: usize,
        /// The plan's members.
        members: usize,
        /// The first missing members.
        missing: Vec<usize>,
        /// The first strays, each `M (in FOLDER)`.
        strays: Vec<String>,
        /// Strays in all.
        stray_count: usize,
    },
    /// A shard's rows changed while being merged.
    #[error("{}: changed while being merged", dir.display())]
    Changed {
        /// The folder.
        dir: PathBuf,
    },
}

impl SweepError {
    /// The system's error `source` at `path`.
    pub(crate) fn io(path: impl Into<PathBuf>, source: std::io::Error) -> SweepError {
        SweepError::Io { path: path.into(), source }
    }

    /// The CSV reader's error `source` at `path`.
    pub(crate) fn csv(path: impl Into<PathBuf>, source: csv::Error) -> SweepError {
        SweepError::Csv { path: path.into(), source }
    }
}

/// What is wrong with the members of shards: `missing_count` of `members` missing (the first
/// `missing` listed), and `stray_count` strays (the first `strays` listed).
fn member_problems(
    missing_count: usize,
    members: usize,
    missing: &[usize],
    strays: &[String],
    stray_count: usize,
) -> String {
    let mut why = Vec::new();
    if missing_count > 0 {
        let listed_missing = listed(&missing.iter().map(usize::to_string).collect::<Vec<_>>(), missing_count);
        why.push(format!(
            "{missing_count} of {members} members are missing: {listed_missing} (their shards did not finish: run them again)"
        ));
    }
    if stray_count > 0 {
        why.push(format!("members not of their shard or given twice: {}", listed(strays, stray_count)));
    }
    why.join("; ")
}

/// Up to 20 of `items`, then how many more of `total`.
fn listed(items: &[String], total: usize) -> String {
    let shown = items.iter().take(20).cloned().collect::<Vec<_>>().join(", ");
    if total > 20 {
        format!("{shown} and {} more", total - 20)
    } else {
        shown
    }
}
