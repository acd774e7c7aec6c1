//! The README's first model file is the one under `docs/examples/`, and it runs as the README
//! shows: `kane check`'s equations, then `gyro-sim run` with a `--set` in degrees.

use std::path::Path;
use std::process::Command;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

#[test]
fn the_readme_shows_the_example_file_as_it_is() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let file = std::fs::read_to_string(root().join("docs/examples/pendulum.al")).unwrap();
    assert!(readme.contains(&file), "README's pendulum is docs/examples/pendulum.al");
}

#[test]
fn the_readme_example_runs_with_a_value_set_in_degrees() {
    let out = std::env::temp_dir().join(format!("guide-pendulum-{}", std::process::id()));
    let run = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "--model"])
        .arg(root().join("docs/examples/pendulum.al"))
        .args(["--set", "Q=60 deg", "--t-final", "1", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let first: Vec<f64> = csv.lines().nth(1).unwrap().split(',').map(|x| x.parse().unwrap()).collect();
    assert!((first[1] - 60f64.to_radians()).abs() < 1e-15, "Q starts at 60 deg: {first:?}");
    std::fs::remove_dir_all(&out).unwrap();
}
