//! The paper's gimbal written as a model file derives exactly the equations of the Rust-API
//! model; editing the geometry in the file changes the equations accordingly.

use kane_model::expr::{Arena, ExprId, SymbolId};
use kane_model::lang;
use kane_model::mechanics::KaneEquations;
use kane_model::models::GimbalGyroscope;
use rand::{Rng, SeedableRng};

const GIMBAL: &str = include_str!("../../kane-model/models/gimbal_gyroscope.al");

/// Value of `e` (in arena `ar`) with symbols looked up by upper-cased name in `vals`.
fn value(ar: &Arena, e: ExprId, vals: &[(String, f64)]) -> f64 {
    let by_name = |s: SymbolId| {
        let n = ar.symbol_info(s).name.to_ascii_uppercase();
        vals.iter().find(|(k, _)| *k == n).map(|(_, v)| *v)
    };
    ar.eval(&[e], by_name).unwrap()[0]
}

fn random_state(rng: &mut impl Rng) -> Vec<(String, f64)> {
    ["M1", "M2", "M3", "H1", "H2", "H3", "L", "W", "Y", "Z", "Q1", "Q2", "Q3", "U1", "U2", "U3", "G", "DX"]
        .iter()
        .map(|n| (n.to_string(), rng.random_range(0.2..2.0)))
        .collect()
}

fn assert_same(a: (&Arena, &KaneEquations), b: (&Arena, &KaneEquations), rng: &mut impl Rng) {
    for _ in 0..50 {
        let vals = random_state(rng);
        for r in 0..3 {
            for s in 0..3 {
                let (x, y) =
                    (value(a.0, a.1.mass_matrix[r][s], &vals), value(b.0, b.1.mass_matrix[r][s], &vals));
                assert!((x - y).abs() < 1e-12 * x.abs().max(1.0), "M[{r}][{s}]: {x} vs {y}");
            }
            let (x, y) = (value(a.0, a.1.forcing[r], &vals), value(b.0, b.1.forcing[r], &vals));
            assert!((x - y).abs() < 1e-12 * x.abs().max(1.0), "f[{r}]: {x} vs {y}");
        }
    }
}

#[test]
fn model_file_derives_the_rust_api_equations() {
    let loaded = lang::load("gimbal_gyroscope.al", GIMBAL).unwrap_or_else(|r| panic!("{}", r.render()));
    let eqs = loaded.equations.as_ref().unwrap();
    let names: Vec<String> =
        eqs.speeds.iter().map(|s| loaded.model.ar.symbol_info(*s).name.clone()).collect();
    assert_eq!(names, ["U1", "U2", "U3"]);
    let mut api = GimbalGyroscope::new().unwrap();
    let api_eqs = api.model.kane().unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    assert_same((&loaded.model.ar, eqs), (&api.model.ar, &api_eqs), &mut rng);
    // INPUT: angles converted from degrees (all zero here), TFINAL kept.
    assert_eq!(loaded.inputs.iter().find(|i| i.name == "TFINAL").map(|i| i.value), Some(5.0));
    assert_eq!(loaded.code.len(), 1);
    assert_eq!(loaded.units.get("Q1").map(String::as_str), Some("DEG"));
}

#[test]
fn editing_the_geometry_changes_the_equations() {
    let base = lang::load("gimbal.al", GIMBAL).unwrap();
    let base_eqs = base.equations.as_ref().unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(12);
    let vals = random_state(&mut rng);

    // 1. Move P: with P at L*D2> the rotor's partial velocities change, but M and f do not
    //    depend on P (no force at P), so the equations stay; the acceleration of P changes.
    let moved = GIMBAL.replace("P_O_P> = L*D1>", "P_O_P> = L*D2>");
    let m = lang::load("moved.al", &moved).unwrap();
    let me = m.equations.as_ref().unwrap();
    assert_same((&m.model.ar, me), (&base.model.ar, base_eqs), &mut rng);

    // 2. Turn the outer gimbal about +A2 instead of -A2: the sign of the Y torque's work flips.
    let flipped = GIMBAL.replace("SIMPROT(A, B, -2, Q1)", "SIMPROT(A, B, 2, Q1)");
    let f = lang::load("flipped.al", &flipped).unwrap();
    let fe = f.equations.as_ref().unwrap();
    let y = vals.iter().find(|(k, _)| k == "Y").unwrap().1;
    let at_rest: Vec<(String, f64)> =
        vals.iter().map(|(k, v)| (k.clone(), if k.starts_with('U') { 0.0 } else { *v })).collect();
    let f1_base = value(&base.model.ar, base_eqs.forcing[0], &at_rest);
    let f1_flip = value(&f.model.ar, fe.forcing[0], &at_rest);
    assert!((f1_base + y).abs() < 1e-12 && (f1_flip - y).abs() < 1e-12, "{f1_base} {f1_flip}");

    // 3. Offset the rotor's mass centre along D1 and add gravity: gravity now does work.
    let heavy = GIMBAL
        .replace("CONSTANTS M{3}, H{3}, L, W, Y, Z", "CONSTANTS M{3}, H{3}, L, W, Y, Z, G, DX")
        .replace("P_O_DO> = 0>", "P_O_DO> = DX*D1>")
        .replace("KANE()", "GRAVITY(-G*A3>)\nKANE()")
        .replace("ZERO = FR() + FRSTAR()", "");
    let h = lang::load("heavy.al", &heavy).unwrap_or_else(|r| panic!("{}", r.render()));
    let he = h.equations.as_ref().unwrap();
    let f_heavy = value(&h.model.ar, he.forcing[0], &at_rest);
    assert!((f_heavy - f1_base).abs() > 1e-6, "gravity with an offset rotor must change f1");
    // The offset moves the rotor's mass centre off its spin axis d2 (d1 is perpendicular to it),
    // so the spin entry M33 grows by exactly M3 DX^2.
    let m3 = vals.iter().find(|(k, _)| k == "M3").unwrap().1;
    let dx = vals.iter().find(|(k, _)| k == "DX").unwrap().1;
    let m33 = value(&h.model.ar, he.mass_matrix[2][2], &vals)
        - value(&base.model.ar, base_eqs.mass_matrix[2][2], &vals);
    assert!((m33 - m3 * dx * dx).abs() < 1e-12, "{m33} vs {}", m3 * dx * dx);
}

#[test]
fn solve_zero_for_the_accelerations_equals_m_inverse_f() {
    // SOLVE(ZERO, U1', U2', U3') after KANE(), as Autolev files write it.
    let src = format!("{GIMBAL}\nSOLVE(ZERO, U1', U2', U3')\nUD2 = RHS(U2')\n");
    let loaded = lang::load("gimbal_solve.al", &src).unwrap_or_else(|r| panic!("{}", r.render()));
    let Some(lang::Value::Scalar(ud2)) = loaded.value("UD2") else { panic!("UD2 missing") };
    let vals: Vec<(String, f64)> = [
        ("M1", 2.0),
        ("M2", 2.0),
        ("M3", 50.0),
        ("H1", 0.6),
        ("H2", 0.5),
        ("H3", 0.4),
        ("L", 0.3),
        ("W", 0.025),
        ("Y", 0.0),
        ("Z", 10.0),
        ("Q1", 0.0),
        ("Q2", 0.0),
        ("Q3", 0.0),
        ("U1", 0.0),
        ("U2", 0.0),
        ("U3", 10.0),
    ]
    .iter()
    .map(|(k, v)| (k.to_string(), *v))
    .collect();
    let got = value(&loaded.model.ar, ud2, &vals);
    assert!((got - (-5.532503457814661)).abs() < 1e-12, "{got}");
}
