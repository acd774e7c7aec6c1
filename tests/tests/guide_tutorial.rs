//! docs/tutorial.md, followed as a reader would: every command of its `sh` blocks is run in a
//! temporary folder holding docs/tutorial/'s files, every output it shows is compared with the
//! command's own, every file it shows with docs/tutorial/, and the facts its prose states about
//! the runs are checked against what the runs wrote.
//!
//! Markers on the line above a fenced block say what the block is:
//! - `<!-- file: NAME -->`: the whole of docs/tutorial/NAME;
//! - `<!-- part: NAME -->`: the next part of NAME (its parts, joined by blank lines, are the file);
//! - `<!-- diff: OLD NEW -->`: a unified diff that turns OLD into NEW;
//! - `<!-- output -->`: what the last command printed (stdout, then stderr), where a line `...`
//!   stands for any lines and `...` inside a line for any text.
//!
//! An unmarked `sh` block is commands, one a line; `# exits with status N` after a command
//! gives its exit status (0 otherwise).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use kane_tests::bins;

/// The tutorial's setup lines, which the test does not run: it builds and finds the binaries
/// itself and works in a temporary folder.
const SETUP: &[&str] = &[
    "cargo build --release -p kane-model --bin kane -p gyro-sim --bin gyro-sim",
    "export PATH=\"$PWD/target/release:$PATH\"",
    "mkdir ~/gimbal && cd ~/gimbal",
];

/// A fenced block of the page: the marker above it, its language, its text and its first line.
struct Block {
    marker: Option<String>,
    lang: String,
    text: String,
    line: usize,
}

/// A temporary folder holding a copy of docs/tutorial/, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new() -> Scratch {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap().as_nanos();
        let dir = std::env::temp_dir().join(format!("guide-tutorial-{}-{nanos}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create the temporary folder");
        for (name, text) in tutorial_files() {
            std::fs::write(dir.join(name), text).expect("copy a tutorial file");
        }
        Scratch(dir)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs")
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("read {}: {e}", path.display()))
}

/// docs/tutorial/'s files by name.
fn tutorial_files() -> BTreeMap<String, String> {
    let dir = docs().join("tutorial");
    let entries = std::fs::read_dir(&dir).expect("docs/tutorial/");
    entries
        .map(|e| e.expect("a folder entry").path())
        .filter(|p| p.is_file())
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), read(&p)))
        .collect()
}

/// The fenced blocks of `page`, indented ones (in list items) with their indentation removed.
fn blocks(page: &str) -> Vec<Block> {
    let lines: Vec<&str> = page.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let indent = lines[i].len() - lines[i].trim_start().len();
        let Some(lang) = lines[i].trim_start().strip_prefix("```") else {
            i += 1;
            continue;
        };
        let marker = i.checked_sub(1).and_then(|j| {
            let above = lines[j].trim();
            above.strip_prefix("<!--")?.strip_suffix("-->").map(|m| m.trim().to_string())
        });
        let end = (i + 1..lines.len())
            .find(|&j| lines[j].trim_start().starts_with("```"))
            .unwrap_or_else(|| panic!("the block at line {} is not closed", i + 1));
        let text = lines[i + 1..end].iter().map(|l| format!("{}\n", l.get(indent..).unwrap_or(""))).collect();
        out.push(Block { marker, lang: lang.trim().to_string(), text, line: i + 1 });
        i = end + 1;
    }
    out
}

/// A command line's words (spaces separate, double quotes group) and its `#` comment.
fn words(line: &str) -> (Vec<String>, Option<String>) {
    let (mut words, mut word, mut quoted, mut any) = (Vec::new(), String::new(), false, false);
    for (i, c) in line.char_indices() {
        match c {
            '"' => (quoted, any) = (!quoted, true),
            '#' if !quoted => {
                if any {
                    words.push(word);
                }
                return (words, Some(line[i + 1..].trim().to_string()));
            }
            c if c.is_whitespace() && !quoted => {
                if any {
                    words.push(std::mem::take(&mut word));
                }
                any = false;
            }
            c => {
                word.push(c);
                any = true;
            }
        }
    }
    if any {
        words.push(word);
    }
    (words, None)
}

