//! Planar relative-angle chains (rigid links pinned end to end, and point masses; n = 5 and 8)
//! derived by kane-model agree with SymPy's KanesMethod at random states: the interpreted mass
//! matrix, forcing and `u' = M^-1 f`, and the generated `rhs`. Fixtures:
//! tests/data/chain_sympy.json and the model files tests/models/chain_*_rel_*.al, both written
//! by tests/data/make_chain_fixtures.py. Differences are relative to the largest entry of
//! SymPy's matrix or vector.

use std::collections::HashMap;

use kane_model::runtime::GeneratedModel;
use kane_tests::value_of;
use nalgebra::{DMatrix, DVector};
use serde::Deserialize;

mod chain_rigid_rel_5 {
    kane_derive::model!("models/chain_rigid_rel_5.al");
}

mod chain_rigid_rel_8 {
    kane_derive::model!("models/chain_rigid_rel_8.al");
}

mod chain_particle_rel_5 {
    kane_derive::model!("models/chain_particle_rel_5.al");
}

mod chain_particle_rel_8 {
    kane_derive::model!("models/chain_particle_rel_8.al");
}

const TOL: f64 = 1e-12;

#[derive(Deserialize)]
struct Fixtures {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    model: String,
    text: String,
    n: usize,
    values: HashMap<String, f64>,
    mass_matrix: Vec<Vec<f64>>,
    forcing: Vec<f64>,
    udot: Vec<f64>,
}

/// The model files the fixtures name, as committed.
fn model_file(name: &str) -> &'static str {
    match name {
        "chain_rigid_rel_5.al" => include_str!("../models/chain_rigid_rel_5.al"),
        "chain_rigid_rel_8.al" => include_str!("../models/chain_rigid_rel_8.al"),
        "chain_particle_rel_5.al" => include_str!("../models/chain_particle_rel_5.al"),
        "chain_particle_rel_8.al" => include_str!("../models/chain_particle_rel_8.al"),
        _ => panic!("no model file {name}"),
    }
}

fn fixtures() -> Vec<Case> {
    let fixtures: Fixtures = serde_json::from_str(include_str!("../data/chain_sympy.json")).unwrap();
    fixtures.cases
}

/// The largest difference of `got` from `want`, relative to `want`'s largest entry.
fn relative(got: &[f64], want: &[f64]) -> f64 {
    let diff = got.iter().zip(want).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    diff / want.iter().map(|v| v.abs()).fold(0.0, f64::max)
}

#[test]
fn the_fixtures_are_the_committed_model_files() {
    let cases = fixtures();
    assert_eq!(cases.len(), 12);
    for case in &cases {
        assert_eq!(
            case.text,
            model_file(&case.model),
            "{}: the model file differs from the fixture's",
            case.model
        );
    }
}

#[test]
fn interpreted_chains_match_sympy() {
    for case in fixtures() {
        let loaded = kane_model::lang::load(&case.model, model_file(&case.model)).unwrap();
        let eqs = loaded.equations.as_ref().unwrap();
        let ar = &loaded.model.ar;
        let n = case.n;
        assert_eq!(eqs.speeds.len(), n, "{}", case.model);
        let by_name = |name: &str| case.values.get(name).copied();
        let m = DMatrix::from_fn(n, n, |i, j| value_of(ar, eqs.mass_matrix[i][j], &by_name));
        let f = DVector::from_fn(n, |i, _| value_of(ar, eqs.forcing[i], &by_name));
        let udot = m.clone().lu().solve(&f).unwrap();
        let got_m: Vec<f64> =
            (0..n).flat_map(|i| (0..n).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).collect();
        let want_m: Vec<f64> = case.mass_matrix.iter().flatten().copied().collect();
        let dm = relative(&got_m, &want_m);
        let df = relative(f.as_slice(), &case.forcing);
        let du = relative(udot.as_slice(), &case.udot);
        assert!(dm <= TOL, "{}: mass matrix differs by {dm:e}", case.model);
        assert!(df <= TOL, "{}: forcing differs by {df:e}", case.model);
        assert!(du <= TOL, "{}: u' differs by {du:e}", case.model);
    }
}

/// The generated `rhs` of `model` against SymPy's `u'` (and `q' = u`) at each of its cases.
fn generated_matches_sympy<M: GeneratedModel>(model: &str) {
    let cases: Vec<Case> = fixtures().into_iter().filter(|c| c.model == model).collect();
    assert_eq!(cases.len(), 3);
    for case in cases {
        let n = case.n;
        assert_eq!(M::INFO.n_coordinates, n);
        let mut p = M::Params::default();
        for name in M::INFO.param_names {
            let v = case.values[&name.to_ascii_uppercase()];
            assert!(M::set_param(&mut p, name, v), "{name}");
        }
        let y: Vec<f64> = M::INFO.state_names.iter().map(|s| case.values[&s.to_ascii_uppercase()]).collect();
        let mut dy = vec![0.0; 2 * n];
        M::rhs(0.0, &y, &p, &mut dy);
        let dq = relative(&dy[..n], &y[n..]);
        let du = relative(&dy[n..], &case.udot);
        assert!(dq <= TOL, "{model}: q' differs from u by {dq:e}");
        assert!(du <= TOL, "{model}: generated u' differs from SymPy's by {du:e}");
    }
}

#[test]
fn generated_rigid_chain_5_matches_sympy() {
    generated_matches_sympy::<chain_rigid_rel_5::Model>("chain_rigid_rel_5.al");
}

#[test]
fn generated_rigid_chain_8_matches_sympy() {
    generated_matches_sympy::<chain_rigid_rel_8::Model>("chain_rigid_rel_8.al");
}

#[test]
fn generated_particle_chain_5_matches_sympy() {
    generated_matches_sympy::<chain_particle_rel_5::Model>("chain_particle_rel_5.al");
}

#[test]
fn generated_particle_chain_8_matches_sympy() {
    generated_matches_sympy::<chain_particle_rel_8::Model>("chain_particle_rel_8.al");
}
