//! The model language's mass and derivative functions (MASS, CM, MOMENTUM, KE, D, DT) give what the
//! mechanics layer computes, checked numerically at one point.

use kane_model::lang::{self, LoadedModel, Value};

const MODEL: &str = "NEWTONIAN N\nBODIES B\nPARTICLES P\nPOINTS O\nVARIABLES Q', U'\n\
CONSTANTS MB, MP, L\nSIMPROT(N, B, 3, Q)\nQ' = U\nV_O_N> = 0>\nP_O_BO> = L*B1>\nP_O_P> = 2*L*N2>\n\
MASS B = MB, P = MP\nTOTAL = MASS()\nJUSTB = MASS(B)\nC> = CM(O)\nLIN> = MOMENTUM(LINEAR)\n\
DQ> = D(P_O_BO>, Q, N)\nDTB> = DT(P_O_BO>, N)\nKALL = KE()\nKB = KE(B)\nKP = KE(P)\nKBP = KE(B, P)\n";

const AT: [(&str, f64); 5] = [("MB", 3.0), ("MP", 1.0), ("L", 0.5), ("Q", 0.3), ("U", 2.0)];

fn scalar(m: &LoadedModel, name: &str) -> f64 {
    let Some(Value::Scalar(x)) = m.value(name) else { panic!("{name} is not a scalar") };
    m.model.ar.eval_named(x, &AT).unwrap()
}

/// Measure numbers in N.
fn vector(m: &mut LoadedModel, name: &str) -> [f64; 3] {
    let Some(Value::Vector(v)) = m.value(name) else { panic!("{name} is not a vector") };
    let n = m.model.newtonian();
    let e = m.model.express(&v, n).unwrap();
    e.map(|x| m.model.ar.eval_named(x, &AT).unwrap())
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12)
}

#[test]
fn mass_centre_momentum_and_derivatives() {
    let mut m = lang::load("masses.al", MODEL).unwrap();
    assert_eq!(scalar(&m, "TOTAL"), 4.0);
    assert_eq!(scalar(&m, "JUSTB"), 3.0);
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    // CM: (3 * 0.5 (c, s, 0) + 1 * (0, 1, 0)) / 4.
    assert!(close(vector(&mut m, "C>"), [1.5 * c / 4.0, (1.5 * s + 1.0) / 4.0, 0.0]));
    // Only the body moves: p = MB L U B2.
    assert!(close(vector(&mut m, "LIN>"), [-3.0 * 0.5 * 2.0 * s, 3.0 * 0.5 * 2.0 * c, 0.0]));
    // d/dQ of L B1 in N is L B2; its time derivative is L U B2 (= W x r).
    assert!(close(vector(&mut m, "DQ>"), [-0.5 * s, 0.5 * c, 0.0]));
    assert!(close(vector(&mut m, "DTB>"), [-0.5 * 2.0 * s, 0.5 * 2.0 * c, 0.0]));
    // KE of the masses named: B's is MB (L U)^2 / 2 (no inertia given); P is at rest.
    assert!((scalar(&m, "KB") - 3.0 * (0.5f64 * 2.0).powi(2) / 2.0).abs() < 1e-12);
    assert_eq!(scalar(&m, "KP"), 0.0);
    assert_eq!(scalar(&m, "KBP"), scalar(&m, "KALL"));
}

#[test]
fn a_mass_not_given_is_named() {
    let src = "NEWTONIAN N\nBODIES B\nPARTICLES P\nPOINTS O\nMASS B = 1\nX = MASS()\n";
    let Err(err) = lang::load("missing.al", src) else { panic!("a missing mass is an error") };
    assert_eq!(err.diagnostics.len(), 1);
    assert_eq!(err.diagnostics[0].message, "P has no mass");
}
