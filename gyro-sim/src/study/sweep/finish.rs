//! A sweep's end: in come the folder's earlier `sweep.csv` and `timing.csv` (member order) and
//! its journal (finish order); out go the new `sweep.csv` and `timing.csv`, each written to a
//! temporary file and renamed. Lines are copied, not parsed, and put in member order by an
//! external sort ([`SortedRuns`]), so memory does not grow with the members or the rows.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use super::sorted_runs::{SortedRuns, FAN_IN, RUN_BUDGET};
use super::table::{record_bytes, RowLines};
use super::{SweepError, JOURNAL_FILE};

/// Writes `dir/sweep.csv` (columns `header`) and `dir/timing.csv`: the earlier rows and the
/// lines of the journal of the sweep `fingerprint`, in member order, each member once (an
/// earlier row wins, then the member's first line in the journal).
pub fn finish(dir: &Path, fingerprint: &str, header: &[String]) -> Result<(), SweepError> {
    finish_within(dir, fingerprint, header, RUN_BUDGET, FAN_IN)
}

/// [`finish`], sorting the journal with buffers of `budget` bytes, `fan_in` runs merged at once.
fn finish_within(
    dir: &Path,
    fingerprint: &str,
    header: &[String],
    budget: usize,
    fan_in: usize,
) -> Result<(), SweepError> {
    let mut runs = SortedRuns::new(dir, budget, fan_in)?;
    super::journal::scan_lines(dir, fingerprint, header, &mut |m, line| runs.push(m, line))?;
    let journal = dir.join(JOURNAL_FILE);
    // The wall time is the first cell, a plain number.
    let split = |line: &[u8]| {
        let comma = line.iter().position(|b| *b == b',');
        comma.ok_or_else(|| SweepError::JournalLine { path: journal.clone() })
    };
    let row = |_: usize, line: &[u8], out: &mut Vec<u8>| {
        out.extend_from_slice(&line[split(line)? + 1..]);
        Ok(())
    };
    write_merged(&dir.join("sweep.csv"), header, &mut runs, &row)?;
    let timing_header = ["member".to_string(), "wall_ms".to_string()];
    let wall = |member: usize, line: &[u8], out: &mut Vec<u8>| {
        out.extend_from_slice(format!("{member},").as_bytes());
        out.extend_from_slice(&line[..split(line)?]);
        out.push(b'\n');
        Ok(())
    };
    write_merged(&dir.join("timing.csv"), &timing_header, &mut runs, &wall)
}

/// How a journal line becomes a row of a rows file: appended to the buffer given.
type RowOf<'a> = &'a dyn Fn(usize, &[u8], &mut Vec<u8>) -> Result<(), SweepError>;