/// Runs one command line of the tutorial in `dir`: its output, stdout then stderr, checked to
/// exit with the status its comment gives (0 without one).
fn run(line: &str, dir: &Path) -> String {
    let (words, comment) = words(line);
    let status = comment
        .as_deref()
        .and_then(|c| c.strip_prefix("exits with status "))
        .map_or(0, |n| n.trim().parse::<i32>().expect("a status number"));
    let binary = match words[0].as_str() {
        "kane" => bins::kane(),
        "gyro-sim" => bins::gyro_sim(),
        "head" => return head(&words[1..], dir),
        other => panic!("the tutorial runs `{other}`, which this test cannot run: {line}"),
    };
    let out = Command::new(binary).args(&words[1..]).current_dir(dir).output().expect("run the command");
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(status),
        "`{line}` exited with {:?}, not {status}:\n{text}",
        out.status
    );
    text
}

/// `head -n N FILE`.
fn head(args: &[String], dir: &Path) -> String {
    let [flag, n, file] = args else { panic!("head takes -n N FILE: {args:?}") };
    assert_eq!(flag, "-n", "head takes -n N FILE");
    let n: usize = n.parse().expect("a line count");
    read(&dir.join(file)).lines().take(n).map(|l| format!("{l}\n")).collect()
}

/// Whether `line` matches `pattern`, where `...` stands for any text.
fn line_matches(pattern: &str, line: &str) -> bool {
    let pieces: Vec<&str> = pattern.split("...").collect();
    let (first, last) = (pieces[0], pieces[pieces.len() - 1]);
    if pieces.len() == 1 {
        return pattern == line;
    }
    if !line.starts_with(first) || line.len() < first.len() + last.len() || !line.ends_with(last) {
        return false;
    }
    let mut rest = &line[first.len()..line.len() - last.len()];
    for piece in &pieces[1..pieces.len() - 1] {
        match rest.find(piece) {
            Some(at) => rest = &rest[at + piece.len()..],
            None => return false,
        }
    }
    true
}

/// Whether the shown lines are the output's, abridged: a line `...` stands for any lines.
fn abridges(shown: &[&str], output: &[&str]) -> bool {
    match shown.split_first() {
        None => output.is_empty(),
        Some((&"...", rest)) => (0..=output.len()).any(|skip| abridges(rest, &output[skip..])),
        Some((first, rest)) => {
            output.first().is_some_and(|line| line_matches(first, line)) && abridges(rest, &output[1..])
        }
    }
}

/// `old` with the unified diff `diff` applied, each hunk at its stated line, context checked.
fn patched(old: &str, diff: &str) -> String {
    let old: Vec<&str> = old.lines().collect();
    let (mut out, mut at, mut in_hunk) = (Vec::new(), 0, false);
    for line in diff.lines() {
        if let Some(header) = line.strip_prefix("@@ -") {
            let start: usize = header.split([',', ' ']).next().unwrap().parse().expect("a hunk's line");
            let start = start.saturating_sub(1);
            assert!(start >= at, "hunks out of order at `{line}`");
            out.extend_from_slice(&old[at..start]);
            (at, in_hunk) = (start, true);
        } else if !in_hunk {
            assert!(line.starts_with("--- ") || line.starts_with("+++ "), "not a diff header: `{line}`");
        } else if let Some(added) = line.strip_prefix('+') {
            out.push(added);
        } else {
            let (kind, text) =
                if line.is_empty() { (' ', "") } else { (line.as_bytes()[0] as char, &line[1..]) };
            assert!(kind == ' ' || kind == '-', "not a diff line: `{line}`");
            assert_eq!(old.get(at).copied(), Some(text), "the diff's line `{line}` is not the file's");
            if kind == ' ' {
                out.push(text);
            }
            at += 1;
        }
    }
    out.extend_from_slice(&old[at..]);
    out.iter().map(|l| format!("{l}\n")).collect()
}

