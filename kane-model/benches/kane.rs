//! Derivation benchmarks: Kane's equations of the gimbal and of n-link pendulums.
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

criterion_group!(benches, derivation);
criterion_main!(benches);
