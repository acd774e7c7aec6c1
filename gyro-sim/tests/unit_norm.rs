//! The top's Euler parameters are held at unit norm: at a loose tolerance over a long run the
//! integrated norm drifts past the tolerance and is projected back (counted in the summary),
//! every written set has unit norm, and the energy stays within the loose tolerance's reach.

use gyro_sim::run;
use gyro_sim::Scene;

fn cusp(rtol: f64, t_final: f64) -> Scene {
    let path = format!("{}/scenes/ejs/cusp.toml", env!("CARGO_MANIFEST_DIR"));
    let mut s = Scene::load(std::path::Path::new(&path)).unwrap_or_else(|e| panic!("{e}"));
    s.integrator.rtol = rtol;
    s.integrator.atol = rtol;
    s.integrator.accuracy = None;
    s.t_final = t_final;
    s
}

/// `|e|` of a row `t, e4, e1, e2, e3, ...`.
fn norm(row: &[f64]) -> f64 {
    row[1..5].iter().map(|v| v * v).sum::<f64>().sqrt()
}

#[test]
fn a_loose_long_run_is_projected_and_writes_unit_quaternions() {
    let loose = run(&cusp(1e-4, 1000.0), None).unwrap().trajectory;
    let drift = loose.norm_drift.expect("the cusp scene names its Euler parameters");
    assert_eq!(drift.threshold, 1e-4);
    assert!(drift.projections > 0, "{drift:?}");
    assert!(drift.largest > 1e-4 && drift.largest < 1e-2, "{drift:?}");
    for row in &loose.rows {
        assert!((norm(row) - 1.0).abs() < 1e-14, "t = {}: |e| = {}", row[0], norm(row));
    }
    let k = 1 + loose.columns.iter().position(|c| c.name == "ENERGY").unwrap();
    let e0 = loose.rows[0][k];
    let worst = loose.rows.iter().map(|r| (r[k] - e0).abs() / e0).fold(0.0, f64::max);
    assert!(worst < 1e-2, "energy drift {worst:e}");
}

#[test]
fn a_tight_run_rarely_projects() {
    let t = run(&cusp(1e-12, 50.0), None).unwrap().trajectory;
    let drift = t.norm_drift.unwrap();
    assert!(drift.largest <= 1e-11, "{drift:?}");
    assert!(drift.projections <= 2, "{drift:?}");
}

#[test]
fn scenes_without_euler_parameters_report_none() {
    let path = format!("{}/scenes/paper/trial1.toml", env!("CARGO_MANIFEST_DIR"));
    let s = Scene::load(std::path::Path::new(&path)).unwrap();
    assert!(run(&s, None).unwrap().trajectory.norm_drift.is_none());
}
