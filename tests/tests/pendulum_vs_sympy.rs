//! The n-link pendulum (n = 1..5) derived by kane-model agrees with SymPy's KanesMethod at random
//! states. Fixtures: tests/data/n_link_pendulum_sympy.json, made by make_pendulum_fixtures.py.

use std::collections::HashMap;

use kane_model::models::n_link_pendulum;
use serde::Deserialize;

#[derive(Deserialize)]
struct Fixtures {
    cases: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    n: usize,
    values: HashMap<String, f64>,
    mass_matrix: Vec<Vec<f64>>,
    forcing: Vec<f64>,
}

#[test]
fn n_link_pendulum_matches_sympy() {
    let text = include_str!("../data/n_link_pendulum_sympy.json");
    let fixtures: Fixtures = serde_json::from_str(text).unwrap();
    assert_eq!(fixtures.cases.len(), 15);
    for case in fixtures.cases {
        let (mut model, _, _) = n_link_pendulum(case.n).unwrap();
        let eqs = model.kane().unwrap();
        let values: Vec<(&str, f64)> = case.values.iter().map(|(k, v)| (k.as_str(), *v)).collect();
        let ar = &model.ar;
        for i in 0..case.n {
            for j in 0..case.n {
                let got = ar.eval_named(eqs.mass_matrix[i][j], &values).unwrap();
                let want = case.mass_matrix[i][j];
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs().max(1.0),
                    "n={} M[{i}][{j}] {got} vs {want}",
                    case.n
                );
            }
            let got = ar.eval_named(eqs.forcing[i], &values).unwrap();
            let want = case.forcing[i];
            assert!((got - want).abs() <= 1e-12 * want.abs().max(1.0), "n={} f[{i}] {got} vs {want}", case.n);
        }
    }
}
