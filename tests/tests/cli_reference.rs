//! docs/cli-reference.md is the commands' own help (`kane --help`, `kane SUB --help`, the same
//! for `gyro-sim`), so the reference cannot drift from the clap definitions. After changing a
//! command's arguments or help, regenerate it: `UPDATE_DOCS=1 cargo test -p kane-tests --test
//! cli_reference`.

use std::path::{Path, PathBuf};
use std::process::Command;

use kane_tests::bins;

/// The help text `binary args... --help` prints.
fn help(binary: &Path, args: &[&str]) -> String {
    let out = Command::new(binary).args(args).arg("--help").output().expect("run the command");
    assert!(out.status.success(), "{} {args:?} --help failed", binary.display());
    String::from_utf8(out.stdout).expect("help is UTF-8").trim_end().to_string()
}

/// The subcommands a top-level help lists under `Commands:` (without `help`).
fn subcommands(top: &str) -> Vec<String> {
    top.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter(|l| !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_string)
        .collect()
}

/// One section per command: its help as printed.
fn reference_of(name: &str, binary: &Path) -> String {
    let top = help(binary, &[]);
    let mut out = format!("## `{name}`\n\n```text\n{top}\n```\n");
    for sub in subcommands(&top) {
        out.push_str(&format!("\n### `{name} {sub}`\n\n```text\n{}\n```\n", help(binary, &[&sub])));
    }
    out
}

fn reference() -> String {
    let mut out = String::from(
        "# Command-line reference\n\nEvery command of `kane` and `gyro-sim` with its arguments, as \
         `--help` prints them (this page is generated from the commands themselves; a test keeps \
         it so). What the commands do, with examples: [the simulator](simulator.md) and \
         [the `kane` command](kane-command.md).\n\n",
    );
    out.push_str(&reference_of("kane", &bins::kane()));
    out.push('\n');
    out.push_str(&reference_of("gyro-sim", &bins::gyro_sim()));
    out
}

fn page() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/cli-reference.md")
}

#[test]
fn the_cli_reference_is_the_commands_own_help() {
    let generated = reference();
    if std::env::var_os("UPDATE_DOCS").is_some() {
        let temporary = page().with_extension("md.new");
        std::fs::write(&temporary, &generated).expect("write docs/cli-reference.md");
        std::fs::rename(&temporary, page()).expect("write docs/cli-reference.md");
        return;
    }
    let written = std::fs::read_to_string(page()).unwrap_or_default();
    assert!(
        written == generated,
        "docs/cli-reference.md differs from the commands' help: regenerate it with \
         UPDATE_DOCS=1 cargo test -p kane-tests --test cli_reference"
    );
}

#[test]
fn the_subcommands_are_read_from_the_top_level_help() {
    let top = help(&bins::kane(), &[]);
    let subs = subcommands(&top);
    assert!(subs.contains(&"check".to_string()) && subs.contains(&"linearize".to_string()), "{subs:?}");
    assert!(!subs.iter().any(|s| s == "help"));
}
