//! Functions and commands research Autolev files use (issue 24): GRAVITY on the masses named,
//! direction-cosine entries `N_A[i,j]`, and INT, FLOOR, CEIL, ROUND and FACTORIAL of numbers.

use kane_model::expr::ExprId;
use kane_model::lang::{self, Value};

fn scalar(m: &lang::LoadedModel, name: &str) -> ExprId {
    match m.value(name) {
        Some(Value::Scalar(x)) => x,
        other => panic!("{name}: {other:?}"),
    }
}

fn number(m: &lang::LoadedModel, name: &str) -> f64 {
    m.model.ar.eval(&[scalar(m, name)], |_| None).unwrap()[0]
}

/// A pendulum carrying particles P at L and R at 2 L along A1>.
fn pendulum(gravity: &str) -> String {
    format!(
        "NEWTONIAN N\nFRAMES A\nPOINTS O\nPARTICLES P, R\nCONSTANTS L, G, MP, MR\nVARIABLES Q', U'\n\
         SIMPROT(N, A, 3, Q)\nQ' = U\nV_O_N> = 0>\nP_O_P> = L*A1>\nP_O_R> = 2*L*A1>\n\
         V2PTS(N, A, O, P)\nV2PTS(N, A, O, R)\nMASS P = MP, R = MR\n{gravity}\n\
         ZERO = FR() + FRSTAR()\nKANE()\n"
    )
}

#[test]
fn gravity_acts_on_the_masses_it_names_only() {
    let m = lang::load("g.al", &pendulum("GRAVITY(-G*N2>, P)")).unwrap();
    let e = m.equations.as_ref().unwrap();
    let values = |s: kane_model::expr::SymbolId| {
        let v = match m.model.ar.symbol_info(s).name.as_str() {
            "L" => 0.7,
            "G" => 9.81,
            "MP" => 2.0,
            "MR" => 3.0,
            "Q" => 0.4,
            _ => 0.0,
        };
        Some(v)
    };
    let v = m.model.ar.eval(&[e.mass_matrix[0][0], e.forcing[0]], values).unwrap();
    let (l, g, mp, mr, q) = (0.7f64, 9.81, 2.0, 3.0, 0.4f64);
    assert!((v[0] - (mp * l * l + mr * 4.0 * l * l)).abs() < 1e-12, "{}", v[0]);
    assert!((v[1] + mp * g * l * q.cos()).abs() < 1e-12, "only P's weight: {}", v[1]);
    let all = lang::load("g.al", &pendulum("GRAVITY(-G*N2>)")).unwrap();
    let f = all.model.ar.eval(&[all.equations.as_ref().unwrap().forcing[0]], values).unwrap()[0];
    assert!((f + (mp + 2.0 * mr) * g * l * q.cos()).abs() < 1e-12, "both weights: {f}");
    let e = lang::load("g.al", &pendulum("GRAVITY(-G*N2>, O)")).err().unwrap().to_string();
    assert!(e.contains("`O` is not a body or particle"), "{e}");
}

#[test]
fn direction_cosine_entries_and_whole_number_functions() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nSIMPROT(N, A, 3, Q)\nC12 = N_A[1,2]\nC21 = N_A[2,1]\n\
               I = INT(-2.7) + FLOOR(2.5) + CEIL(2.5) + ROUND(2.4)\nF = FACTORIAL(5)\n";
    let m = lang::load("d.al", src).unwrap();
    let ar = &m.model.ar;
    let q = |s: kane_model::expr::SymbolId| (ar.symbol_info(s).name == "Q").then_some(0.3f64);
    let c = ar.eval(&[scalar(&m, "C12"), scalar(&m, "C21")], q).unwrap();
    // N_A[i,j] = Ni> . Aj>: A turned by Q about N3>.
    assert!((c[0] + 0.3f64.sin()).abs() < 1e-15 && (c[1] - 0.3f64.sin()).abs() < 1e-15, "{c:?}");
    assert_eq!(number(&m, "I"), -2.0 + 2.0 + 3.0 + 2.0);
    assert_eq!(number(&m, "F"), 120.0);
    let e = lang::load("d.al", "VARIABLES Q'\nX = INT(Q)\n").err().unwrap().to_string();
    assert!(e.contains("INT() of an expression in the model's symbols is not supported"), "{e}");
    let e = lang::load("d.al", "X = FACTORIAL(2.5)\n").err().unwrap().to_string();
    assert!(e.contains("FACTORIAL of 2.5"), "{e}");
}
