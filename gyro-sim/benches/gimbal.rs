//! Gimbal benchmarks: generated `rhs` per call, Trial 3 to t = 5 at three tolerances, and Trial 3
//! over a range of tolerances for the high-order methods (`trial3_equal_error`), to compare them
//! at equal error.
//!
//! `cargo bench -p gyro-sim --bench gimbal`; it also prints RHS evaluations and the error against
//! the independent reference for each case (for `trial3_equal_error` against a tight reference
//! computed here). Figures are in BENCHMARKS.md.

use std::hint::black_box;
use std::ops::ControlFlow;

use criterion::{criterion_group, criterion_main, Criterion};
use gyro_sim::gimbal_gyroscope as gimbal;
use gyro_sim::{tableau, Integration, Method, Tolerances};
use gyro_sim::{ModelSystem, Reduced};
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
    let stats = Integration::new(&sys, 0.0, &y0, method)
        .run(&times, |_, y| {
            for i in 0..6 {
                let want = reference[k][i + 1];
                worst = worst.max((y[i] - want).abs() / want.abs().max(1.0));
            }
            k += 1;
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    (stats.rhs_evals, worst)
}

/// The hand-written RHS the 12 ns anchor describes, written from the hand derivation
/// (tests/tests/gimbal_hand_derivation.rs): constants computed once, `u2'` from `M22` alone and
/// the 1-3 block by its 2x2 inverse.
struct HandGimbal {
    i1: f64,
    jk: f64,
    j1k1: f64,
    k1: f64,
    r22: f64,
    y: f64,
    z: f64,
}

impl HandGimbal {
    fn new(p: &gimbal::Params) -> Self {
        let moments = |m: f64, h: f64| {
            let w = p.w;
            (2.0 / 3.0 * m * (h * w - w * w), m * h * h / 6.0 - m * (h - w) * (h - w) / 6.0)
        };
        let (i1, _) = moments(p.m1, p.h1);
        let (j1, j2) = moments(p.m2, p.h2);
        let k1 = p.m3 * p.l * p.l / 2.0;
        let k2 = p.m3 * p.l * p.l / 4.0 + p.m3 * p.h3 * p.h3 / 12.0;
        // M11 = I1 + (J1 + K1) c^2 + (J2 + K2) s^2 = (I1 + J2 + K2) + (J1 + K1 - J2 - K2) c^2
        HandGimbal {
            i1: i1 + j2 + k2,
            jk: j1 + k1 - j2 - k2,
            j1k1: k1,
            k1,
            r22: 1.0 / (j1 + k2),
            y: p.y_,
            z: p.z,
        }
    }

    /// `u'` from q2 and the speeds.
    #[inline]
    fn accelerations(&self, q2: f64, u1: f64, u2: f64, u3: f64) -> [f64; 3] {
        let (s, c) = q2.sin_cos();
        let m11 = self.i1 + self.jk * c * c;
        let m13 = self.j1k1 * c;
        let f1 = -self.y + 2.0 * self.jk * s * c * u1 * u2 + self.k1 * s * u2 * u3;
        let f2 = -self.z - self.jk * s * c * u1 * u1 - self.k1 * s * u1 * u3;
        let f3 = self.k1 * s * u1 * u2;
        let rdet = 1.0 / (m11 * self.k1 - m13 * m13);
        [(self.k1 * f1 - m13 * f3) * rdet, f2 * self.r22, (m11 * f3 - m13 * f1) * rdet]
    }

    #[inline]
    fn rhs(&self, y: &[f64], dy: &mut [f64]) {
        let a = self.accelerations(y[1], y[3], y[4], y[5]);
        dy[..3].copy_from_slice(&y[3..6]);
        dy[3..6].copy_from_slice(&a);
    }
}

/// The hand-written RHS on (q2, u1, u2, u3) alone: the cyclic q1 and q3 left out without any
/// copying, to see whether a smaller state pays.
struct HandGimbalReduced(HandGimbal);

impl gyro_sim::System for HandGimbalReduced {
    const FIXED_DIM: usize = 4;
    fn dim(&self) -> usize {
        4
    }
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        let a = self.0.accelerations(y[0], y[1], y[2], y[3]);
        dy[0] = y[2];
        dy[1..4].copy_from_slice(&a);
    }
}

