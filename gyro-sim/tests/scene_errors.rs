//! Malformed scenes are rejected with the file, the line and the fix.

use gyro_sim::run::run;
use gyro_sim::scene::Scene;

fn error(text: &str) -> String {
    match Scene::parse("bad.toml", text) {
        Ok(s) => run(&s, None).map(|_| ()).unwrap_err().to_string(),
        Err(e) => e.to_string(),
    }
}

#[test]
fn unknown_key() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\nt_finla = 2.0\n");
    assert!(e.starts_with("bad.toml:4:1: error: unknown field `t_finla`"), "{e}");
    assert!(e.contains("help:"), "{e}");
}

#[test]
fn wrong_unit() {
    let e =
        error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[initial]\nQ2 = \"3 m/s\"\n");
    assert!(e.starts_with("bad.toml:5:6: error: `Q2` is in DEG, not M/S"), "{e}");
}

#[test]
fn missing_or_unknown_model() {
    let e = error("t_final = 1.0\noutput_step = 0.1\n");
    assert!(e.contains("error: missing `model`") && e.contains("help: add model ="), "{e}");
    let e = error("model = \"gimbal\"\nt_final = 1.0\noutput_step = 0.1\n");
    assert!(
        e.starts_with("bad.toml:1:9: error: unknown model `gimbal`") && e.contains("gimbal_gyroscope"),
        "{e}"
    );
}

#[test]
fn negative_t_final() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = -5.0\noutput_step = 0.1\n");
    assert!(e.starts_with("bad.toml:2:11: error: t_final must be positive, not -5"), "{e}");
}

#[test]
fn unknown_parameter_and_output() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nYY = 1.0\n");
    assert!(
        e.contains("bad.toml:5:6: error: `YY` is not a parameter") && e.contains("parameters: M1"),
        "{e}"
    );
    let e =
        error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\noutputs = [\"Q1\", \"AQ\"]\n");
    assert!(e.contains("`AQ` is neither a state nor an output"), "{e}");
}

#[test]
fn accuracy_must_be_positive_and_needs_an_adaptive_method() {
    let base = "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[integrator]\n";
    let e = error(&format!("{base}method = \"dop853\"\naccuracy = -1e-6\n"));
    assert!(e.starts_with("bad.toml:6:12: error: accuracy must be positive"), "{e}");
    let e = error(&format!("{base}method = \"rk4\"\naccuracy = 1e-6\n"));
    assert!(e.starts_with("bad.toml:6:12: error: accuracy needs an adaptive method"), "{e}");
    assert!(e.contains("dop853"), "{e}");
}

#[test]
fn plot_points_must_be_in_range() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\nplot_points = 0\n");
    assert!(e.starts_with("bad.toml:4:15: error: plot_points must be 1 to 1000, not 0"), "{e}");
}
