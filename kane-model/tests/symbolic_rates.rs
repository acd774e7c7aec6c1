//! The speed rates formed as expressions (what a file reads after `SOLVE(ZERO, U1', ...)`)
//! equal the numeric solve at random states: the Whipple bicycle (three motion constraints)
//! and the gimbal (none).

use kane_model::expr::SymbolId;
use kane_model::lang;
use rand::{Rng, SeedableRng};

fn rates_agree(file: &str) {
    let src = std::fs::read_to_string(file).unwrap();
    let mut m = lang::load(file, &src).unwrap_or_else(|r| panic!("{}", r.render()));
    let eqs = m.equations.clone().unwrap();
    let symbolic = eqs.symbolic_rates(&mut m.model.ar).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(37);
    let ar = &m.model.ar;
    let inputs: Vec<(String, f64)> =
        m.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
    for _ in 0..20 {
        let state: Vec<(SymbolId, f64)> =
            eqs.coordinates.iter().chain(&eqs.speeds).map(|s| (*s, rng.random_range(-0.6..0.6))).collect();
        let value = |s: SymbolId| {
            state.iter().find(|(x, _)| *x == s).map(|(_, v)| *v).or_else(|| {
                let name = ar.symbol_info(s).name.to_ascii_uppercase();
                inputs.iter().find(|(n, _)| *n == name).map(|(_, v)| *v).or(Some(0.7))
            })
        };
        let numeric = eqs.rates_at(ar, &value).unwrap();
        let formed = ar.eval(&symbolic.speeds, value).unwrap();
        for (a, b) in formed.iter().zip(&numeric.speeds) {
            assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{file}: {a} against {b}");
        }
        let dependent = ar.eval(&symbolic.dependent, value).unwrap();
        for (a, b) in dependent.iter().zip(&numeric.dependent) {
            assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{file}: dependent {a} against {b}");
        }
    }
}

#[test]
fn the_constrained_bicycle_s_rates_as_expressions_equal_its_numeric_solve() {
    rates_agree(concat!(env!("CARGO_MANIFEST_DIR"), "/models/whipple_bicycle.al"));
}

#[test]
fn the_gimbal_s_rates_as_expressions_equal_its_numeric_solve() {
    rates_agree(concat!(env!("CARGO_MANIFEST_DIR"), "/models/gimbal_gyroscope.al"));
}
