//! Running what `kane code` and `kane fmu` write in their real runtimes (gcc, gfortran, GNU
//! Octave, python3): scratch folders, commands that must succeed, and the CSV tables the
//! programs write.

use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh folder of this test process's own, `{prefix}-{name}-{pid}` under the system's
/// temporary folder.
pub fn scratch(prefix: &str, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("{prefix}-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `cmd`, panicking with its output when it fails; its stdout and stderr.
pub fn succeeds(cmd: &mut Command, what: &str) -> String {
    let out = cmd.output().unwrap_or_else(|e| panic!("{what}: cannot start ({e}); tests/run installs it"));
    let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{what} failed:\n{stdout}\n{stderr}");
    format!("{stdout}{stderr}")
}

/// A CSV's header and rows.
pub struct Table {
    /// The column names.
    pub header: Vec<String>,
    /// The rows' values.
    pub rows: Vec<Vec<f64>>,
}

/// The CSV table at `path`.
pub fn table(path: &Path) -> Table {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(str::to_string).collect();
    let rows = lines.map(|l| l.split(',').map(|v| v.parse::<f64>().unwrap()).collect()).collect();
    Table { header, rows }
}

/// Compiles the C program `source` into `exe` with gcc, warnings as errors.
pub fn gcc(source: &Path, exe: &Path) {
    let mut gcc = Command::new("gcc");
    gcc.args(["-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-o"]).arg(exe).arg(source).arg("-lm");
    succeeds(&mut gcc, "gcc");
}

/// Compiles the Fortran program `source` into `exe` with gfortran.
pub fn gfortran(source: &Path, exe: &Path) {
    let mut gfortran = Command::new("gfortran");
    gfortran.args(["-O2", "-Wall", "-o"]).arg(exe).arg(source);
    succeeds(&mut gfortran, "gfortran");
}

/// `octave-cli --eval NAME` in `dir` (its own home folder).
pub fn octave(dir: &Path, name: &str) -> String {
    let mut cmd = Command::new("octave-cli");
    cmd.args(["--quiet", "--norc", "--no-history", "--eval", name]).current_dir(dir).env("HOME", dir);
    succeeds(&mut cmd, "GNU Octave")
}
