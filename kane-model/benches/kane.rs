//! Derivation benchmarks: Kane's equations of the gimbal and of n-link pendulums, and the
//! Whipple bicycle's linearisation at one speed once its equations are lowered.
//!
//! Run with `cargo bench -p kane-model --bench kane`; operation counts and peak memory come from
//! `cargo run --release -p kane-model --example derivation_stats`. Figures are in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use kane_model::models::{n_link_pendulum, GimbalGyroscope};

fn derivation(c: &mut Criterion) {
    let mut g = c.benchmark_group("derive");
    g.bench_function("gimbal", |b| {
        b.iter(|| {
            let mut model = GimbalGyroscope::new().expect("gimbal model");
            black_box(model.model.kane().expect("gimbal equations").forcing.len())
        })
    });
    for n in [1, 2, 5, 10, 20, 40] {
        g.bench_function(format!("n_link_pendulum_{n}"), |b| {
            b.iter(|| {
                let (mut m, _, _) = n_link_pendulum(n).expect("pendulum model");
                black_box(m.kane().expect("pendulum equations").forcing.len())
            })
        });
    }
    g.finish();
}

/// `kane linearize`'s work per operating point: dual-number passes through the lowered rhs.
fn linearisation(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/whipple_bicycle.al");
    let source = std::fs::read_to_string(path).expect("the bicycle model file");
    let loaded = kane_model::lang::check_for_generation(path, &source).expect("bicycle loads").model;
    let values: std::collections::HashMap<String, f64> =
        loaded.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
    let mut spec = loaded.into_spec("whipple_bicycle").expect("bicycle spec");
    let lowered = kane_model::program::lower(&mut spec).expect("bicycle lowers");
    let value = |s: &kane_model::expr::SymbolId| values[&spec.symbol_name(*s).to_ascii_uppercase()];
    let mut params: Vec<f64> = lowered.params.iter().map(value).collect();
    let y: Vec<f64> = lowered.states.iter().map(value).collect();
    let speed = lowered.params.iter().position(|s| spec.symbol_name(*s) == "V").expect("V");
    c.bench_function("linearize/whipple_bicycle_one_speed", |b| {
        let mut v = 0.0;
        b.iter(|| {
            v = (v + 1.0) % 11.0;
            params[speed] = v;
            black_box(
                kane_model::program::linearize::linearize(&lowered.program, &params, 0.0, &y, &[]).a.len(),
            )
        })
    });
}

criterion_group!(benches, derivation, linearisation);
criterion_main!(benches);
