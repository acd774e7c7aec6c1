//! Expression-engine benchmarks: construction rate, differentiation, simplification, tape cost.
//!
//! Run with `cargo bench -p kane-model --bench expr`; figures are recorded in BENCHMARKS.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use kane_model::expr::{Arena, ExprId, Func, SymbolId, Tape};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

const SYMBOLS: usize = 8;

/// A deep random expression of `ops` operations: each operation takes the previous result and a
/// random earlier node, so depth grows linearly. Returns the root and the symbols.
fn deep_random(ar: &mut Arena, ops: usize, seed: u64) -> (ExprId, Vec<SymbolId>) {
    deep_random_with(ar, ops, seed, true)
}

/// [`deep_random`], optionally without the transcendental functions.
fn deep_random_with(ar: &mut Arena, ops: usize, seed: u64, trig: bool) -> (ExprId, Vec<SymbolId>) {
    let mut rng = StdRng::seed_from_u64(seed);
    let syms: Vec<ExprId> = (0..SYMBOLS).map(|i| ar.constant(&format!("x{i}")).unwrap()).collect();
    let mut pool: Vec<ExprId> = syms.clone();
    for k in 1..=5 {
        pool.push(ar.integer(k));
    }
    let mut last = syms[0];
    for _ in 0..ops {
        let other = if rng.random_bool(0.5) {
            syms[rng.random_range(0..SYMBOLS)]
        } else {
            pool[rng.random_range(pool.len().saturating_sub(256)..pool.len())]
        };
        last = match rng.random_range(0..if trig { 10 } else { 8 }) {
            0..=2 => ar.add(&[last, other]).unwrap(),
            3..=5 => ar.mul(&[last, other]).unwrap(),
            6 => ar.sub(last, other).unwrap(),
            7 => ar.powi(last, 2).unwrap(),
            8 => ar.func(Func::Sin, last).unwrap(),
            _ => ar.func(Func::Cos, last).unwrap(),
        };
        pool.push(last);
    }
    let sym_ids = syms.iter().map(|e| ar.as_symbol(*e).unwrap()).collect();
    (last, sym_ids)
}

fn construction(c: &mut Criterion) {
    let mut ar = Arena::new();
    deep_random(&mut ar, 1_000_000, 7);
    println!("deep_random_1M_ops stores {} distinct nodes", ar.len());
    let mut g = c.benchmark_group("construction");
    g.sample_size(10);
    g.throughput(Throughput::Elements(1_000_000));
    g.bench_function("deep_random_1M_ops", |b| {
        b.iter(|| {
            let mut ar = Arena::new();
            let (root, _) = deep_random(&mut ar, 1_000_000, 7);
            black_box((root, ar.len()))
        })
    });
    g.finish();
}

fn differentiation(c: &mut Criterion) {
    let mut g = c.benchmark_group("differentiation");
    g.sample_size(10);
    g.bench_function("diff_deep_random_10k_ops", |b| {
        b.iter_batched(
            || {
                let mut ar = Arena::new();
                let (root, syms) = deep_random(&mut ar, 10_000, 11);
                (ar, root, syms[1])
            },
            |(mut ar, root, s)| black_box(ar.diff(root, s).unwrap()),
            BatchSize::LargeInput,
        )
    });
    g.finish();
}

/// `(a sin q + b cos q + c)^n (sin q - cos q)^n`, which trig simplification reduces to a
/// polynomial of degree at most one in `sin q`.
fn trig_polynomial(ar: &mut Arena, n: i64) -> ExprId {
    let [a, b, c, q] = ["a", "b", "c", "q"].map(|s| ar.constant(s).unwrap());
    let s = ar.sin(q).unwrap();
    let co = ar.cos(q).unwrap();
    let t1 = ar.mul(&[a, s]).unwrap();
    let t2 = ar.mul(&[b, co]).unwrap();
    let sum = ar.add(&[t1, t2, c]).unwrap();
    let diff = ar.sub(s, co).unwrap();
    let p1 = ar.powi(sum, n).unwrap();
    let p2 = ar.powi(diff, n).unwrap();
    ar.mul(&[p1, p2]).unwrap()
}

fn simplification(c: &mut Criterion) {
    let mut g = c.benchmark_group("simplification");
    g.sample_size(10);
    for n in [2, 4, 6] {
        g.bench_function(format!("trig_simplify_degree_{}", 2 * n), |b| {
            b.iter_batched(
                || {
                    let mut ar = Arena::new();
                    let e = trig_polynomial(&mut ar, n);
                    (ar, e)
                },
                |(mut ar, e)| black_box(ar.trig_simplify(e).unwrap()),
                BatchSize::LargeInput,
            )
        });
    }
    g.finish();
}

fn tape(c: &mut Criterion) {
    let mut g = c.benchmark_group("tape");
    for (label, trig) in [("arithmetic", false), ("with_sin_cos", true)] {
        let mut ar = Arena::new();
        let (root, syms) = deep_random_with(&mut ar, 100_000, 13, trig);
        let tape = Tape::compile(&ar, &[root], |s| syms.iter().position(|x| *x == s)).unwrap();
        let inputs: Vec<f64> = (0..SYMBOLS).map(|i| 0.1 + 0.05 * i as f64).collect();
        let mut regs = Vec::new();
        let mut out = [0.0];
        g.throughput(Throughput::Elements(tape.ops.len() as u64));
        g.bench_function(format!("eval_{label}_{}_instructions", tape.ops.len()), |b| {
            b.iter(|| {
                let inputs = black_box(&inputs);
                tape.eval_in(|k| inputs[k], &mut regs, &mut out);
                black_box(out[0])
            })
        });
    }
    g.finish();
}

criterion_group!(benches, construction, differentiation, simplification, tape);
criterion_main!(benches);
