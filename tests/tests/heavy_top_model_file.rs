//! The EJS top as a model file (DIRCOS with Euler parameters, KINDIFFS, inertia by shape)
//! derives the equations of the Rust-API top.

use kane_model::expr::{Arena, ExprId, SymbolId};
use kane_model::lang;
use kane_model::models::HeavyTop;
use rand::{Rng, SeedableRng};

const TOP: &str = include_str!("../../kane-model/models/heavy_top.al");

fn value(ar: &Arena, e: ExprId, vals: &[(&str, f64)]) -> f64 {
    let by = |s: SymbolId| {
        let n = ar.symbol_info(s).name.to_ascii_uppercase();
        vals.iter().find(|(k, _)| k.eq_ignore_ascii_case(&n)).map(|(_, v)| *v)
    };
    ar.eval(&[e], by).unwrap()[0]
}

#[test]
fn model_file_top_equals_the_rust_api_top() {
    let loaded = lang::load("heavy_top.al", TOP).unwrap_or_else(|r| panic!("{}", r.render()));
    let eqs = loaded.equations.as_ref().unwrap();
    let mut api = HeavyTop::new().unwrap();
    let api_eqs = api.model.kane().unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(31);
    for _ in 0..50 {
        let q: Vec<f64> = (0..4).map(|_| rng.random_range(-1.0..1.0)).collect();
        let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        let (s, v1, v2, v3) = (q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
        let w: Vec<f64> = (0..3).map(|_| rng.random_range(-3.0..3.0)).collect();
        let (m, g, r, d) = (
            rng.random_range(0.5..2.0),
            rng.random_range(0.5..2.0),
            rng.random_range(0.5..2.0),
            rng.random_range(0.5..2.0),
        );
        let file = [
            ("E1", v1),
            ("E2", v2),
            ("E3", v3),
            ("E4", s),
            ("W1", w[0]),
            ("W2", w[1]),
            ("W3", w[2]),
            ("M", m),
            ("G", g),
            ("RR", r),
            ("D", d),
            ("AXIAL", 0.4),
        ];
        let api_vals = [
            ("e1", v1),
            ("e2", v2),
            ("e3", v3),
            ("e0", s),
            ("w1", w[0]),
            ("w2", w[1]),
            ("w3", w[2]),
            ("M", m),
            ("g", g),
            ("R", r),
            ("d", d),
        ];
        for i in 0..3 {
            let a = value(&loaded.model.ar, eqs.forcing[i], &file);
            let b = value(&api.model.ar, api_eqs.forcing[i], &api_vals);
            assert!((a - b).abs() < 1e-12 * a.abs().max(1.0), "f{i}: {a} vs {b}");
            for j in 0..3 {
                let a = value(&loaded.model.ar, eqs.mass_matrix[i][j], &file);
                let b = value(&api.model.ar, api_eqs.mass_matrix[i][j], &api_vals);
                assert!((a - b).abs() < 1e-12 * a.abs().max(1.0), "M{i}{j}: {a} vs {b}");
            }
        }
        // Kinematics: E1..E4 here are e1, e2, e3, e0 there.
        for (i, k) in [1usize, 2, 3, 0].iter().enumerate() {
            let a = value(&loaded.model.ar, eqs.kinematics[i], &file);
            let b = value(&api.model.ar, api_eqs.kinematics[*k], &api_vals);
            assert!((a - b).abs() < 1e-12, "e'{i}: {a} vs {b}");
        }
    }
}

#[test]
fn kindiffs_of_a_body_sequence_inverts_the_angular_velocity() {
    // KINDIFFS(N, B, BODY312, ...) with W_B_N> = U1*B1> + U2*B2> + U3*B3>: the angle rates it
    // gives reproduce those speeds.
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q{3}', U{3}'\nDIRCOS(N, B, BODY312, Q1, Q2, Q3)\n\
               W_B_N> = U1*B1> + U2*B2> + U3*B3>\nKINDIFFS(N, B, BODY312, Q1, Q2, Q3)\n";
    let mut loaded = lang::load("k.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    let b = loaded.model.frame("B").unwrap();
    let implied = loaded.model.orientation_angular_velocity(b).unwrap();
    let implied = loaded.model.express(&implied, b).unwrap();
    // Replace the rates Qi' by the kinematic equations KINDIFFS produced.
    let mut map = rustc_hash::FxHashMap::default();
    for n in ["Q1", "Q2", "Q3"] {
        let s = loaded.model.ar.lookup(n).unwrap();
        let d = loaded.model.ar.lookup(&format!("{n}'")).unwrap();
        let rhs = loaded.model.kinematics(s).unwrap();
        map.insert(loaded.model.ar.symbol_expr(d), rhs);
    }
    let w = loaded.model.ar.subs_many(&implied, &map).unwrap();
    let vals = [("Q1", 0.3), ("Q2", -0.7), ("Q3", 1.1), ("U1", 0.4), ("U2", -1.3), ("U3", 2.2)];
    for (i, u) in [0.4, -1.3, 2.2].iter().enumerate() {
        let got = value(&loaded.model.ar, w[i], &vals);
        assert!((got - u).abs() < 1e-12, "w{} {got} vs {u}", i + 1);
    }
}
