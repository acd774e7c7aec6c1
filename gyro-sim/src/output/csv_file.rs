//! The CSV of a run: `t`, then the columns, every output time.

use std::path::Path;

use super::{write_atomically, Table};

/// Writes `table` as CSV to `path` (atomically).
pub fn write_csv(table: &Table, path: &Path) -> Result<(), String> {
    write_atomically(path, |tmp| {
        let mut w = csv::Writer::from_path(tmp).map_err(|e| format!("{}: {e}", tmp.display()))?;
        let mut header = vec!["t".to_string()];
        header.extend(table.columns.iter().map(|c| c.name.clone()));
        w.write_record(&header).map_err(|e| e.to_string())?;
        for row in &table.rows {
            w.write_record(row.iter().map(|v| v.to_string())).map_err(|e| e.to_string())?;
        }
        w.flush().map_err(|e| e.to_string())
    })
}
