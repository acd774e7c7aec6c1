//! Conservation of the EJS top over 1000 s: in come the presets `scenes/ejs/cusp.toml` and
//! `scenes/ejs/fast.toml`, run to t = 1000 s with dop853 at rtol = atol = 1e-12 (no accuracy
//! refinement), output every 0.1 s; out goes, for each, the largest relative drift of the energy,
//! of L_z (vertical angular momentum about the support) and of L_3 (along the axle) from their
//! initial values, the largest departure of the written Euler parameters from unit norm, the
//! integrated Euler parameters' norm drift and how often they were projected back to unit norm
//! (the run's `norm_drift`), and the cost. Energy and momenta are computed from the written
//! states (support at the origin, M = g = d = 1, I1 = I2 = 151/125, I3 = 2/5 about the support).
//!
//! `cargo run --release -p gyro-sim --example drift`

use std::path::Path;

use gyro_sim::run;
use gyro_sim::Scene;

const I1: f64 = 151.0 / 125.0;
const I3: f64 = 0.4;

/// Energy, L_z, L_3 and |q| of a row `t, qw, qx, qy, qz, w1, w2, w3`.
fn invariants(r: &[f64]) -> [f64; 4] {
    let [w, x, y, z] = [r[1], r[2], r[3], r[4]];
    let l_body = [I1 * r[5], I1 * r[6], I3 * r[7]];
    // Space z in body axes (the third row of the body -> space rotation); its third entry is
    // also the axle's height.
    let z_body = [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), w * w - x * x - y * y + z * z];
    let lz: f64 = (0..3).map(|k| z_body[k] * l_body[k]).sum();
    let kinetic: f64 = (0..3).map(|k| 0.5 * l_body[k] * r[5 + k]).sum();
    let norm = (w * w + x * x + y * y + z * z).sqrt();
    [kinetic + z_body[2], lz, l_body[2], norm]
}

/// The largest relative drifts of energy, L_z and L_3 over `rows`, and the largest | |q| - 1 |.
fn drifts(rows: &[Vec<f64>]) -> ([f64; 4], f64) {
    let start = invariants(&rows[0]);
    let mut drift = [0.0f64; 4];
    for r in rows {
        let now = invariants(r);
        for k in 0..3 {
            drift[k] = drift[k].max((now[k] - start[k]).abs() / start[k].abs());
        }
        drift[3] = drift[3].max((now[3] - 1.0).abs());
    }
    (drift, start[0])
}

fn main() {
    let dir = env!("CARGO_MANIFEST_DIR");
    println!(
        "| preset | energy (absolute) | L_z | L_3 | max abs(abs(q) - 1), written | norm drift, integrated | projections (past) | steps | RHS evaluations | wall time |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for name in ["cusp", "fast"] {
        let path = format!("{dir}/scenes/ejs/{name}.toml");
        let mut scene = Scene::load(Path::new(&path)).unwrap_or_else(|e| panic!("{e}"));
        scene.t_final = 1000.0;
        scene.output_step = 0.1;
        scene.integrator.method = gyro_sim::by_name("dop853").expect("a method scenes can name");
        scene.integrator.rtol = 1e-12;
        scene.integrator.atol = 1e-12;
        scene.integrator.accuracy = None;
        let t = run(&scene, None).unwrap_or_else(|e| panic!("{name}: {e}")).trajectory;
        let (drift, energy) = drifts(&t.rows);
        let norm = t.norm_drift.unwrap_or_else(|| panic!("{name}: the run holds no unit norm"));
        println!(
            "| {name} (t = 0..{}) | {:.1e} ({:.1e}) | {:.1e} | {:.1e} | {:.1e} | {:.1e} | {} ({:.0e}) | {} | {} | {:.1} ms |",
            t.rows.last().map_or(0.0, |r| r[0]),
            drift[0],
            drift[0] * energy.abs(),
            drift[1],
            drift[2],
            drift[3],
            norm.largest,
            norm.projections,
            norm.threshold,
            t.stats.steps,
            t.stats.rhs_evals,
            t.wall.as_secs_f64() * 1e3
        );
    }
}
