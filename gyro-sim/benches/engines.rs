//! The three engines side by side in one process: `rhs` per call compiled by rustc (the
//! model's Rust from `kane_derive::model!`), JIT-compiled and evaluated, on the gimbal, the
//! heavy top, the bicycle, the four-bar loop, the rolling disc and the 40-link chain; the time
//! the JIT engine takes to be ready; Trial 3 on the built-in model and on the JIT engine.
//!
//! `cargo bench -p gyro-sim --bench engines`; figures are in BENCHMARKS.md.

use std::hint::black_box;
use std::ops::ControlFlow;
use std::path::Path;
use std::sync::Arc;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use gyro_sim::{tableau, Integration, JitSystem, Method, ModelFile, ModelSystem, System, Tolerances};
use kane_model::jit::JitModel;
use kane_model::program::ProgramModel;
use kane_model::runtime::GeneratedModel;

mod gimbal {
    kane_derive::model!("../kane-model/models/gimbal_gyroscope.al");
}
mod heavy_top {
    kane_derive::model!("../kane-model/models/heavy_top.al");
}
mod bicycle {
    kane_derive::model!("../kane-model/models/whipple_bicycle.al");
}
mod four_bar {
    kane_derive::model!("../kane-model/models/four_bar.al");
}
mod rolling_disc {
    kane_derive::model!("tests/data/rolling_disc.al");
}
mod chain40 {
    kane_derive::model!("tests/data/chain40_rigid.al");
}

/// The lowered program of a model file (no drawing).
fn program(file: &str) -> Arc<ProgramModel> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
    let source = std::fs::read_to_string(&path).unwrap();
    ModelFile::from_source(&path, source, false).unwrap().program
}

/// `rhs` per call on the three engines, at the compiled model's default parameters and a
/// fixed state; the JIT's derivative is checked against the compiled one first.
fn rhs_per_call<M: GeneratedModel>(c: &mut Criterion, name: &str, file: &str) {
    let evaluator = program(file);
    let jit = JitModel::new(evaluator.clone()).unwrap();
    let info = evaluator.info();
    let p = M::Params::default();
    let params: Vec<f64> = info.param_names.iter().map(|n| M::param(&p, n).unwrap_or(f64::NAN)).collect();
    let n = info.state_names.len();
    let y: Vec<f64> = (0..n).map(|i| 0.1 + 0.37 * ((i * 7) % 11) as f64 / 11.0).collect();
    let d = M::param_constants(&p);
    let constants = evaluator.param_constants(&params);
    let (mut compiled, mut jitted) = (vec![0.0; n], vec![0.0; n]);
    M::rhs_with_constants(0.0, &y, &p, &d, &mut compiled);
    jit.rhs(0.0, &y, &params, &constants, &mut jitted);
    for (a, b) in compiled.iter().zip(&jitted) {
        assert!(
            (a - b).abs() <= 1e-12 * a.abs().max(1.0),
            "{name}: compiled {compiled:?} against JIT {jitted:?}"
        );
    }
    let mut g = c.benchmark_group(format!("rhs_call/{name}"));
    let mut dy = vec![0.0; n];
    g.bench_function("compiled", |b| {
        b.iter(|| {
            M::rhs_with_constants(black_box(0.0), black_box(&y), black_box(&p), black_box(&d), &mut dy);
            black_box(dy[n - 1])
        })
    });
    g.bench_function("jit", |b| {
        b.iter(|| {
            jit.rhs(black_box(0.0), black_box(&y), black_box(&params), black_box(&constants), &mut dy);
            black_box(dy[n - 1])
        })
    });
    // Latency: each call's state depends on the last call's result, as in an integrator.
    g.bench_function("compiled_latency", |b| {
        let mut yy = y.clone();
        b.iter(|| {
            M::rhs_with_constants(0.0, &yy, &p, &d, &mut dy);
            yy[0] = y[0] + 1e-9 * dy[n - 1];
        })
    });
    g.bench_function("jit_latency", |b| {
        let mut yy = y.clone();
        b.iter(|| {
            jit.rhs(0.0, &yy, &params, &constants, &mut dy);
            yy[0] = y[0] + 1e-9 * dy[n - 1];
        })
    });
    let mut regs = Vec::new();
    g.bench_function("instant", |b| {
        b.iter(|| {
            evaluator.rhs(black_box(0.0), black_box(&y), &params, &constants, &mut dy, &mut regs);
            black_box(dy[n - 1])
        })
    });
    g.finish();
    let mut g = c.benchmark_group("jit_ready");
    g.sample_size(10).measurement_time(Duration::from_secs(3));
    g.bench_function(name, |b| b.iter(|| black_box(JitModel::new(evaluator.clone()).unwrap())));
    g.finish();
}

