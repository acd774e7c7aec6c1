//! Failures named for their cause at any time: a square root or logarithm of a
//! negative number, a pole, a mass matrix turning singular, all met mid-run, are each named with
//! the operation (written with the model's names), the time and the state, not as a step size
//! that underflowed. And the errors of a `--model` run point at what the user gave (`--set`, the
//! model file), never at the scene generated for the run.

use std::path::{Path, PathBuf};
use std::process::Output;

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/failures").join(name).display().to_string()
}

fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("failure_causes").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `gyro-sim run --model FILE --engine instant ARGS` into a folder of its own.
fn run_model(file: &str, args: &[&str]) -> Output {
    let out = folder(Path::new(file).file_stem().unwrap().to_str().unwrap());
    std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "--model", file, "--engine", "instant", "--out", out.to_str().unwrap()])
        .args(args)
        .output()
        .unwrap()
}

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

/// The time after `at t = ` in `message`.
fn time_in(message: &str) -> f64 {
    let rest = &message[message.find("at t = ").expect("a time") + 7..];
    rest.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-'))
        .next()
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn a_square_root_of_a_negative_number_mid_run_is_named_with_its_expression() {
    let run = run_model(&data("root_past_one.al"), &[]);
    let e = text(&run);
    assert_eq!(run.status.code(), Some(1), "{e}");
    assert!(e.contains("the square root of a negative number"), "{e}");
    assert!(e.contains("sqrt(1 - T)"), "{e}");
    let t = time_in(&e);
    assert!(t > 1.0 && t < 1.2, "{e}");
    assert!(!e.contains("step size underflow"), "{e}");
}

#[test]
fn a_logarithm_of_a_negative_number_mid_run_is_named() {
    let run = run_model(&data("log_of_gap.al"), &[]);
    let e = text(&run);
    assert_eq!(run.status.code(), Some(1), "{e}");
    assert!(e.contains("the logarithm of a number that is not positive"), "{e}");
    assert!(e.contains("ln(Q1)"), "{e}");
}

#[test]
fn a_pole_in_time_is_a_singularity_named_not_a_step_size_underflow() {
    let run = run_model(&data("pole_at_one.al"), &[]);
    let e = text(&run);
    assert_eq!(run.status.code(), Some(1), "{e}");
    assert!(e.contains("singularity") || e.contains("division by zero"), "{e}");
    assert!(e.contains("T - 1") || e.contains("-1 + T"), "{e}");
    let t = time_in(&e);
    assert!((t - 1.0).abs() < 1e-3, "{e}");
}

#[test]
fn a_mass_matrix_turning_singular_mid_run_is_named_with_its_configuration() {
    let run = run_model(&data("massless_at_zero.al"), &[]);
    let e = text(&run);
    assert_eq!(run.status.code(), Some(1), "{e}");
    assert!(e.contains("mass matrix singular"), "{e}");
    assert!(e.contains("Q1 = "), "{e}");
    assert!(time_in(&e) > 0.1, "mid-run, not at the start: {e}");
}

#[test]
fn errors_of_a_model_run_point_at_the_argument_or_the_file() {
    let file = data("root_past_one.al");
    let e = text(&run_model(&file, &["--set", "Q1=abc"]));
    assert!(e.starts_with("--set Q1=abc:"), "{e}");
    assert!(!e.contains("<command line>"), "{e}");
    let e = text(&run_model(&file, &["--set", "M=2 furlongs"]));
    assert!(e.starts_with("--set M=2 furlongs:"), "{e}");
    // A failure of the run is the model file's.
    let e = text(&run_model(&file, &[]));
    assert!(e.starts_with(&file), "{e}");
    assert!(!e.contains("<command line>"), "{e}");
}
