//! What the command-line tests share: running the built `kane` command.

use std::process::Command;

/// Runs `kane ARGS`: whether it succeeded, its standard output and its standard error.
pub fn kane(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kane")).args(args).output().expect("run kane");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}
