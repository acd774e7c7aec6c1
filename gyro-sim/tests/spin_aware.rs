//! The spin-aware top (kane-model/models/heavy_top_axle.al: the orientation of the non-spinning
//! axle frame, the spin angle PSI relative to it): exact when the rotor is axisymmetric, since
//! then no equation reads PSI; and on the fast top (spin 1000 rad/s) the same axle motion as the
//! plain model against the quadruple-precision reference, in far fewer steps.

use std::path::{Path, PathBuf};

use gyro_sim::run;
use gyro_sim::ModelFile;
use gyro_sim::Scene;
use gyro_sim::Trajectory;

fn models_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../kane-model/models")
}

/// `dy` of `file` at one state with the spin angle at each of `angles`.
fn rates_over_spin_angle(file: &ModelFile, angles: &[f64]) -> Vec<Vec<f64>> {
    let program = &file.program;
    let info = program.info();
    let params = program.default_params();
    let constants = program.param_constants(&params);
    let psi = info.state("PSI").expect("PSI is a state");
    let mut y = program.initial_state();
    for (name, v) in [("E1", 0.3), ("E2", -0.2), ("E3", 0.4), ("W1", 0.7), ("W2", -1.1), ("W3", 25.0)] {
        y[info.state(name).unwrap()] = v;
    }
    let norm = ["E1", "E2", "E3"].iter().map(|n| y[info.state(n).unwrap()].powi(2)).sum::<f64>();
    y[info.state("E4").unwrap()] = (1.0 - norm).sqrt();
    let mut regs = Vec::new();
    angles
        .iter()
        .map(|a| {
            y[psi] = *a;
            let mut dy = vec![0.0; y.len()];
            program.rhs(0.0, &y, &params, &constants, &mut dy, &mut regs);
            dy
        })
        .collect()
}

#[test]
fn the_spin_angle_is_cyclic_exactly_when_the_rotor_is_axisymmetric() {
    let angles = [0.0, 0.4, 1.7, -2.9, 1e3];
    let path = models_dir().join("heavy_top_axle.al");
    let symmetric = ModelFile::load(&path).unwrap_or_else(|e| panic!("{e}"));
    let rates = rates_over_spin_angle(&symmetric, &angles);
    assert!(rates.iter().all(|dy| dy == &rates[0]), "the equations read PSI: {rates:?}");
    // Unequal transverse moments: the spin angle is in the equations again.
    let text = std::fs::read_to_string(&path).unwrap();
    let lopsided = text.replacen("INERTIA R, 26/125*M*RR^2,", "INERTIA R, 36/125*M*RR^2,", 1);
    assert_ne!(lopsided, text);
    let dir = std::env::temp_dir().join(format!("spin-aware-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let lopsided_path = dir.join("lopsided_top_axle.al");
    std::fs::write(&lopsided_path, lopsided).unwrap();
    let lopsided = ModelFile::load(&lopsided_path).unwrap_or_else(|e| panic!("{e}"));
    let rates = rates_over_spin_angle(&lopsided, &angles);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(rates.iter().any(|dy| dy != &rates[0]), "PSI should matter for an asymmetric rotor");
}

fn solve(rel: &str) -> Trajectory {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(rel);
    let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    run(&scene, None).unwrap_or_else(|e| panic!("{e}")).trajectory
}

/// The body z axis in space from Euler parameters (scalar first, body -> space).
fn axle([w, x, y, z]: [f64; 4]) -> [f64; 3] {
    [2.0 * (x * z + w * y), 2.0 * (y * z - w * x), w * w - x * x - y * y + z * z]
}

/// The largest distance of the axle from the reference's over the reference's grid.
fn axle_error(t: &Trajectory) -> f64 {
    let reference = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/ejs/top_fast_quad.csv"),
    )
    .unwrap();
    // Row entry 0 is t; column i is entry i + 1.
    let col = |name: &str| 1 + t.columns.iter().position(|c| c.name == name).unwrap();
    let q = [col("E4"), col("E1"), col("E2"), col("E3")];
    let mut worst: f64 = 0.0;
    for line in reference.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let row = t.rows.iter().find(|r| (r[0] - v[0]).abs() < 1e-9).expect("a row at the reference's time");
        let ours = axle(q.map(|i| row[i]));
        let theirs = axle([v[1], v[2], v[3], v[4]]);
        let d = ours.iter().zip(theirs).map(|(a, b)| (a - b).powi(2)).sum::<f64>().sqrt();
        worst = worst.max(d);
    }
    worst
}

#[test]
fn the_spin_aware_fast_top_keeps_the_axle_in_far_fewer_steps() {
    let plain = solve("ejs/fast.toml");
    let aware = solve("ejs/fast_spin_aware.toml");
    let (e_plain, e_aware) = (axle_error(&plain), axle_error(&aware));
    assert!(e_plain < 1e-8 && e_aware < 1e-8, "axle errors {e_plain:e} (plain), {e_aware:e} (spin-aware)");
    let (n_plain, n_aware) = (plain.stats.steps, aware.stats.steps);
    assert!(3 * n_aware < n_plain, "steps: {n_aware} spin-aware against {n_plain} plain");
}