/// The marker's kind and its words (`file`, `[NAME]`).
fn marker(block: &Block) -> Option<(&str, Vec<&str>)> {
    let m = block.marker.as_deref()?;
    let (kind, args) = m.split_once(':').unwrap_or((m, ""));
    Some((kind.trim(), args.split_whitespace().collect()))
}

#[test]
fn the_files_the_tutorial_shows_are_the_files_in_docs_tutorial() {
    let files = tutorial_files();
    let file = |name: &str| files.get(name).unwrap_or_else(|| panic!("docs/tutorial/{name} is missing"));
    let mut parts: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut shown: Vec<String> = Vec::new();
    let page = read(&docs().join("tutorial.md"));
    for block in blocks(&page) {
        let at = block.line;
        match marker(&block) {
            Some(("file", args)) => {
                assert!(
                    block.text == *file(args[0]),
                    "the block at line {at} is not docs/tutorial/{}",
                    args[0]
                );
                shown.push(args[0].to_string());
            }
            Some(("part", args)) => parts.entry(args[0].to_string()).or_default().push(block.text.clone()),
            Some(("diff", args)) => {
                let new = patched(file(args[0]), &block.text);
                assert!(
                    new == *file(args[1]),
                    "the diff at line {at} does not give docs/tutorial/{}",
                    args[1]
                );
                assert!(block.text.starts_with(&format!("--- {}\n+++ {}\n", args[0], args[1])));
                shown.push(args[1].to_string());
            }
            Some(("output", _)) | None => {}
            Some((other, _)) => panic!("unknown marker `{other}` at line {at}"),
        }
    }
    for (name, texts) in &parts {
        assert!(texts.join("\n") == *file(name), "the parts of {name} shown are not docs/tutorial/{name}");
        shown.push(name.clone());
    }
    for name in files.keys() {
        assert!(shown.contains(name), "the tutorial does not show docs/tutorial/{name}");
    }
}

#[test]
fn every_command_of_the_tutorial_runs_and_prints_what_it_shows() {
    let scratch = Scratch::new();
    let page = read(&docs().join("tutorial.md"));
    let (mut last, mut commands) = (None::<(String, String)>, 0);
    for block in blocks(&page) {
        match (marker(&block), block.lang.as_str()) {
            (Some(("output", _)), _) => {
                let (command, output) = last.as_ref().expect("an output block after a command");
                let shown: Vec<&str> = block.text.lines().collect();
                let lines: Vec<&str> = output.lines().collect();
                assert!(
                    abridges(&shown, &lines),
                    "`{command}` printed\n{output}\nnot (line {})\n{}",
                    block.line,
                    block.text
                );
            }
            (None, "sh") => {
                for line in block.text.lines().map(str::trim).filter(|l| !l.is_empty()) {
                    if SETUP.contains(&line) {
                        continue;
                    }
                    last = Some((line.to_string(), run(line, &scratch.0)));
                    commands += 1;
                }
            }
            _ => {}
        }
    }
    assert!(commands >= 10, "only {commands} commands ran");
    the_runs_are_as_the_prose_says(&scratch.0);
}

/// A CSV's header and rows.
fn csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = read(path);
    let mut lines = text.lines();
    let header = lines.next().expect("a header").split(',').map(str::to_string).collect();
    let rows = lines.map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect()).collect();
    (header, rows)
}

/// The largest |x - ref| / max(1, |ref|) between a run (angles in degrees) and a reference of
/// the same rows and columns (angles in radians).
fn error_against(run: &[Vec<f64>], reference: &Path) -> f64 {
    let (_, reference) = csv(reference);
    assert_eq!(run.len(), reference.len(), "rows against {}", reference.len());
    let mut worst: f64 = 0.0;
    for (row, want) in run.iter().zip(&reference) {
        assert!((row[0] - want[0]).abs() < 1e-12, "the same output times");
        for k in 1..=7 {
            let value = if k <= 3 { row[k].to_radians() } else { row[k] };
            worst = worst.max((value - want[k]).abs() / want[k].abs().max(1.0));
        }
    }
    worst
}

