//! Gimbal benchmarks: generated `rhs` per call, and Trial 3 to t = 5 at three tolerances.
//!
//! `cargo bench -p gyro-sim --bench gimbal`; it also prints RHS evaluations and the error against
//! the independent reference for each case. Figures are in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use gyro_sim::models::gimbal_gyroscope as gimbal;
use gyro_sim::ode::{integrate, tableau, Method, Tolerances};
use gyro_sim::run::{ModelSystem, Reduced};
use kane_model::runtime::GeneratedModel;

fn trial3() -> (ModelSystem<gimbal::Model>, Vec<f64>, Vec<f64>) {
    let mut p = gimbal::Params::default();
    gimbal::Model::set_param(&mut p, "Y", 10.0);
    gimbal::Model::set_param(&mut p, "Z", 10.0);
    let y0 = vec![0.0, 0.0, 0.0, 0.0, 0.0, 100.0];
    let times: Vec<f64> = (0..=100).map(|i| i as f64 * 0.05).collect();
    (ModelSystem::new(p), y0, times)
}

fn reference() -> Vec<Vec<f64>> {
    include_str!("../tests/data/gimbal_trial3.csv")
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// One run; the reference is parsed once outside the timed loop.
fn run(method: Method, reference: &[Vec<f64>]) -> (usize, f64) {
    let (sys, y0, times) = trial3();
    let mut worst: f64 = 0.0;
    let mut k = 0;
    let stats = integrate(&sys, 0.0, &y0, &times, method, |_, y| {
        for i in 0..6 {
            let want = reference[k][i + 1];
            worst = worst.max((y[i] - want).abs() / want.abs().max(1.0));
        }
        k += 1;
        Ok(())
    })
    .unwrap();
    (stats.rhs_evals, worst)
}

fn benches(c: &mut Criterion) {
    let p = gimbal::Params::default();
    let d = gimbal::derive(&p);
    let y = [0.1, 0.2, 0.3, 0.4, 0.5, 100.0];
    let mut dy = [0.0; 6];
    c.bench_function("gimbal_rhs_call", |b| {
        b.iter(|| {
            gimbal::rhs_derived(black_box(0.0), black_box(&y), black_box(&p), black_box(&d), &mut dy);
            black_box(dy[5])
        })
    });
    let reference = reference();
    let reference = reference.as_slice();
    let mut g = c.benchmark_group("trial3_to_t5");
    for tab in [&tableau::DOPRI5, &tableau::DOP853] {
        for tol in [1e-6, 1e-9, 1e-12] {
            let m = Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol });
            let (evals, err) = run(m, reference);
            println!("{} tol {tol:e}: {evals} RHS evaluations, largest relative error {err:.2e}", tab.name);
            g.bench_function(format!("{}_tol_{tol:e}", tab.name), |b| {
                b.iter(|| black_box(run(m, reference)))
            });
        }
    }
    // Q2 and the speeds only: the cyclic q1 and q3 are not integrated.
    let reduced = |tol: f64| -> (usize, f64) {
        let (sys, y0, times) = trial3();
        let keep = vec![1, 3, 4, 5];
        let red = Reduced::new(&sys, keep.clone());
        let y_red: Vec<f64> = keep.iter().map(|k| y0[*k]).collect();
        let mut worst: f64 = 0.0;
        let mut row = 0;
        let m = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: tol, atol: tol });
        let stats = integrate(&red, 0.0, &y_red, &times, m, |_, y| {
            for (i, k) in keep.iter().enumerate() {
                let want = reference[row][k + 1];
                worst = worst.max((y[i] - want).abs() / want.abs().max(1.0));
            }
            row += 1;
            Ok(())
        })
        .unwrap();
        (stats.rhs_evals, worst)
    };
    let (evals, err) = reduced(1e-9);
    println!("dop853 reduced (q1, q3 left out) tol 1e-9: {evals} RHS evaluations, largest relative error {err:.2e}");
    g.bench_function("dop853_reduced_tol_1e-9", |b| b.iter(|| black_box(reduced(1e-9))));
    for step in [1e-3, 1e-4] {
        let m = Method::Fixed(&tableau::RK4, step);
        let (evals, err) = run(m, reference);
        println!("rk4 step {step:e}: {evals} RHS evaluations, largest relative error {err:.2e}");
        g.bench_function(format!("rk4_step_{step:e}"), |b| b.iter(|| black_box(run(m, reference))));
    }
    g.finish();
}

criterion_group!(gimbal_benches, benches);
criterion_main!(gimbal_benches);
