//! A running sweep's journal: in come finished members' rows, one at a time from any thread;
//! out goes `sweep.journal.csv` beside `sweep.csv`, one line per member appended and flushed as
//! soon as the member ends, so a killed sweep keeps every member it finished. The first line is
//! the sweep's fingerprint (`plan,fnv1a64:...`), the second the header; then each line is the
//! member's wall time in milliseconds and its `sweep.csv` cells. A line is complete once its
//! newline is written: a cut last line is dropped when the journal is opened again.

use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use super::SweepError;

/// The journal's file name in a sweep's folder.
pub const JOURNAL_FILE: &str = "sweep.journal.csv";

/// An open journal, appended to by finished members.
pub struct Journal {
    path: PathBuf,
    file: Mutex<File>,
}

/// Called with a member's index and its line's bytes (newline included).
pub type VisitLine<'a> = &'a mut dyn FnMut(usize, &[u8]) -> Result<(), SweepError>;

/// One journaled member: its index and where its line is in the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The member's index.
    pub member: usize,
    /// The line's first byte.
    pub start: u64,
    /// One past its newline.
    pub end: u64,
}

impl Journal {
    /// Opens (creating) the journal in `dir` of the sweep `fingerprint` whose rows carry
    /// `header`, passing each member line it holds to `visit`; an error when it holds another
    /// sweep's rows.
    pub fn open(
        dir: &Path,
        fingerprint: &str,
        header: &[String],
        visit: &mut dyn FnMut(Entry) -> Result<(), SweepError>,
    ) -> Result<Journal, SweepError> {
        let path = dir.join(JOURNAL_FILE);
        let fresh = !has_header(&path)?;
        if !fresh {
            scan(dir, fingerprint, header, visit)?;
        }
        let file =
            OpenOptions::new().create(true).append(true).open(&path).map_err(|e| SweepError::io(&path, e))?;
        let journal = Journal { path, file: Mutex::new(file) };
        if fresh {
            let mut line = vec!["wall_ms".to_string()];
            line.extend(header.iter().cloned());
            let mut head = super::table::record_bytes(&["plan".to_string(), fingerprint.to_string()])?;
            head.extend(super::table::record_bytes(&line)?);
            journal.write(&head)?;
        }
        Ok(journal)
    }

    /// Appends one member's `cells` and wall time, flushed before returning.
    pub fn record(&self, cells: &[String], wall_ms: f64) -> Result<(), SweepError> {
        let mut line = vec![format!("{wall_ms:.4}")];
        line.extend(cells.iter().cloned());
        self.append(&line)
    }

    /// Writes `line` as one CSV record in a single write.
    fn append(&self, line: &[String]) -> Result<(), SweepError> {
        self.write(&super::table::record_bytes(line)?)
    }

    /// Writes `bytes` in a single write, flushed.
    fn write(&self, bytes: &[u8]) -> Result<(), SweepError> {
        let mut file = self.file.lock().map_err(|_| SweepError::Poisoned)?;
        file.write_all(bytes).and_then(|()| file.flush()).map_err(|e| SweepError::io(&self.path, e))
    }

    /// Removes the journal (its rows are in `sweep.csv`).
    pub fn remove(self) -> Result<(), SweepError> {
        std::fs::remove_file(&self.path).map_err(|e| SweepError::io(&self.path, e))
    }
}

/// Whether the journal at `path` has its two first lines (plan and header) whole: after
/// cutting a half-written last line, a journal without them is emptied (a run killed as it began).
fn has_header(path: &Path) -> Result<bool, SweepError> {
    use std::io::BufRead;
    drop_cut_line(path)?;
    let Ok(file) = File::open(path) else { return Ok(false) };
    let mut lines = std::io::BufReader::new(file).split(b'\n');
    if lines.next().is_some() && lines.next().is_some() {
        return Ok(true);
    }
    let file = OpenOptions::new().write(true).open(path).map_err(|e| SweepError::io(path, e))?;
    file.set_len(0).map_err(|e| SweepError::io(path, e))?;
    Ok(false)
}

