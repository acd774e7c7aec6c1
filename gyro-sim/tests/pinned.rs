//! Pinned results: the paper's four cases through the `gyro-sim` command (integrator statistics
//! and a hash of the CSV's bytes, so every written value's bits) and the integrator test
//! problems' statistics. A refactor that changes any of them shows up here.

use std::path::Path;
use std::process::Command;

use std::ops::ControlFlow;

use gyro_sim::content_hash as fnv1a;
use gyro_sim::test_problems::{Gaussian, Oscillator};
use gyro_sim::{tableau, Integration, Method, Stats, Stepper, StopReason, System, Tolerances};

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

/// Integrates `sys` from `(0, y0)` through `0, 0.1, ..., 10` with `method`: the cost and a hash
/// of every output value's bits.
fn pinned_run<S: System>(sys: &S, y0: &[f64], method: Method) -> (Stats, String) {
    let times: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.1).collect();
    let mut bits = Vec::new();
    let s = Integration::new(sys, 0.0, y0, method)
        .run(&times, |_, y| {
            bits.extend(y.iter().flat_map(|v| v.to_bits().to_le_bytes()));
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    (s, fnv1a(&bits))
}

/// The pin of an adaptive run: its name, steps, rejections, evaluations and values' hash.
fn adaptive_line<S: System>(label: &str, sys: &S, y0: &[f64], method: Method) -> String {
    let (s, hash) = pinned_run(sys, y0, method);
    format!("{label}: {} steps, {} rejected, {} evaluations, fnv1a {hash}", s.steps, s.rejected, s.rhs_evals)
}

/// Tolerances with `rtol = atol = tol`.
fn tolerances(tol: f64) -> Tolerances {
    Tolerances { rtol: tol, atol: tol }
}

/// The pins of `sys` (named `name`, starting at `y0`) by dopri5 and dop853 at three tolerances
/// and rk4 at one step.
fn erk_lines<S: System>(name: &str, sys: &S, y0: &[f64]) -> Vec<String> {
    let mut lines = Vec::new();
    for tab in [&tableau::DOPRI5, &tableau::DOP853] {
        for tol in [1e-6, 1e-9, 1e-12] {
            let m = Method::Adaptive(tab, tolerances(tol));
            lines.push(adaptive_line(&format!("{name} {} {tol:e}", tab.name), sys, y0, m));
        }
    }
    let (s, hash) = pinned_run(sys, y0, Method::Fixed(&tableau::RK4, 0.03));
    lines.push(format!("{name} rk4 0.03: {} steps, fnv1a {hash}", s.steps));
    lines
}

/// The pins of `sys` by vern7, vern9 and the Taylor method at three tolerances.
fn verner_taylor_lines<S: System>(name: &str, sys: &S, y0: &[f64]) -> Vec<String> {
    let mut lines = Vec::new();
    for tol in [1e-6, 1e-9, 1e-12] {
        for tab in [&tableau::VERN7, &tableau::VERN9] {
            let m = Method::Adaptive(tab, tolerances(tol));
            lines.push(adaptive_line(&format!("{name} {} {tol:e}", tab.name), sys, y0, m));
        }
        let m = Method::Taylor(tolerances(tol));
        lines.push(adaptive_line(&format!("{name} taylor {tol:e}"), sys, y0, m));
    }
    lines
}

#[test]
fn integrator_statistics_are_pinned() {
    let mut lines = erk_lines("oscillator", &Oscillator, &[0.0, 1.0]);
    lines.extend(erk_lines("gaussian", &Gaussian, &[1.0]));
    insta::assert_snapshot!(lines.join("\n"));
}

#[test]
fn verner_and_taylor_statistics_are_pinned() {
    let mut lines = verner_taylor_lines("oscillator", &Oscillator, &[0.0, 1.0]);
    lines.extend(verner_taylor_lines("gaussian", &Gaussian, &[1.0]));
    insta::assert_snapshot!(lines.join("\n"));
}

/// A watched run of the oscillator stopped by its watcher at `t = 5` (the first step past it):
/// the steps the watcher saw (their ends' and midpoints' bits hashed), the outputs, the cost and
/// where it stopped.
#[test]
fn watched_runs_are_pinned() {
    let times: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.1).collect();
    let mut lines = Vec::new();
    let methods = [
        ("dop853", Method::Adaptive(&tableau::DOP853, tolerances(1e-9))),
        ("taylor", Method::Taylor(tolerances(1e-9))),
    ];
    for (label, m) in methods {
        let (mut seen, mut bits) = (Vec::new(), Vec::new());
        let mut mid = [0.0; 2];
        let watch = |s: &dyn Stepper| {
            s.interpolate(0.5 * (s.step_start() + s.t()), &mut mid).unwrap();
            seen.extend([s.t(), mid[0], mid[1]].iter().flat_map(|v| v.to_bits().to_le_bytes()));
            if s.t() > 5.0 {
                ControlFlow::Break(5.0)
            } else {
                ControlFlow::Continue(())
            }
        };
        let out = |_: f64, y: &[f64]| {
            bits.extend(y.iter().flat_map(|v| v.to_bits().to_le_bytes()));
            ControlFlow::Continue(())
        };
        let run =
            Integration::new(&Oscillator, 0.0, &[0.0, 1.0], m).max_steps(1000).watch(watch).run(&times, out);
        let (s, reason) = run.map(|run| (run.stats, run.reason)).unwrap();
        // The pin says where it stopped as the event's time.
        let stop = match reason {
            StopReason::Event { time } => Some(time),
            _ => None,
        };
        lines.push(format!(
            "{label} 1e-9: {} steps, {} rejected, {} evaluations, stopped at {stop:?}, {} outputs, fnv1a {} steps {}",
            s.steps,
            s.rejected,
            s.rhs_evals,
            bits.len() / 16,
            fnv1a(&bits),
            fnv1a(&seen)
        ));
    }
    insta::assert_snapshot!(lines.join("\n"));
}
