//! A running sweep's journal: in come finished members' rows, one at a time from any thread;
//! out goes `sweep.journal.csv` beside `sweep.csv`, one line per member appended and flushed as
//! soon as the member ends, so a killed sweep keeps every member it finished. A line is complete
//! once its newline is written: reading keeps only complete lines. Each line is the member's
//! wall time in milliseconds, then its `sweep.csv` cells.

use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The journal's file name in a sweep's folder.
pub const JOURNAL_FILE: &str = "sweep.journal.csv";

/// An open journal, appended to by finished members.
pub struct Journal {
    path: PathBuf,
    file: Mutex<File>,
}

/// The rows a journal holds: each member's cells and wall time (ms).
pub type Journaled = Vec<(Vec<String>, f64)>;

impl Journal {
    /// Opens (creating) the journal in `dir`, whose rows carry `header`; an error when it holds
    /// another sweep's rows.
    pub fn open(dir: &Path, header: &[String]) -> Result<Journal, String> {
        let path = dir.join(JOURNAL_FILE);
        drop_cut_line(&path)?;
        let fresh = std::fs::metadata(&path).map(|m| m.len() == 0).unwrap_or(true);
        let file = OpenOptions::new()
            .create(true)
            .append(true)
            .open(&path)
            .map_err(|e| format!("{}: {e}", path.display()))?;
        let journal = Journal { path, file: Mutex::new(file) };
        if fresh {
            let mut line = vec!["wall_ms".to_string()];
            line.extend(header.iter().cloned());
            journal.append(&line)?;
        }
        Ok(journal)
    }

    /// Appends one member's `cells` and wall time, flushed before returning.
    pub fn record(&self, cells: &[String], wall_ms: f64) -> Result<(), String> {
        let mut line = vec![format!("{wall_ms:.4}")];
        line.extend(cells.iter().cloned());
        self.append(&line)
    }

    /// Writes `line` as one CSV record in a single write.
    fn append(&self, line: &[String]) -> Result<(), String> {
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(line).map_err(|e| e.to_string())?;
        let bytes = w.into_inner().map_err(|e| e.to_string())?;
        let mut file = self.file.lock().map_err(|_| "the sweep journal's lock is poisoned".to_string())?;
        file.write_all(&bytes)
            .and_then(|()| file.flush())
            .map_err(|e| format!("{}: {e}", self.path.display()))
    }

    /// Removes the journal (its rows are in `sweep.csv`).
    pub fn remove(self) -> Result<(), String> {
        std::fs::remove_file(&self.path).map_err(|e| format!("{}: {e}", self.path.display()))
    }
}

/// Cuts the journal at `path` back to its last complete line (a killed run's half-written line).
fn drop_cut_line(path: &Path) -> Result<(), String> {
    let Ok(bytes) = std::fs::read(path) else { return Ok(()) };
    let complete = bytes.iter().rposition(|b| *b == b'\n').map_or(0, |i| i + 1);
    if complete == bytes.len() {
        return Ok(());
    }
    let file = OpenOptions::new().write(true).open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    file.set_len(complete as u64).map_err(|e| format!("{}: {e}", path.display()))
}

/// The complete rows of the journal in `dir` whose header is `header`: none when there is no
/// journal, an error when it belongs to another sweep.
pub fn read_journal(dir: &Path, header: &[String]) -> Result<Journaled, String> {
    let path = dir.join(JOURNAL_FILE);
    let Ok(text) = std::fs::read_to_string(&path) else { return Ok(Vec::new()) };
    let complete = &text[..text.rfind('\n').map_or(0, |i| i + 1)];
    let mut r = csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(complete.as_bytes());
    let mut records = r.records();
    match records.next() {
        None => return Ok(Vec::new()),
        Some(first) => {
            let first = first.map_err(|e| format!("{}: {e}", path.display()))?;
            if first.iter().skip(1).ne(header.iter().map(String::as_str)) {
                return Err(format!(
                    "{} belongs to another sweep (other columns): give another --out or remove it",
                    path.display()
                ));
            }
        }
    }
    let mut rows = Vec::new();
    for rec in records {
        let rec = rec.map_err(|e| format!("{}: {e}", path.display()))?;
        let cells: Vec<String> = rec.iter().map(String::from).collect();
        let wall = cells.first().and_then(|w| w.parse::<f64>().ok());
        match wall {
            Some(ms) if cells.len() == header.len() + 1 => rows.push((cells[1..].to_vec(), ms)),
            _ => return Err(format!("{}: a damaged line ({} cells)", path.display(), cells.len())),
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header() -> Vec<String> {
        ["member", "Y", "status"].map(String::from).to_vec()
    }

    #[test]
    fn complete_lines_survive_and_a_cut_last_line_is_dropped() {
        let dir = std::env::temp_dir().join(format!("journal-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let _ = std::fs::remove_file(dir.join(JOURNAL_FILE));
        let j = Journal::open(&dir, &header()).unwrap();
        j.record(&["0".into(), "1.5".into(), "ok".into()], 2.0).unwrap();
        j.record(&["1".into(), "2.5".into(), "a, \"quoted\" failure".into()], 3.0).unwrap();
        drop(j);
        // A kill in the middle of a line: its bytes without the newline.
        let mut f = OpenOptions::new().append(true).open(dir.join(JOURNAL_FILE)).unwrap();
        f.write_all(b"4.0000,2,3.5,o").unwrap();
        let rows = read_journal(&dir, &header()).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[1].0[2], "a, \"quoted\" failure");
        assert_eq!(rows[0].1, 2.0);
        let other = ["member", "Z", "status"].map(String::from);
        assert!(read_journal(&dir, &other).unwrap_err().contains("another sweep"));
        // Reopening drops the cut line, so the next record starts a line of its own.
        let j = Journal::open(&dir, &header()).unwrap();
        j.record(&["2".into(), "3.5".into(), "ok".into()], 4.0).unwrap();
        let rows = read_journal(&dir, &header()).unwrap();
        assert_eq!(rows.iter().map(|r| r.0[0].as_str()).collect::<Vec<_>>(), ["0", "1", "2"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
