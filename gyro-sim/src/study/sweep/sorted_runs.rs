//! Journal lines put in member order within bounded memory: in come `(member, line)` pairs in
//! journal order; out they go again in member order, each member once (its first line in the
//! journal). Lines are gathered up to a byte budget, sorted and written as a run file in the
//! sweep's folder (a hidden temporary, removed when done or failed); the runs are then merged.
//! Memory holds one budget of lines while gathering and one line per run while merging.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::fs::File;
use std::io::{BufReader, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

use super::journal::VisitLine;
use super::SweepError;

/// The name run files are temporaries of (`.partial-{pid}-{random}-sweep.run`).
pub(crate) const RUN_NAME: &str = "sweep.run";

/// Bytes a buffer of lines may hold before it is written as a run.
pub const RUN_BUDGET: usize = 64 << 20;

/// Runs merged at once (each an open file); more are first merged into fewer.
pub const FAN_IN: usize = 64;

/// Bytes counted for each buffered line besides its own (its member and place).
const LINE_COST: usize = 3 * std::mem::size_of::<usize>();

/// Journal lines being sorted into run files in a sweep's folder; the files go when it is dropped.
pub struct SortedRuns {
    dir: PathBuf,
    budget: usize,
    fan_in: usize,
    bytes: Vec<u8>,
    lines: Vec<(usize, usize, usize)>,
    runs: Vec<PathBuf>,
    made: Vec<PathBuf>,
}

impl SortedRuns {
    /// Sorting into `dir` with a buffer of `budget` bytes, merging `fan_in` runs at once; run
    /// files left there by an earlier, killed sort are removed (the folder's lock is held).
    pub fn new(dir: &Path, budget: usize, fan_in: usize) -> Result<SortedRuns, SweepError> {
        crate::output::remove_temporaries(dir, &[RUN_NAME])?;
        Ok(SortedRuns {
            dir: dir.to_path_buf(),
            budget,
            fan_in: fan_in.max(2),
            bytes: Vec::new(),
            lines: Vec::new(),
            runs: Vec::new(),
            made: Vec::new(),
        })
    }

    /// Takes member `member`'s `line` (the next in journal order).
    pub fn push(&mut self, member: usize, line: &[u8]) -> Result<(), SweepError> {
        self.lines.push((member, self.bytes.len(), line.len()));
        self.bytes.extend_from_slice(line);
        if self.bytes.len() + self.lines.len() * LINE_COST >= self.budget {
            self.spill()?;
        }
        Ok(())
    }

    /// Passes each member's first line to `visit`, in member order, once all are pushed (as
    /// often as asked).
    pub fn merge(&mut self, visit: VisitLine<'_>) -> Result<(), SweepError> {
        self.spill()?;
        self.bytes = Vec::new();
        self.lines = Vec::new();
        while self.runs.len() > self.fan_in {
            let runs = std::mem::take(&mut self.runs);
            for group in runs.chunks(self.fan_in) {
                let path = self.new_run();
                let mut w = RunWriter::create(&path)?;
                merge_runs(group, &mut |m, line| w.write(m, line))?;
                w.finish()?;
                self.runs.push(path);
                for done in group {
                    std::fs::remove_file(done).map_err(|e| SweepError::io(done, e))?;
                }
            }
        }
        merge_runs(&self.runs, visit)
    }

    /// Writes the buffered lines as a run, sorted by member, each member's first line once.
    fn spill(&mut self) -> Result<(), SweepError> {
        if self.lines.is_empty() {
            return Ok(());
        }
        // A stable sort keeps a member's lines in journal order: the first is its row.
        self.lines.sort_by_key(|l| l.0);
        let path = self.new_run();
        let mut w = RunWriter::create(&path)?;
        let mut last = None;
        for &(member, at, len) in &self.lines {
            if last != Some(member) {
                w.write(member, &self.bytes[at..at + len])?;
                last = Some(member);
            }
        }
        w.finish()?;
        self.runs.push(path);
        self.bytes.clear();
        self.lines.clear();
        Ok(())
    }

    /// A fresh run file's path, noted for removal.
    fn new_run(&mut self) -> PathBuf {
        let path = self.dir.join(crate::output::unique_temporary(RUN_NAME));
        self.made.push(path.clone());
        path
    }
}

impl Drop for SortedRuns {
    /// Removes the run files (those already merged are gone).
    fn drop(&mut self) {
        for path in &self.made {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// Passes the lines of the sorted `runs` to `visit` in member order, each member once: of equal
/// members, the one in the earliest run (runs are in journal order).
fn merge_runs(runs: &[PathBuf], visit: VisitLine<'_>) -> Result<(), SweepError> {
    let mut readers = runs.iter().map(|p| RunReader::open(p)).collect::<Result<Vec<_>, _>>()?;
    let mut heads: Vec<Vec<u8>> = vec![Vec::new(); readers.len()];
    let mut heap = BinaryHeap::with_capacity(readers.len());
    for (k, r) in readers.iter_mut().enumerate() {
        if let Some(m) = r.next(&mut heads[k])? {
            heap.push(Reverse((m, k)));
        }
    }
    let mut last = None;
    while let Some(Reverse((m, k))) = heap.pop() {
        if last != Some(m) {
            visit(m, &heads[k])?;
            last = Some(m);
        }
        if let Some(next) = readers[k].next(&mut heads[k])? {
            heap.push(Reverse((next, k)));
        }
    }
    Ok(())
}

/// A run file being written: records of the member (8 bytes), the line's length (8 bytes),
/// the line, all little-endian.
struct RunWriter {
    path: PathBuf,
    out: BufWriter<File>,
}

impl RunWriter {
    /// A new run file at `path` (never one that exists).
    fn create(path: &Path) -> Result<RunWriter, SweepError> {
        let file = File::options().write(true).create_new(true).open(path);
        let file = file.map_err(|e| SweepError::io(path, e))?;
        Ok(RunWriter { path: path.to_path_buf(), out: BufWriter::new(file) })
    }

    /// Appends member `member`'s `line`.
    fn write(&mut self, member: usize, line: &[u8]) -> Result<(), SweepError> {
        let fail = |e: std::io::Error| SweepError::io(&self.path, e);
        self.out.write_all(&(member as u64).to_le_bytes()).map_err(fail)?;
        self.out.write_all(&(line.len() as u64).to_le_bytes()).map_err(fail)?;
        self.out.write_all(line).map_err(fail)
    }

    /// Writes out what is buffered.
    fn finish(mut self) -> Result<(), SweepError> {
        self.out.flush().map_err(|e| SweepError::io(&self.path, e))
    }
}

/// A run file read one record at a time, checked to be in member order.
struct RunReader {
    path: PathBuf,
    input: BufReader<File>,
    last: Option<usize>,
}

impl RunReader {
    /// Opens the run file at `path`.
    fn open(path: &Path) -> Result<RunReader, SweepError> {
        let file = File::open(path).map_err(|e| SweepError::io(path, e))?;
        Ok(RunReader { path: path.to_path_buf(), input: BufReader::new(file), last: None })
    }

    /// The next record's member, its line put in `line`; `None` at the end.
    fn next(&mut self, line: &mut Vec<u8>) -> Result<Option<usize>, SweepError> {
        use std::io::BufRead;
        let fail = |e: std::io::Error| SweepError::io(&self.path, e);
        let damaged = || SweepError::DamagedRun { path: self.path.clone() };
        if self.input.fill_buf().map_err(fail)?.is_empty() {
            return Ok(None);
        }
        let mut word = [0u8; 8];
        self.input.read_exact(&mut word).map_err(fail)?;
        let member = usize::try_from(u64::from_le_bytes(word)).map_err(|_| damaged())?;
        self.input.read_exact(&mut word).map_err(fail)?;
        let len = usize::try_from(u64::from_le_bytes(word)).map_err(|_| damaged())?;
        line.clear();
        let read = (&mut self.input).take(len as u64).read_to_end(line).map_err(fail)?;
        if read != len || self.last.is_some_and(|last| member < last) {
            return Err(damaged());
        }
        self.last = Some(member);
        Ok(Some(member))
    }
}
