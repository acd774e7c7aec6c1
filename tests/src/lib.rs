//! Workspace-level tests live in `tests/tests/`; this library is the harness they and
//! gyro-sim's tests share: generated code against the interpreted equations of the same model,
//! and runs against reference trajectories.

pub mod bins;
pub mod runtimes;

use kane_model::expr::{Arena, ExprId};
use kane_model::mechanics::KaneEquations;
use kane_model::runtime::GeneratedModel;
use rand::rngs::StdRng;
use rand::SeedableRng;

/// The value of `e` with symbols looked up by upper-case name.
pub fn value_of(ar: &Arena, e: ExprId, by_name: &dyn Fn(&str) -> Option<f64>) -> f64 {
    ar.eval(&[e], |s| by_name(&ar.symbol_info(s).name.to_ascii_uppercase())).map_or(f64::NAN, |v| v[0])
}

/// `q'` and `u'` of interpreted equations (solved numerically, constraints included) at the
/// named values; NaN where they cannot be evaluated.
pub fn interpreted_rhs(
    ar: &Arena,
    eqs: &KaneEquations,
    by_name: &dyn Fn(&str) -> Option<f64>,
) -> (Vec<f64>, Vec<f64>) {
    let value = |s: kane_model::expr::SymbolId| by_name(&ar.symbol_info(s).name.to_ascii_uppercase());
    match eqs.rates_at(ar, &value) {
        Ok(r) => (r.coordinates, r.speeds),
        Err(_) => (vec![f64::NAN; eqs.coordinates.len()], vec![f64::NAN; eqs.speeds.len()]),
    }
}

/// `y'` of a lowered program at parameters `values` (by upper-case name) and state `y`.
pub fn lowered_rhs(
    spec: &kane_model::spec::ModelSpec,
    lowered: &kane_model::program::Lowered,
    values: &rustc_hash::FxHashMap<String, f64>,
    y: &[f64],
) -> Vec<f64> {
    use kane_model::program::ir::Input;
    let params: Vec<f64> =
        lowered.params.iter().map(|s| values[&spec.symbol_name(*s).to_ascii_uppercase()]).collect();
    let p = &lowered.program;
    let mut constants = vec![0.0; p.param_constants.results.len()];
    p.param_constants.eval(|i| if let Input::Param(k) = i { params[k] } else { f64::NAN }, &mut constants);
    let mut out = vec![0.0; p.rhs.results.len()];
    let read = |i: Input| match i {
        Input::State(k) => y[k],
        Input::Param(k) => params[k],
        Input::ParamConstant(k) => constants[k],
        _ => 0.0,
    };
    p.rhs.eval(read, &mut out);
    out
}

/// Largest difference of `got` from `want`, relative to the largest of 1 and `|want|`'s entries.
pub fn normwise(got: &[f64], want: &[f64]) -> f64 {
    let diff = got.iter().zip(want).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    diff / want.iter().map(|v| v.abs()).fold(1.0, f64::max)
}

/// How random parameters and states are drawn.
pub struct Sampling<'a> {
    /// The random number generator's seed.
    pub seed: u64,
    /// Samples to compare.
    pub samples: usize,
    /// A parameter's value by name.
    pub param: &'a dyn Fn(&str, &mut StdRng) -> f64,
    /// State `i`'s value.
    pub state: &'a dyn Fn(usize, &mut StdRng) -> f64,
}

/// The largest normwise relative difference (of `q'` and of `u'` apiece) between `M::rhs` and
/// the interpreted equations `eqs` (with their arena) over random samples.
pub fn worst_generated_difference<M: GeneratedModel>(
    ar: &Arena,
    eqs: &KaneEquations,
    sampling: &Sampling<'_>,
) -> f64 {
    let mut rng = StdRng::seed_from_u64(sampling.seed);
    let nq = eqs.coordinates.len();
    let mut worst: f64 = 0.0;
    for _ in 0..sampling.samples {
        let mut p = M::Params::default();
        let mut vals: Vec<(String, f64)> = Vec::new();
        for name in M::INFO.param_names {
            let v = (sampling.param)(name, &mut rng);
            assert!(M::set_param(&mut p, name, v), "{name}");
            vals.push((name.to_ascii_uppercase(), v));
        }
        let y: Vec<f64> = (0..M::INFO.state_names.len()).map(|i| (sampling.state)(i, &mut rng)).collect();
        vals.extend(M::INFO.state_names.iter().zip(&y).map(|(n, v)| (n.to_ascii_uppercase(), *v)));
        let by_name = |n: &str| vals.iter().find(|(k, _)| k == n).map(|(_, v)| *v);
        let (qdot, udot) = interpreted_rhs(ar, eqs, &by_name);
        let mut got = vec![0.0; y.len()];
        M::rhs(0.0, &y, &p, &mut got);
        worst = worst.max(normwise(&got[..nq], &qdot)).max(normwise(&got[nq..], &udot));
    }
    worst
}

/// The largest error of `rows` (t, then values in model units) against a reference CSV with a
/// header and the same columns, relative to max(1, |reference|); panics if times differ.
pub fn reference_error(rows: &[Vec<f64>], reference_csv: &str) -> f64 {
    assert_eq!(rows.len(), reference_csv.lines().count() - 1, "rows against reference lines");
    let mut worst: f64 = 0.0;
    for (row, line) in rows.iter().zip(reference_csv.lines().skip(1)) {
        let want: Vec<f64> = line.split(',').map(|x| x.trim().parse().unwrap_or(f64::NAN)).collect();
        assert!((row[0] - want[0]).abs() < 1e-12, "times {} vs {}", row[0], want[0]);
        for (got, want) in row[1..].iter().zip(&want[1..]) {
            worst = worst.max((got - want).abs() / want.abs().max(1.0));
        }
    }
    worst
}
