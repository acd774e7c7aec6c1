//! A sweep's rows on disk: in come rows; out go their CSV cells, one line per member in member
//! order, and the lines read back one at a time for resuming and merging. Numbers are written in
//! Rust's shortest round-trip form, so the same inputs give the same bytes.

use std::path::Path;

use super::SweepError;

/// One member's row.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepRow {
    /// The member's index.
    pub member: usize,
    /// The varied values, in the ranges' order and units.
    pub varied: Vec<f64>,
    /// `ok`, or the failure named.
    pub status: String,
    /// Final values, then minima, then maxima of the written columns (empty on failure).
    pub values: Vec<f64>,
    /// Accepted steps.
    pub steps: usize,
    /// Right-hand-side evaluations.
    pub rhs_evals: usize,
}

/// The header: `member`, the varied names, `status`, `steps`, `rhs_evals`, the value columns.
pub fn header(varied: &[String], value_columns: &[String]) -> Vec<String> {
    let mut h = vec!["member".to_string()];
    h.extend(varied.iter().cloned());
    h.extend(["status", "steps", "rhs_evals"].map(String::from));
    h.extend(value_columns.iter().cloned());
    h
}

/// A row's cells for the CSV (values empty when it failed).
pub fn cells(row: &SweepRow, n_values: usize) -> Vec<String> {
    let mut c = vec![row.member.to_string()];
    c.extend(row.varied.iter().map(|v| v.to_string()));
    c.extend([row.status.clone(), row.steps.to_string(), row.rhs_evals.to_string()]);
    if row.values.is_empty() {
        c.extend(std::iter::repeat_n(String::new(), n_values));
    } else {
        c.extend(row.values.iter().map(|v| v.to_string()));
    }
    c
}

/// The header and rows of a `sweep.csv` (empty when the file does not exist).
pub fn read_rows(path: &Path) -> Result<(Vec<String>, Vec<Vec<String>>), SweepError> {
    if !path.exists() {
        return Ok((Vec::new(), Vec::new()));
    }
    let fail = |e: csv::Error| SweepError::csv(path, e);
    let mut r = csv::Reader::from_path(path).map_err(fail)?;
    let header: Vec<String> = r.headers().map_err(fail)?.iter().map(String::from).collect();
    let mut rows = Vec::new();
    for rec in r.records() {
        let rec = rec.map_err(fail)?;
        rows.push(rec.iter().map(String::from).collect());
    }
    Ok((header, rows))
}

/// A sorted rows file (`sweep.csv`, `timing.csv`) read one line at a time: its header, then each
/// row's member and bytes (its newline included).
pub struct RowLines {
    path: std::path::PathBuf,
    reader: std::io::BufReader<std::fs::File>,
    /// The file's column names.
    pub header: Vec<String>,
    last: Option<usize>,
}

impl RowLines {
    /// Opens `path` and reads its header; `None` when there is no such file.
    pub fn open(path: &Path) -> Result<Option<RowLines>, SweepError> {
        use std::io::BufRead;
        let file = match std::fs::File::open(path) {
            Ok(f) => f,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(SweepError::io(path, e)),
        };
        let mut reader = std::io::BufReader::new(file);
        let mut first = Vec::new();
        reader.read_until(b'\n', &mut first).map_err(|e| SweepError::io(path, e))?;
        let mut r = csv::ReaderBuilder::new().has_headers(false).from_reader(first.as_slice());
        let header = match r.records().next() {
            Some(rec) => rec.map_err(|e| SweepError::csv(path, e))?.iter().map(String::from).collect(),
            None => Vec::new(),
        };
        Ok(Some(RowLines { path: path.to_path_buf(), reader, header, last: None }))
    }

    /// The next row's member and line; an error when rows are out of member order.
    pub fn next_row(&mut self) -> Result<Option<(usize, Vec<u8>)>, SweepError> {
        use std::io::BufRead;
        let mut line = Vec::new();
        let n = self.reader.read_until(b'\n', &mut line).map_err(|e| SweepError::io(&self.path, e))?;
        if n == 0 {
            return Ok(None);
        }
        if !line.ends_with(b"\n") {
            line.push(b'\n');
        }
        let first = line.split(|b| *b == b',' || *b == b'\n').next().unwrap_or_default();
        let member = std::str::from_utf8(first).ok().and_then(|m| m.trim().parse::<usize>().ok());
        match member {
            Some(m) if self.last.is_none_or(|last| m > last) => {
                self.last = Some(m);
                Ok(Some((m, line)))
            }
            Some(member) => Err(SweepError::RowOrder {
                path: self.path.clone(),
                member,
                after: self.last.unwrap_or_default(),
            }),
            None => Err(SweepError::NoMember {
                path: self.path.clone(),
                line: String::from_utf8_lossy(&line).trim_end().to_string(),
            }),
        }
    }
}

/// One CSV record's bytes (newline included), as the rows files write it.
pub fn record_bytes(cells: &[String]) -> Result<Vec<u8>, SweepError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(cells).map_err(SweepError::Record)?;
    w.into_inner().map_err(|e| SweepError::Record(e.into_error().into()))
}
