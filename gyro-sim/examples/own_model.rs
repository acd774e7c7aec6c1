//! The library path: your own model file compiled into your own program, beside the built-in
//! models, through the same driver the `gyro-sim` command uses. Copy this file into a crate
//! that depends on `gyro-sim`, `kane-derive` and `kane-model` (path dependencies on this
//! workspace) and point `model!` at your file (relative to your crate's `Cargo.toml`).
//!
//! `cargo run --release -p gyro-sim --example own_model`

use gyro_sim::run_with;
use gyro_sim::Registry;
use gyro_sim::Scene;

/// The variant gimbal (rotor offset, gravity, flipped axis), compiled at build time.
mod variant {
    kane_derive::model!("tests/data/variant_gimbal.al");
}

/// A scene for it, as a user writes one (it could as well be a `.toml` file).
const SCENE: &str = r#"
title = "Variant gimbal: rotor 8 cm off O, tilted 20 deg, under gravity"
model = "variant_gimbal"
t_final = 2.0
output_step = 0.01
outputs = ["Q1", "Q2", "U1", "U2", "U3"]

[integrator]
method = "dop853"
rtol = 1e-10
atol = 1e-10

[parameters]
OFF = 0.08
Z = 0.0

[initial]
Q2 = "20 deg"
U3 = "100 rad/s"
"#;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let registry = Registry::builtin().with::<variant::Model>();
    let scene = Scene::parse("own_model.toml", SCENE)?;
    let summary = run_with(&scene, &registry, None)?;
    let t = &summary.trajectory;
    let last = t.rows.last().ok_or("no rows")?;
    println!("{}: {} steps, {} RHS evaluations", scene.title, t.stats.steps, t.stats.rhs_evals);
    // Rows are in model units: angles in radians even where the model reports degrees.
    for (c, v) in t.columns.iter().zip(&last[1..]) {
        let (v, unit) =
            if c.unit.eq_ignore_ascii_case("DEG") { (v.to_degrees(), "deg") } else { (*v, c.unit.as_str()) };
        println!("  {} at t = {}: {v:.6} {unit}", c.name, last[0]);
    }
    Ok(())
}