/// A Trial 3 run of a system integrating (q2, u1, u2, u3) (states `keep` of the full one).
fn run_reduced<S: gyro_sim::System>(sys: &S, tol: f64, reference: &[Vec<f64>]) -> (usize, f64) {
    let (_, y0, times) = trial3();
    let keep = [1, 3, 4, 5];
    let y_red: Vec<f64> = keep.iter().map(|k| y0[*k]).collect();
    let mut worst: f64 = 0.0;
    let mut row = 0;
    let m = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: tol, atol: tol });
    let stats = Integration::new(sys, 0.0, &y_red, m)
        .run(&times, |_, y| {
            for (i, k) in keep.iter().enumerate() {
                let want = reference[row][k + 1];
                worst = worst.max((y[i] - want).abs() / want.abs().max(1.0));
            }
            row += 1;
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    (stats.rhs_evals, worst)
}

fn benches(c: &mut Criterion) {
    let p = gimbal::Params::default();
    let d = gimbal::param_constants(&p);
    let y = [0.1, 0.2, 0.3, 0.4, 0.5, 100.0];
    let mut dy = [0.0; 6];
    c.bench_function("gimbal_rhs_call", |b| {
        b.iter(|| {
            gimbal::rhs_with_constants(black_box(0.0), black_box(&y), black_box(&p), black_box(&d), &mut dy);
            black_box(dy[5])
        })
    });
    let mut p3 = p.clone();
    gimbal::Model::set_param(&mut p3, "Y", 10.0);
    let hand = HandGimbal::new(&p3);
    let (mut dy_hand, mut dy_gen) = ([0.0; 6], [0.0; 6]);
    hand.rhs(&y, &mut dy_hand);
    gimbal::rhs(0.0, &y, &p3, &mut dy_gen);
    for (a, b) in dy_hand.iter().zip(&dy_gen) {
        assert!(
            (a - b).abs() <= 1e-12 * a.abs().max(1.0),
            "hand-written {dy_hand:?} vs generated {dy_gen:?}"
        );
    }
    c.bench_function("hand_written_rhs_call", |b| {
        b.iter(|| {
            black_box(&hand).rhs(black_box(&y), &mut dy);
            black_box(dy[5])
        })
    });
    // Latency: each call's q2 and u2 depend on the last call's result, as a stage depends on
    // the stage before in an integrator.
    c.bench_function("gimbal_rhs_latency", |b| {
        let mut yy = y;
        b.iter(|| {
            gimbal::rhs_with_constants(0.0, &yy, black_box(&p), black_box(&d), &mut dy);
            yy[1] = 0.1 + 1e-9 * dy[5];
            yy[4] = 0.4 + 1e-9 * dy[3];
        })
    });
    c.bench_function("hand_written_rhs_latency", |b| {
        let mut yy = y;
        b.iter(|| {
            black_box(&hand).rhs(&yy, &mut dy);
            yy[1] = 0.1 + 1e-9 * dy[5];
            yy[4] = 0.4 + 1e-9 * dy[3];
        })
    });
    let reference = reference();
    let reference = reference.as_slice();
    let mut g = c.benchmark_group("trial3_to_t5");
    for tab in [&tableau::DOPRI5, &tableau::DOP853, &tableau::VERN7, &tableau::VERN9] {
        for tol in [1e-6, 1e-9, 1e-12] {
            let m = Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol });
            let (evals, err) = run(m, reference);
            println!("{} tol {tol:e}: {evals} RHS evaluations, largest relative error {err:.2e}", tab.name);
            g.bench_function(format!("{}_tol_{tol:e}", tab.name), |b| {
                b.iter(|| black_box(run(m, reference)))
            });
        }
    }
    // Q2 and the speeds only: the cyclic q1 and q3 are not integrated, through gyro-sim's
    // wrapper around the generated rhs and with the hand-written reduced RHS.
    let (full, _, _) = trial3();
    let wrapped = Reduced::new(&full, vec![1, 3, 4, 5]);
    let (evals, err) = run_reduced(&wrapped, 1e-9, reference);
    println!("dop853 reduced (q1, q3 left out) tol 1e-9: {evals} RHS evaluations, largest relative error {err:.2e}");
    g.bench_function("dop853_reduced_tol_1e-9", |b| {
        b.iter(|| black_box(run_reduced(&wrapped, 1e-9, reference)))
    });
    let hand4 = HandGimbalReduced(HandGimbal::new(&p3));
    let (evals, err) = run_reduced(&hand4, 1e-9, reference);
    println!(
        "dop853 hand-written 4-state RHS tol 1e-9: {evals} RHS evaluations, largest relative error {err:.2e}"
    );
    g.bench_function("dop853_hand_written_4_states_tol_1e-9", |b| {
        b.iter(|| black_box(run_reduced(&hand4, 1e-9, reference)))
    });
    for step in [1e-3, 1e-4] {
        let m = Method::Fixed(&tableau::RK4, step);
        let (evals, err) = run(m, reference);
        println!("rk4 step {step:e}: {evals} RHS evaluations, largest relative error {err:.2e}");
        g.bench_function(format!("rk4_step_{step:e}"), |b| b.iter(|| black_box(run(m, reference))));
    }
    g.finish();
    equal_error(c);
}