/// The column `name` of a CSV.
fn column(csv: &(Vec<String>, Vec<Vec<f64>>), name: &str) -> Vec<f64> {
    let k = csv.0.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    csv.1.iter().map(|row| row[k]).collect()
}

/// The facts the tutorial's prose states about the runs it shows.
fn the_runs_are_as_the_prose_says(dir: &Path) {
    let references = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gyro-sim/tests/data");
    let gimbal = csv(&dir.join("out/gimbal/trajectory.csv"));
    let columns = "t,q1_deg,q2_deg,q3_deg,u1_rad_per_s,u2_rad_per_s,u3_rad_per_s,ap_m_per_s2";
    assert_eq!(gimbal.0.join(","), columns);
    assert_eq!(gimbal.1.len(), 101);
    for file in ["trajectory.png", "view.html"] {
        assert!(dir.join("out/gimbal").join(file).is_file(), "{file} written");
    }
    assert_eq!(format!("{:.2}", column(&gimbal, "q1_deg")[100]), "823.06");
    let error = error_against(&gimbal.1, &references.join("gimbal_script_case.csv"));
    assert!(error < 1e-7, "the script's case against its reference: {error:e}");

    let view = read(&dir.join("out/scene/view.html"));
    for body in ["outer gimbal B", "inner gimbal C", "rotor D"] {
        assert!(view.contains(body), "the scene's view draws {body}");
    }

    let trial3 = csv(&dir.join("out/trial3/trajectory.csv"));
    let ap = column(&trial3, "ap_m_per_s2");
    assert!(ap.iter().all(|a| (3000.0 - 1e-9..=3005.0).contains(a)), "|a_P| in Trial 3: {ap:?}");
    assert_eq!(format!("{:.2}", column(&trial3, "q1_deg")[100]), "-46.52");
    assert_eq!(format!("{:.2}", column(&trial3, "q2_deg")[100]), "-37.44");
    let error = error_against(&trial3.1, &references.join("gimbal_trial3.csv"));
    assert!(error < 1e-6, "Trial 3 against its reference: {error:e}");

    let offset = csv(&dir.join("out/offset/trajectory.csv"));
    let q1 = column(&offset, "q1_deg");
    assert_eq!(format!("{:.1}", q1[100]), "62.5");
    assert_eq!(format!("{:.1}", q1[100] / 5.0), "12.5");
    let (m3, g, e, k1, u3) = (50.0, 9.81, 0.1, 0.5 * 50.0 * 0.3 * 0.3, 100.0);
    assert_eq!(format!("{:.3}", m3 * g * e / (k1 * u3)), "0.218");
    let q2 = column(&offset, "q2_deg");
    assert!(q2.iter().all(|q| (30.0 - 1e-9..30.15).contains(q)), "q2 nods above 30 deg: {q2:?}");
}

#[test]
fn abridged_outputs_match_line_by_line() {
    let output = ["a: 1 steps, 2 ms; done", "b", "c", "d"];
    assert!(abridges(&["a: ... steps, ... ms; done", "b", "..."], &output));
    assert!(abridges(&["...", "d"], &output));
    assert!(!abridges(&["a: ... steps, ... ms; done", "c", "..."], &output));
    assert!(!abridges(&["...", "c"], &output));
    assert!(!line_matches("x...y", "xy-"));
    assert_eq!(words(r#"gyro-sim run --set "U3=100 rad/s"   # exits with status 1"#).0[3], "U3=100 rad/s");
    let diff = "--- a\n+++ b\n@@ -1,3 +1,3 @@\n x\n-y\n+Y\n z\n";
    assert_eq!(patched("x\ny\nz\nw\n", diff), "x\nY\nz\nw\n");
}
