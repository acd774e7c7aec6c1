//! Pinned results: the paper's four cases through the `gyro-sim` command (integrator statistics
//! and a hash of the CSV's bytes, so every written value's bits) and the integrator test
//! problems' statistics. A refactor that changes any of them shows up here.

use std::path::Path;
use std::process::Command;

use gyro_sim::content_hash as fnv1a;

/// Runs a scene with the command; returns its statistics line and the CSV's hash.
fn run_scene(scene: &str) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = std::env::temp_dir().join(format!("gyro-sim-pinned-{}-{scene}", std::process::id()));
    let result = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .arg("run")
        .arg(root.join(format!("scenes/paper/{scene}.toml")))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&result.stdout).to_string();
    assert!(result.status.success(), "{scene}: {stdout}\n{}", String::from_utf8_lossy(&result.stderr));
    // "...: S steps (R rejected), E RHS evaluations, ...": the first line's statistics.
    let first = stdout.lines().next().unwrap_or_default();
    let at = first.rfind(" steps (").expect("statistics in the summary");
    let start = first[..at].rfind(' ').map_or(0, |i| i + 1);
    let stats: String = first[start..].split(", ").take(2).collect::<Vec<_>>().join(", ");
    let csv = std::fs::read(out.join("trajectory.csv")).unwrap();
    let _ = std::fs::remove_dir_all(&out);
    format!("{scene}: {stats}; csv {} bytes, fnv1a {}", csv.len(), fnv1a(&csv))
}

#[test]
fn paper_cases_are_pinned() {
    let lines: Vec<String> = ["script", "trial1", "trial2", "trial3"].iter().map(|s| run_scene(s)).collect();
    insta::assert_snapshot!(lines.join("\n"));
}

#[test]
fn integrator_statistics_are_pinned() {
    use gyro_sim::test_problems::{Gaussian, Oscillator};
    use gyro_sim::{integrate, tableau, Method, System, Tolerances};
    let times: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.1).collect();
    let mut lines = Vec::new();
    let problems: [(&str, &dyn System, &[f64]); 2] =
        [("oscillator", &Oscillator, &[0.0, 1.0]), ("gaussian", &Gaussian, &[1.0])];
    for (name, sys, y0) in problems {
        for tab in [&tableau::DOPRI5, &tableau::DOP853] {
            for tol in [1e-6, 1e-9, 1e-12] {
                let mut bits = Vec::new();
                let m = Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol });
                let s = integrate(sys, 0.0, y0, &times, m, |_, y| {
                    bits.extend(y.iter().flat_map(|v| v.to_bits().to_le_bytes()));
                    std::ops::ControlFlow::Continue(())
                })
                .unwrap();
                lines.push(format!(
                    "{name} {} {tol:e}: {} steps, {} rejected, {} evaluations, fnv1a {}",
                    tab.name,
                    s.steps,
                    s.rejected,
                    s.rhs_evals,
                    fnv1a(&bits)
                ));
            }
        }
        let mut bits = Vec::new();
        let s = integrate(sys, 0.0, y0, &times, Method::Fixed(&tableau::RK4, 0.03), |_, y| {
            bits.extend(y.iter().flat_map(|v| v.to_bits().to_le_bytes()));
            std::ops::ControlFlow::Continue(())
        })
        .unwrap();
        lines.push(format!("{name} rk4 0.03: {} steps, fnv1a {}", s.steps, fnv1a(&bits)));
    }
    insta::assert_snapshot!(lines.join("\n"));
}