/// Trial 3's states at its output times, `t` first as in the reference file, from one run.
fn trajectory(method: Method) -> Vec<Vec<f64>> {
    let (sys, y0, times) = trial3();
    let mut rows = Vec::new();
    let mut k = 0;
    Integration::new(&sys, 0.0, &y0, method)
        .run(&times, |_, y| {
            rows.push([&[times[k]][..], y].concat());
            k += 1;
            ControlFlow::Continue(())
        })
        .unwrap();
    rows
}

/// The largest difference of two trajectories in the measure of [`run`].
fn difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    let pairs = a.iter().zip(b).flat_map(|(ra, rb)| ra[1..].iter().zip(&rb[1..]));
    pairs.map(|(x, y)| (x - y).abs() / y.abs().max(1.0)).fold(0.0, f64::max)
}

/// DOP853, Vern7, Vern9 and the Taylor method on Trial 3 from tolerance 1e-6 to 1e-14, each
/// run's error measured
/// against DOP853 at 1e-15 (Vern9 at 1e-15 agrees with it, printed first): the time at a given
/// error follows by interpolating between tolerances.
fn equal_error(c: &mut Criterion) {
    let tight = |tab| Method::Adaptive(tab, Tolerances { rtol: 1e-15, atol: 1e-15 });
    let reference = trajectory(tight(&tableau::DOP853));
    let check = trajectory(tight(&tableau::VERN9));
    let file = self::reference();
    println!(
        "tight reference: dop853 and vern9 at 1e-15 differ by {:.2e}; the file's reference by {:.2e}",
        difference(&check, &reference),
        difference(&file, &reference)
    );
    let mut g = c.benchmark_group("trial3_equal_error");
    let rk = [&tableau::DOP853, &tableau::VERN7, &tableau::VERN9].map(|tab| (tab.name, Some(tab)));
    for (name, tab) in rk.into_iter().chain([("taylor", None)]) {
        for exp in 6..=14 {
            let tol = Tolerances { rtol: 10f64.powi(-exp), atol: 10f64.powi(-exp) };
            let m = tab.map_or(Method::Taylor(tol), |tab| Method::Adaptive(tab, tol));
            let (evals, err) = run(m, &reference);
            let tol = tol.rtol;
            println!("{name} tol {tol:e}: {evals} RHS evaluations, error {err:.2e} (tight reference)");
            g.bench_function(format!("{name}_tol_{tol:e}"), |b| b.iter(|| black_box(run(m, &reference))));
        }
    }
    g.finish();
}

criterion_group!(gimbal_benches, benches);
criterion_main!(gimbal_benches);
