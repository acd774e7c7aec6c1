//! The CSV of a run: `t`, then the columns, every output time; written from a table at once, or
//! row by row while the run goes ([`CsvStream`]).

use std::fs::File;
use std::path::{Path, PathBuf};

use super::display::DisplayRows;
use super::{write_atomically, Table, WriteError};
use crate::problem::{RowError, RowSink};

/// Writes `table` as CSV to `path` (atomically).
pub fn write_csv(table: &Table, path: &Path) -> Result<(), WriteError> {
    write_atomically(path, |tmp| {
        let fail = |e: csv::Error| WriteError::csv(tmp, e);
        let mut w = csv::Writer::from_path(tmp).map_err(fail)?;
        w.write_record(header(table)).map_err(fail)?;
        for row in &table.rows {
            write_row(&mut w, row).map_err(fail)?;
        }
        w.flush().map_err(|e| WriteError::io(tmp, e))
    })
}

/// `t` and the columns' names.
fn header(table: &Table) -> Vec<String> {
    let mut header = vec!["t".to_string()];
    header.extend(table.columns.iter().map(|c| c.name.clone()));
    header
}

/// One row, each value as Rust prints it (the shortest text that reads back the same).
fn write_row<W: std::io::Write>(w: &mut csv::Writer<W>, row: &[f64]) -> Result<(), csv::Error> {
    w.write_record(row.iter().map(|v| v.to_string()))
}

/// A CSV written row by row as a run produces rows (model units in, display units out): the
/// same text [`write_csv`] writes for the same rows.
pub struct CsvStream {
    path: PathBuf,
    writer: Option<csv::Writer<File>>,
    display: DisplayRows,
    rows: usize,
}

impl CsvStream {
    /// Creates `path` with the header of `columns` (a run's columns, model units).
    pub(crate) fn create(path: &Path, columns: &[crate::problem::Column]) -> Result<CsvStream, WriteError> {
        let (display, shown) = DisplayRows::new(columns);
        let table = Table { title: String::new(), columns: shown, rows: Vec::new(), plot_rows: Vec::new() };
        let mut w = csv::Writer::from_path(path).map_err(|e| WriteError::csv(path, e))?;
        w.write_record(header(&table)).map_err(|e| WriteError::csv(path, e))?;
        Ok(CsvStream { path: path.to_path_buf(), writer: Some(w), display, rows: 0 })
    }

    /// Flushes and closes the file; the rows written.
    pub(crate) fn finish(&mut self) -> Result<usize, WriteError> {
        if let Some(mut w) = self.writer.take() {
            w.flush().map_err(|e| WriteError::io(&self.path, e))?;
        }
        Ok(self.rows)
    }
}

impl RowSink for CsvStream {
    fn row(&mut self, row: &[f64]) -> Result<(), RowError> {
        let closed = || WriteError::Closed { path: self.path.clone() };
        let w = self.writer.as_mut().ok_or_else(closed).map_err(RowError::sink)?;
        write_row(w, &self.display.row(row)).map_err(|e| RowError::sink(WriteError::csv(&self.path, e)))?;
        self.rows += 1;
        Ok(())
    }
}
