//! The heavy top built through kane-model's Rust API (`HeavyTop::spec`, compiled with
//! `kane_derive::builtin_model!`) and the same top as a model file run through the same path
//! (scene -> resolve -> solve) and give the same trajectory; the API form's typed outputs
//! (energies, angular momentum, quaternion) hold their physics.

use gyro_sim::run;
use gyro_sim::Scene;

const TIMES: &str =
    "t_final = 10.0\noutput_step = 0.1\n[integrator]\nmethod = \"dop853\"\nrtol = 1e-12\natol = 1e-12\n";

fn rows(text: &str) -> Vec<Vec<f64>> {
    let scene = Scene::parse("top.toml", text).unwrap();
    run(&scene, None).unwrap().trajectory.rows
}

#[test]
fn the_rust_api_top_and_the_model_file_top_give_the_same_trajectory() {
    let file = rows(&format!(
        "model = \"heavy_top\"\noutputs = [\"E4\", \"E1\", \"E2\", \"E3\", \"W1\", \"W2\", \"W3\"]\n{TIMES}"
    ));
    let api = rows(&format!(
        "model = \"heavy_top_rust\"\noutputs = [\"e0\", \"e1\", \"e2\", \"e3\", \"w1\", \"w2\", \"w3\"]\n{TIMES}"
    ));
    assert_eq!(file.len(), 101);
    let mut worst: f64 = 0.0;
    for (a, b) in file.iter().zip(&api) {
        assert_eq!(a[0], b[0]);
        for k in 1..8 {
            worst = worst.max((a[k] - b[k]).abs() / b[k].abs().max(1.0));
        }
    }
    assert!(worst < 1e-9, "largest relative difference {worst:e}");
    // The top moves: the comparison is not between two resting states.
    assert!((api[100][2] - api[0][2]).abs() > 1e-2, "{:?}", api[100]);
}

#[test]
fn the_api_tops_outputs_conserve_energy_and_vertical_angular_momentum() {
    let api = rows(&format!("model = \"heavy_top_rust\"\noutputs = [\"KE\", \"PE\", \"L\", \"Q\", \"e0\", \"e1\", \"e2\", \"e3\"]\n{TIMES}"));
    // Columns: t, KE, PE, L_N1, L_N2, L_N3, Q_E0..Q_E3, e0..e3.
    let energy = |r: &Vec<f64>| r[1] + r[2];
    let (e0, lz0) = (energy(&api[0]), api[0][5]);
    for r in &api {
        assert!((energy(r) - e0).abs() < 1e-9 * e0.abs().max(1.0), "energy {} vs {e0}", energy(r));
        assert!((r[5] - lz0).abs() < 1e-9 * lz0.abs().max(1.0), "L_z {} vs {lz0}", r[5]);
        let n = (r[10] * r[10] + r[11] * r[11] + r[12] * r[12] + r[13] * r[13]).sqrt();
        let sign = if r[10] < 0.0 { -1.0 } else { 1.0 };
        for k in 0..4 {
            assert!((r[6 + k] - sign * r[10 + k] / n).abs() < 1e-9, "quaternion output {:?}", &r[6..14]);
        }
    }
    // Gravity does work: kinetic energy changes while the total does not.
    assert!(api.iter().any(|r| (r[1] - api[0][1]).abs() > 1e-3));
}
