//! An output set whose CSV is written while the run goes: rows reach the disk as they are
//! produced (memory stays flat), the figures and the view are drawn from the run's bounded set
//! of kept rows at the end, and the whole set is put in place together. A run that fails keeps
//! the rows it computed as `trajectory.partial.csv` beside the earlier set, which it leaves alone.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use super::csv_file::CsvStream;
use super::display::display_table;
use super::set::{Staging, PARTIAL_CSV};
use super::write::finish_set;
use super::{WriteError, Written};
use crate::problem::RowStream;
use crate::problem::{Column, Trajectory};
use crate::scene::ViewSpec;

/// A set being written into a folder: its CSV open in the staging folder.
pub struct StreamedSet {
    dir: PathBuf,
    staging: Staging,
    csv: Arc<Mutex<CsvStream>>,
}

impl StreamedSet {
    /// Stages a set in `dir` (made if missing) and opens its CSV for a run's `columns`.
    pub fn begin(dir: &Path, columns: &[Column]) -> Result<StreamedSet, WriteError> {
        let staging = Staging::new(dir)?;
        let csv = CsvStream::create(&staging.path("trajectory.csv"), columns)?;
        Ok(StreamedSet { dir: dir.to_path_buf(), staging, csv: Arc::new(Mutex::new(csv)) })
    }

    /// Where the run sends its rows.
    pub fn stream(&self) -> RowStream {
        RowStream(self.csv.clone())
    }

    /// Closes the CSV; the rows it holds.
    fn close(&self) -> Result<usize, WriteError> {
        let mut csv = self.csv.lock().map_err(|_| WriteError::Poisoned)?;
        csv.finish()
    }

    /// Closes the CSV, writes the figures and the view from `trajectory`'s kept rows, and puts
    /// the set in place.
    pub fn finish(self, trajectory: &Trajectory, view: Option<&ViewSpec>) -> Result<Written, WriteError> {
        let rows = self.close()?;
        let table = display_table(trajectory);
        finish_set(self.staging, trajectory, &table, view, &self.dir, rows)
    }

    /// After a failed run: the rows written so far put in place as `trajectory.partial.csv`
    /// (the earlier set untouched), with their count; `None` when there were none.
    pub fn keep_partial(self) -> Result<Option<(PathBuf, usize)>, WriteError> {
        let rows = self.close()?;
        if rows == 0 {
            return Ok(None);
        }
        let path = self.staging.commit_one("trajectory.csv", PARTIAL_CSV)?;
        Ok(Some((path, rows)))
    }
}
