//! Taylor coefficients per call: the generated `taylor_with_constants` of the heavy top and the gimbal
//! at every straight-line order, and the loop at order 16 beside it.
//!
//! `cargo bench -p gyro-sim --bench taylor_coefficients`. Figures are in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use gyro_sim::{gimbal_gyroscope as gimbal, heavy_top as top};
use kane_model::runtime::TAYLOR_UNROLLED_ORDERS;

/// Benches `$m::taylor_with_constants` at `$y`, every straight-line order, and the loop at 16.
macro_rules! coefficient_benches {
    ($c:expr, $name:literal, $m:ident, $y:expr) => {{
        let p = $m::Params::default();
        let d = $m::param_constants(&p);
        let y: Vec<f64> = $y.to_vec();
        let mut work = Vec::new();
        let mut g = $c.benchmark_group(concat!("taylor_", $name));
        for &order in TAYLOR_UNROLLED_ORDERS {
            let mut out = vec![0.0; y.len() * (order + 1)];
            g.bench_function(format!("order_{order}"), |b| {
                b.iter(|| $m::taylor_with_constants(0.0, black_box(&y), &p, &d, order, &mut out, &mut work))
            });
        }
        let mut out = vec![0.0; y.len() * 17];
        g.bench_function("loop_order_16", |b| {
            b.iter(|| $m::taylor_with_constants_loop(0.0, black_box(&y), &p, &d, 16, &mut out, &mut work))
        });
        g.finish();
    }};
}

fn benches(c: &mut Criterion) {
    coefficient_benches!(c, "heavy_top", top, [0.1, 0.05, 0.02, 0.99, 0.3, -0.2, 10.0]);
    coefficient_benches!(c, "gimbal", gimbal, [0.1, 0.2, 0.3, 1.0, -2.0, 100.0]);
}

criterion_group!(coefficients, benches);
criterion_main!(coefficients);
