//! The workspace's command-line programs for tests in any crate: `env!("CARGO_BIN_EXE_...")`
//! only names a test's own package's binaries, so these are built once per test process (with
//! the profile the test runs in, into the same target folder) and found beside the test.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The `gyro-sim` binary, built if needed.
pub fn gyro_sim() -> PathBuf {
    binary("gyro-sim")
}

/// The `kane` binary, built if needed.
pub fn kane() -> PathBuf {
    binary("kane")
}

/// `target/<profile>/<name>` after one `cargo build` of both binaries in this process.
fn binary(name: &str) -> PathBuf {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    let profile_dir = BUILT.get_or_init(build);
    profile_dir.join(format!("{name}{}", std::env::consts::EXE_SUFFIX))
}

/// Builds `gyro-sim` and `kane` for the profile this test was built with; the profile folder.
fn build() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's own path");
    // target/<profile>/deps/<test>
    let profile_dir = exe.parent().and_then(Path::parent).expect("target/<profile>/deps").to_path_buf();
    let target_dir = profile_dir.parent().expect("target folder");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut build = Command::new(cargo);
    build.args([
        "build",
        "--quiet",
        "-p",
        "gyro-sim",
        "--bin",
        "gyro-sim",
        "-p",
        "kane-model",
        "--bin",
        "kane",
    ]);
    build.arg("--target-dir").arg(target_dir);
    build.current_dir(env!("CARGO_MANIFEST_DIR"));
    match profile_dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") => {}
        Some("release") => {
            build.arg("--release");
        }
        Some(other) => {
            build.args(["--profile", other]);
        }
        None => panic!("no profile folder above {}", exe.display()),
    }
    let status = build.status().expect("run cargo build");
    assert!(status.success(), "cargo build of gyro-sim and kane failed");
    profile_dir
}
