//! A sweep's end: in come the folder's earlier `sweep.csv` and `timing.csv` (member order) and
//! its journal (finish order); out go the new `sweep.csv` and `timing.csv`, each written to a
//! temporary file and renamed. Lines are copied, not parsed: only the journal's line positions
//! are held (24 bytes a member), so memory does not grow with the rows' width.

use std::fs::File;
use std::io::{BufWriter, Read, Seek, SeekFrom, Write};
use std::path::Path;

use super::journal::Entry;
use super::table::{record_bytes, RowLines};
use super::JOURNAL_FILE;

/// Writes `dir/sweep.csv` (columns `header`) and `dir/timing.csv`: the earlier rows and the
/// journal's `entries`, in member order, each member once (an earlier row wins).
pub fn finish(dir: &Path, header: &[String], mut entries: Vec<Entry>) -> Result<(), String> {
    entries.sort_by_key(|e| e.member);
    entries.dedup_by_key(|e| e.member);
    let journal_path = dir.join(JOURNAL_FILE);
    let journal = File::open(&journal_path).map_err(|e| format!("{}: {e}", journal_path.display()));
    let journal = if entries.is_empty() { None } else { Some(journal?) };
    let line = |e: &Entry| -> Result<(Vec<u8>, usize), String> {
        let file = journal.as_ref().ok_or("the journal is gone")?;
        let bytes = read_span(file, e).map_err(|err| format!("{}: {err}", journal_path.display()))?;
        // The wall time is the first cell, a plain number.
        let comma = bytes.iter().position(|b| *b == b',').ok_or("a journal line without cells")?;
        Ok((bytes, comma))
    };
    let rows = entries.iter().map(|e| line(e).map(|(b, comma)| (e.member, b[comma + 1..].to_vec())));
    write_merged(&dir.join("sweep.csv"), header, rows)?;
    let timing_header = ["member".to_string(), "wall_ms".to_string()];
    let walls = entries.iter().map(|e| {
        line(e).map(|(b, comma)| {
            let mut t = format!("{},", e.member).into_bytes();
            t.extend_from_slice(&b[..comma]);
            t.push(b'\n');
            (e.member, t)
        })
    });
    write_merged(&dir.join("timing.csv"), &timing_header, walls)
}

/// The bytes of a journal line.
fn read_span(mut file: &File, e: &Entry) -> std::io::Result<Vec<u8>> {
    let mut bytes = vec![0; usize::try_from(e.end - e.start).unwrap_or(0)];
    file.seek(SeekFrom::Start(e.start))?;
    file.read_exact(&mut bytes)?;
    Ok(bytes)
}

/// Rewrites the rows file `path` as its rows merged with `new` (member order), `header` first;
/// an error when its columns are not `header`.
fn write_merged(
    path: &Path,
    header: &[String],
    new: impl Iterator<Item = Result<(usize, Vec<u8>), String>>,
) -> Result<(), String> {
    let mut old = RowLines::open(path)?;
    if let Some(o) = &old {
        if o.header != header {
            return Err(format!(
                "{}: its columns are not this sweep's: give --new to start over",
                path.display()
            ));
        }
    }
    crate::output::write_atomically(path, |tmp| {
        let file = File::create(tmp).map_err(|e| format!("{}: {e}", tmp.display()))?;
        let mut w = BufWriter::new(file);
        let io = |e: std::io::Error| format!("{}: {e}", tmp.display());
        w.write_all(&record_bytes(header)?).map_err(io)?;
        let mut new = new.peekable();
        let mut next_old = match &mut old {
            Some(o) => o.next_row()?,
            None => None,
        };
        loop {
            let take_old = match (&next_old, new.peek()) {
                (None, None) => break,
                (Some((m, _)), Some(Ok((n, _)))) => m <= n,
                (Some(_), None) => true,
                _ => false,
            };
            if take_old {
                let (m, bytes) = next_old.take().ok_or("no row")?;
                w.write_all(&bytes).map_err(io)?;
                next_old = old.as_mut().map_or(Ok(None), RowLines::next_row)?;
                while new.peek().is_some_and(|r| r.as_ref().is_ok_and(|(n, _)| *n == m)) {
                    new.next();
                }
            } else {
                let (_, bytes) = new.next().ok_or("no row")??;
                w.write_all(&bytes).map_err(io)?;
            }
        }
        w.flush().map_err(io)
    })
}