/// Trial 3's six states at its 101 output times, from one run; and the largest error against
/// the reference.
fn trial3<S: System>(sys: &S, method: Method, reference: &[Vec<f64>]) -> f64 {
    let y0 = [0.0, 0.0, 0.0, 0.0, 0.0, 100.0];
    let times: Vec<f64> = (0..=100).map(|i| i as f64 * 0.05).collect();
    let (mut worst, mut k) = (0.0f64, 0);
    Integration::new(sys, 0.0, &y0, method)
        .run(&times, |_, y| {
            for i in 0..6 {
                let want = reference[k][i + 1];
                worst = worst.max((y[i] - want).abs() / want.abs().max(1.0));
            }
            k += 1;
            ControlFlow::Continue(())
        })
        .unwrap();
    worst
}

fn trial3_engines(c: &mut Criterion) {
    let reference: Vec<Vec<f64>> = include_str!("../tests/data/gimbal_trial3.csv")
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let mut p = gyro_sim::gimbal_gyroscope::Params::default();
    gyro_sim::gimbal_gyroscope::Model::set_param(&mut p, "Y", 10.0);
    gyro_sim::gimbal_gyroscope::Model::set_param(&mut p, "Z", 10.0);
    let builtin = ModelSystem::<gyro_sim::gimbal_gyroscope::Model>::new(p.clone());
    let evaluator = program("../kane-model/models/gimbal_gyroscope.al");
    let jit = JitModel::new(evaluator.clone()).unwrap();
    let params: Vec<f64> = evaluator
        .info()
        .param_names
        .iter()
        .map(|n| gyro_sim::gimbal_gyroscope::Model::param(&p, n).unwrap())
        .collect();
    let jit_system = JitSystem::new(&jit, params);
    let mut g = c.benchmark_group("trial3_engines");
    let tolerances = |tol: f64| Tolerances { rtol: tol, atol: tol };
    let methods = [
        ("dop853", 1e-6, Method::Adaptive(&tableau::DOP853, tolerances(1e-6))),
        ("dop853", 1e-9, Method::Adaptive(&tableau::DOP853, tolerances(1e-9))),
        ("vern9", 1e-12, Method::Adaptive(&tableau::VERN9, tolerances(1e-12))),
        ("taylor", 1e-9, Method::Taylor(tolerances(1e-9))),
        ("taylor", 1e-12, Method::Taylor(tolerances(1e-12))),
    ];
    for (name, tol, m) in methods {
        let (e_builtin, e_jit) = (trial3(&builtin, m, &reference), trial3(&jit_system, m, &reference));
        println!("{name} tol {tol:e}: error built-in {e_builtin:.3e}, JIT {e_jit:.3e}");
        g.bench_function(format!("{name}_{tol:e}/built_in"), |b| {
            b.iter(|| black_box(trial3(&builtin, m, &reference)))
        });
        g.bench_function(format!("{name}_{tol:e}/jit"), |b| {
            b.iter(|| black_box(trial3(&jit_system, m, &reference)))
        });
    }
    g.finish();
}

fn benches(c: &mut Criterion) {
    rhs_per_call::<gimbal::Model>(c, "gimbal", "../kane-model/models/gimbal_gyroscope.al");
    rhs_per_call::<heavy_top::Model>(c, "heavy_top", "../kane-model/models/heavy_top.al");
    rhs_per_call::<bicycle::Model>(c, "bicycle", "../kane-model/models/whipple_bicycle.al");
    rhs_per_call::<four_bar::Model>(c, "four_bar", "../kane-model/models/four_bar.al");
    rhs_per_call::<rolling_disc::Model>(c, "rolling_disc", "tests/data/rolling_disc.al");
    rhs_per_call::<chain40::Model>(c, "chain40", "tests/data/chain40_rigid.al");
    trial3_engines(c);
}

criterion_group!(engines, benches);
criterion_main!(engines);
