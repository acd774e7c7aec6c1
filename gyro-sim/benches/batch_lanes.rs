//! Batch lanes against scalar runs: 256 members of the gimbal (Trial 3's
//! equations to t = 5; Y and Z in 0..20 N m, U3 in 50..150 rad/s, a fixed quasi-random set),
//! DOP853 at rtol = atol = 1e-7, 1e-9 and 1e-11, one thread: each member alone (the scalar
//! stepper), 4 or 8 members in lock step through `rhs_lanes`, and 4 in lock step after ordering
//! the members by spin (lanes of similar step sizes).
//!
//! `cargo bench -p gyro-sim --bench batch_lanes`; it also prints, once, each way's RHS
//! evaluations per member and its largest final-state error against DOP853 at 1e-14. Members per
//! second per core = 256 / the time. Figures are in BENCHMARKS.md.

use std::hint::black_box;
use std::ops::ControlFlow;

use criterion::{criterion_group, criterion_main, Criterion};
use gyro_sim::final_states;
use gyro_sim::gimbal_gyroscope as gimbal;
use gyro_sim::ModelSystem;
use gyro_sim::{tableau, Integration, Method, Tolerances};
use kane_model::runtime::GeneratedModel;

const MEMBERS: usize = 256;
const T_END: f64 = 5.0;
/// Tolerances: the error of each way at each is printed, to compare times at equal error.
const TOLERANCES: [f64; 3] = [1e-7, 1e-9, 1e-11];

/// The members: parameters and initial states (a Halton-like set over the three ranges).
fn members() -> Vec<(gimbal::Params, Vec<f64>)> {
    let frac = |i: usize, base: usize| {
        let (mut f, mut x, mut n) = (1.0, 0.0, i + 1);
        while n > 0 {
            f /= base as f64;
            x += f * (n % base) as f64;
            n /= base;
        }
        x
    };
    (0..MEMBERS)
        .map(|i| {
            let mut p = gimbal::Params::default();
            gimbal::Model::set_param(&mut p, "Y", 20.0 * frac(i, 2));
            gimbal::Model::set_param(&mut p, "Z", 20.0 * frac(i, 3));
            (p, vec![0.0, 0.0, 0.0, 0.0, 0.0, 50.0 + 100.0 * frac(i, 5)])
        })
        .collect()
}

/// Each member alone; the final states and the RHS evaluations.
fn scalar(members: &[(gimbal::Params, Vec<f64>)], tol: f64) -> (Vec<Vec<f64>>, usize) {
    let method = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: tol, atol: tol });
    let mut evals = 0;
    let finals = members
        .iter()
        .map(|(p, y0)| {
            let sys = ModelSystem::<gimbal::Model>::new(p.clone());
            let mut end = Vec::new();
            let stats = Integration::new(&sys, 0.0, y0, method)
                .run(&[T_END], |_, y| {
                    end = y.to_vec();
                    ControlFlow::Continue(())
                })
                .unwrap()
                .stats;
            evals += stats.rhs_evals;
            end
        })
        .collect();
    (finals, evals)
}

fn lanes<const N: usize>(members: &[(gimbal::Params, Vec<f64>)], tol: f64) -> (Vec<Vec<f64>>, usize) {
    let tol = Tolerances { rtol: tol, atol: tol };
    let (finals, stats) = final_states::<gimbal::Model, N>(members, T_END, &tableau::DOP853, tol).unwrap();
    (finals, stats.rhs_evals * N)
}

/// The members ordered by spin (the step size follows it), so that lanes share similar steps;
/// the finals put back in the original order.
fn lanes4_by_spin(members: &[(gimbal::Params, Vec<f64>)], tol: f64) -> (Vec<Vec<f64>>, usize) {
    let mut order: Vec<usize> = (0..members.len()).collect();
    order.sort_by(|a, b| members[*a].1[5].total_cmp(&members[*b].1[5]));
    let sorted: Vec<_> = order.iter().map(|k| members[*k].clone()).collect();
    let (finals, evals) = lanes::<4>(&sorted, tol);
    let mut back = vec![Vec::new(); finals.len()];
    for (slot, k) in order.iter().enumerate() {
        back[*k] = finals[slot].clone();
    }
    (back, evals)
}

fn worst(got: &[Vec<f64>], reference: &[Vec<f64>]) -> f64 {
    got.iter()
        .flatten()
        .zip(reference.iter().flatten())
        .map(|(a, b)| (a - b).abs() / b.abs().max(1.0))
        .fold(0.0, f64::max)
}

fn batch_lanes(c: &mut Criterion) {
    let members = members();
    let (reference, _) = scalar(&members, 1e-14);
    type Way = fn(&[(gimbal::Params, Vec<f64>)], f64) -> (Vec<Vec<f64>>, usize);
    let ways: [(&str, Way); 4] = [
        ("scalar", scalar),
        ("lanes4", lanes::<4>),
        ("lanes8", lanes::<8>),
        ("lanes4_by_spin", lanes4_by_spin),
    ];
    for tol in TOLERANCES {
        for (name, way) in ways {
            let (finals, evals) = way(&members, tol);
            let per_member = evals as f64 / MEMBERS as f64;
            let err = worst(&finals, &reference);
            eprintln!("{name} tol {tol:e}: {per_member:.0} RHS evaluations per member, error {err:.1e}");
        }
    }
    let mut g = c.benchmark_group("batch_lanes_256_members");
    g.sample_size(10);
    for tol in TOLERANCES {
        for (name, way) in ways {
            g.bench_function(format!("{name}/{tol:e}"), |b| b.iter(|| black_box(way(&members, tol))));
        }
    }
    g.finish();
}

criterion_group!(benches, batch_lanes);
criterion_main!(benches);