/// Rewrites the rows file `path` as its rows merged with the rows `row` makes of the sorted
/// journal lines `runs` (member order; an earlier row of a member wins), `header` first; an
/// error when its columns are not `header`.
fn write_merged(
    path: &Path,
    header: &[String],
    runs: &mut SortedRuns,
    row: RowOf<'_>,
) -> Result<(), SweepError> {
    let mut old = RowLines::open(path)?;
    if let Some(o) = &old {
        if o.header != header {
            return Err(SweepError::OtherColumns { path: path.to_path_buf() });
        }
    }
    crate::output::write_atomically(path, |tmp| {
        let io = |e: std::io::Error| SweepError::io(tmp, e);
        let mut w = BufWriter::new(File::create(tmp).map_err(io)?);
        w.write_all(&record_bytes(header)?).map_err(io)?;
        let mut next_old = old.as_mut().map_or(Ok(None), RowLines::next_row)?;
        let mut bytes = Vec::new();
        runs.merge(&mut |m, line| {
            while let Some((o, earlier)) = next_old.take_if(|(o, _)| *o <= m) {
                w.write_all(&earlier).map_err(io)?;
                next_old = old.as_mut().map_or(Ok(None), RowLines::next_row)?;
                if o == m {
                    return Ok(());
                }
            }
            bytes.clear();
            row(m, line, &mut bytes)?;
            w.write_all(&bytes).map_err(io)
        })?;
        while let Some((_, earlier)) = next_old.take() {
            w.write_all(&earlier).map_err(io)?;
            next_old = old.as_mut().map_or(Ok(None), RowLines::next_row)?;
        }
        w.flush().map_err(io)
    })
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;
    use std::path::PathBuf;

    use super::*;
    use crate::study::sweep::Journal;

    fn header() -> Vec<String> {
        ["member", "Y", "status"].map(String::from).to_vec()
    }

    /// An empty folder for the test case `name`.
    fn folder(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("finish-test-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// The names of the hidden temporaries left in `dir`.
    fn leftovers(dir: &Path) -> Vec<String> {
        let names =
            std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned());
        names.filter(|n| n.starts_with(".partial-")).collect()
    }

    /// A file of `header` and `rows`, in order.
    fn rows_file(header: &str, rows: impl Iterator<Item = String>) -> String {
        std::iter::once(header.to_string()).chain(rows).collect()
    }

    #[test]
    fn an_external_sort_writes_what_an_in_memory_sort_writes() {
        for (budget, fan_in) in [(1, 2), (300, 3), (4096, 5), (RUN_BUDGET, FAN_IN)] {
            let dir = folder(&format!("{budget}-{fan_in}"));
            // Earlier rows (every 7th member, some past the journal's): they win over the journal's.
            let earlier: BTreeMap<usize, (String, String)> = (0..700)
                .step_by(7)
                .map(|m| (m, (format!("{m},earlier,ok\n"), format!("{m},1.0000\n"))))
                .collect();
            std::fs::write(
                dir.join("sweep.csv"),
                rows_file("member,Y,status\n", earlier.values().map(|r| r.0.clone())),
            )
            .unwrap();
            let timing = rows_file("member,wall_ms\n", earlier.values().map(|r| r.1.clone()));
            std::fs::write(dir.join("timing.csv"), timing).unwrap();
            let (mut rows, mut walls) = (BTreeMap::new(), BTreeMap::new());
            let journal = Journal::open(&dir, "fp", &header(), &mut |_| Ok(())).unwrap();
            let mut x: u64 = 0x2545_f491_4f6c_dd1d;
            for k in 0..2000 {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                // Members in shuffled order, many journaled more than once: the first line wins.
                let m = (x % 600) as usize;
                let status = if k % 5 == 0 { "a, \"quoted\" failure" } else { "ok" };
                let cells = [m.to_string(), format!("{k}.5"), status.to_string()];
                journal.record(&cells, k as f64 * 0.25).unwrap();
                rows.entry(m).or_insert_with(|| String::from_utf8(record_bytes(&cells).unwrap()).unwrap());
                walls.entry(m).or_insert_with(|| format!("{m},{:.4}\n", k as f64 * 0.25));
            }
            for (m, (row, wall)) in earlier {
                rows.insert(m, row);
                walls.insert(m, wall);
            }
            finish_within(&dir, "fp", &header(), budget, fan_in).unwrap();
            let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
            assert_eq!(
                read("sweep.csv"),
                rows_file("member,Y,status\n", rows.into_values()),
                "budget {budget}"
            );
            assert_eq!(
                read("timing.csv"),
                rows_file("member,wall_ms\n", walls.into_values()),
                "budget {budget}"
            );
            assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }

    #[test]
    fn run_files_go_on_success_and_on_failure_and_a_stale_one_is_not_read() {
        let dir = folder("stale");
        let journal = Journal::open(&dir, "fp", &header(), &mut |_| Ok(())).unwrap();
        for m in [3, 1, 2] {
            journal.record(&[m.to_string(), "1.5".into(), "ok".into()], 2.0).unwrap();
        }
        // A killed sort's run, in the run format: member 0's line.
        let line = b"9.0000,0,stale,ok\n";
        let stale = [&0u64.to_le_bytes()[..], &(line.len() as u64).to_le_bytes(), line].concat();
        std::fs::write(dir.join(".partial-1-0000000000000000-sweep.run"), stale).unwrap();
        finish_within(&dir, "fp", &header(), 1, 2).unwrap();
        let text = std::fs::read_to_string(dir.join("sweep.csv")).unwrap();
        assert_eq!(text, "member,Y,status\n1,1.5,ok\n2,1.5,ok\n3,1.5,ok\n");
        assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
        // Another sweep's rows: refused once the runs are made, and they are removed.
        std::fs::write(dir.join("sweep.csv"), "member,Z,status\n").unwrap();
        let e = finish_within(&dir, "fp", &header(), 1, 2).unwrap_err().to_string();
        assert!(e.contains("sweep.csv: its columns are not this sweep's"), "{e}");
        assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