/// Cuts the journal at `path` back to its last complete line (a killed run's half-written line).
fn drop_cut_line(path: &Path) -> Result<(), SweepError> {
    use std::io::{Read, Seek, SeekFrom};
    let Ok(mut file) = OpenOptions::new().read(true).write(true).open(path) else { return Ok(()) };
    let fail = |e: std::io::Error| SweepError::io(path, e);
    let len = file.metadata().map_err(fail)?.len();
    let mut end = len;
    let mut chunk = vec![0u8; 1 << 16];
    // Back from the end, a chunk at a time, to the last newline.
    let complete = loop {
        if end == 0 {
            break 0;
        }
        let start = end.saturating_sub(chunk.len() as u64);
        let part = &mut chunk[..(end - start) as usize];
        file.seek(SeekFrom::Start(start)).and_then(|_| file.read_exact(part)).map_err(fail)?;
        if let Some(i) = part.iter().rposition(|b| *b == b'\n') {
            break start + i as u64 + 1;
        }
        end = start;
    };
    if complete < len {
        file.set_len(complete).map_err(fail)?;
    }
    Ok(())
}

/// The length of `file` up to its last byte when that is a newline, else one less (a cut line
/// then ends past it).
fn complete_length(mut file: &File) -> std::io::Result<u64> {
    use std::io::{Read, Seek, SeekFrom};
    let len = file.metadata()?.len();
    if len == 0 {
        return Ok(0);
    }
    let mut last = [0u8];
    file.seek(SeekFrom::Start(len - 1))?;
    file.read_exact(&mut last)?;
    file.seek(SeekFrom::Start(0))?;
    Ok(if last[0] == b'\n' { len } else { len - 1 })
}

/// Passes each complete member line of the journal in `dir` (none when there is none) to
/// `visit`, in the file's order, once it is checked to be of the sweep `fingerprint` with
/// `header`; how many there were.
pub fn scan(
    dir: &Path,
    fingerprint: &str,
    header: &[String],
    visit: &mut dyn FnMut(Entry) -> Result<(), SweepError>,
) -> Result<usize, SweepError> {
    let path = dir.join(JOURNAL_FILE);
    let file = match File::open(&path) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(0),
        Err(e) => return Err(SweepError::io(&path, e)),
    };
    let complete = complete_length(&file).map_err(|e| SweepError::io(&path, e))?;
    let mut r = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_reader(std::io::BufReader::new(file));
    let mut rec = csv::ByteRecord::new();
    let read = |r: &mut csv::Reader<std::io::BufReader<File>>, rec: &mut csv::ByteRecord| {
        r.read_byte_record(rec).map_err(|source| SweepError::JournalRead { path: path.clone(), source })
    };
    let plan_line = [b"plan".as_slice(), fingerprint.as_bytes()];
    if read(&mut r, &mut rec)? && !rec.iter().eq(plan_line) {
        return Err(SweepError::OtherJournal { path: path.clone() });
    }
    let wanted = std::iter::once("wall_ms").chain(header.iter().map(String::as_str)).map(str::as_bytes);
    if read(&mut r, &mut rec)? && !rec.iter().eq(wanted) {
        return Err(SweepError::OtherColumns { path: path.clone() });
    }
    let mut count = 0;
    loop {
        let start = r.position().byte();
        if !read(&mut r, &mut rec)? {
            break;
        }
        let end = r.position().byte();
        let member = std::str::from_utf8(rec.get(1).unwrap_or_default()).ok().and_then(|m| m.parse().ok());
        match member {
            Some(member) if rec.len() == header.len() + 1 && end <= complete => {
                visit(Entry { member, start, end })?;
                count += 1;
            }
            _ if end >= complete => break, // a line still being written
            _ => {
                return Err(SweepError::DamagedJournal { path: path.clone(), cells: rec.len(), byte: start })
            }
        }
    }
    Ok(count)
}

