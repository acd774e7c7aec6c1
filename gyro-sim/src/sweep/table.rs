//! A sweep's rows on disk: in come rows (or shard folders); out goes `sweep.csv`, one line per
//! member in member order, written to a temporary file and renamed (so a killed run leaves the
//! old file or the new one), and read back for resuming and merging. Numbers are written in
//! Rust's shortest round-trip form, so the same inputs give the same bytes.

use std::path::Path;

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

/// Writes `header` and `rows` (cells) to `path` through a temporary file and a rename.
pub fn write_rows(path: &Path, header: &[String], rows: &[Vec<String>]) -> Result<(), String> {
    crate::output::write_atomically(path, |tmp| {
        let mut w = csv::Writer::from_path(tmp).map_err(|e| format!("{}: {e}", tmp.display()))?;
        w.write_record(header).map_err(|e| e.to_string())?;
        for r in rows {
            w.write_record(r).map_err(|e| e.to_string())?;
        }
        w.flush().map_err(|e| e.to_string())
    })
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
pub fn read_rows(path: &Path) -> Result<(Vec<String>, Vec<Vec<String>>), String> {
    if !path.exists() {
        return Ok((Vec::new(), Vec::new()));
    }
    let mut r = csv::Reader::from_path(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let header: Vec<String> =
        r.headers().map_err(|e| format!("{}: {e}", path.display()))?.iter().map(String::from).collect();
    let mut rows = Vec::new();
    for rec in r.records() {
        let rec = rec.map_err(|e| format!("{}: {e}", path.display()))?;
        rows.push(rec.iter().map(String::from).collect());
    }
    Ok((header, rows))
}

/// The member index of a row's cells.
pub fn member_of(row: &[String]) -> Option<usize> {
    row.first()?.parse().ok()
}

/// Joins the `sweep.csv` of each folder into `out/sweep.csv`, in member order; an error when
/// their headers differ or a member is in two of them.
pub fn merge(shards: &[&Path], out: &Path) -> Result<usize, String> {
    let mut header: Option<Vec<String>> = None;
    let mut rows: Vec<Vec<String>> = Vec::new();
    for dir in shards {
        let path = dir.join("sweep.csv");
        if !path.exists() {
            return Err(format!("{}: no sweep.csv (is it a shard's --out folder?)", dir.display()));
        }
        let (h, r) = read_rows(&path)?;
        match &header {
            Some(known) if *known != h => {
                return Err(format!(
                    "{}: its columns differ from the first shard's (another sweep?)",
                    path.display()
                ))
            }
            _ => header = Some(h),
        }
        rows.extend(r);
    }
    rows.sort_by_key(|r| member_of(r));
    if let Some(w) = rows.windows(2).find(|w| member_of(&w[0]) == member_of(&w[1])) {
        return Err(format!("member {} is in two shards", w[0][0]));
    }
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    write_rows(&out.join("sweep.csv"), &header.unwrap_or_default(), &rows)?;
    Ok(rows.len())
}