/// Passes each complete member line of the journal in `dir`, as [`scan`] finds them, to `visit`
/// with its bytes (newline included), read in one forward pass; how many there were.
pub fn scan_lines(
    dir: &Path,
    fingerprint: &str,
    header: &[String],
    visit: VisitLine<'_>,
) -> Result<usize, SweepError> {
    use std::io::Read;
    let path = dir.join(JOURNAL_FILE);
    let fail = |e: std::io::Error| SweepError::io(&path, e);
    // The journal read forward a second time, and the byte it is at.
    let mut second: Option<(std::io::BufReader<File>, u64)> = None;
    let mut line = Vec::new();
    scan(dir, fingerprint, header, &mut |e| {
        let (reader, at) = match &mut second {
            Some(open) => open,
            None => second.insert((std::io::BufReader::new(File::open(&path).map_err(fail)?), 0)),
        };
        let skip = e.start.checked_sub(*at).and_then(|n| i64::try_from(n).ok());
        let skip = skip.ok_or_else(|| SweepError::JournalOrder { path: path.clone() })?;
        reader.seek_relative(skip).map_err(fail)?;
        line.resize(usize::try_from(e.end - e.start).unwrap_or(0), 0);
        reader.read_exact(&mut line).map_err(fail)?;
        *at = e.end;
        visit(e.member, &line)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header() -> Vec<String> {
        ["member", "Y", "status"].map(String::from).to_vec()
    }

    /// The journal's member lines as `scan` finds them.
    fn entries(dir: &Path, header: &[String]) -> Result<Vec<Entry>, SweepError> {
        let mut out = Vec::new();
        let n = scan(dir, "fp", header, &mut |e| {
            out.push(e);
            Ok(())
        })?;
        assert_eq!(n, out.len());
        Ok(out)
    }

    #[test]
    fn complete_lines_survive_and_a_cut_last_line_is_dropped() {
        let dir = std::env::temp_dir().join(format!("journal-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let _ = std::fs::remove_file(dir.join(JOURNAL_FILE));
        let j = Journal::open(&dir, "fp", &header(), &mut |_| Ok(())).unwrap();
        j.record(&["0".into(), "1.5".into(), "ok".into()], 2.0).unwrap();
        j.record(&["1".into(), "2.5".into(), "a, \"quoted\" failure".into()], 3.0).unwrap();
        drop(j);
        // A kill in the middle of a line: its bytes without the newline.
        let mut f = OpenOptions::new().append(true).open(dir.join(JOURNAL_FILE)).unwrap();
        f.write_all(b"4.0000,2,3.5,o").unwrap();
        let text = std::fs::read_to_string(dir.join(JOURNAL_FILE)).unwrap();
        let found = entries(&dir, &header()).unwrap();
        assert_eq!(found.iter().map(|e| e.member).collect::<Vec<_>>(), [0, 1]);
        let line = &text[found[1].start as usize..found[1].end as usize];
        assert_eq!(line, "3.0000,1,2.5,\"a, \"\"quoted\"\" failure\"\n");
        let mut lines = Vec::new();
        let n = scan_lines(&dir, "fp", &header(), &mut |m, l| {
            lines.push((m, l.to_vec()));
            Ok(())
        });
        assert_eq!(n.unwrap(), 2);
        let want: Vec<(usize, Vec<u8>)> = found
            .iter()
            .map(|e| (e.member, text.as_bytes()[e.start as usize..e.end as usize].to_vec()))
            .collect();
        assert_eq!(lines, want);
        let other = ["member", "Z", "status"].map(String::from);
        assert!(entries(&dir, &other).unwrap_err().to_string().contains("columns are not this sweep's"));
        let refused = Journal::open(&dir, "other", &header(), &mut |_| Ok(()));
        assert!(refused.is_err_and(|e| e.to_string().contains("another sweep's journal")));
        // Reopening drops the cut line, so the next record starts a line of its own.
        let mut held = 0;
        let j = Journal::open(&dir, "fp", &header(), &mut |_| {
            held += 1;
            Ok(())
        });
        let j = j.unwrap();
        assert_eq!(held, 2);
        j.record(&["2".into(), "3.5".into(), "ok".into()], 4.0).unwrap();
        let members: Vec<usize> = entries(&dir, &header()).unwrap().iter().map(|e| e.member).collect();
        assert_eq!(members, [0, 1, 2]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
