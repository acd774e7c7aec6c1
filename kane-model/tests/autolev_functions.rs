//! Functions and commands research Autolev files use: GRAVITY on the masses named,
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
    // Of the model's symbols: shown as Autolev prints it, not a quantity a model can use.
    let m = lang::load("d.al", "VARIABLES Q'\nX = INT(Q)\n").unwrap();
    assert_eq!(m.value("X"), Some(Value::Shown("INT(Q)".into())));
    let e = lang::load("d.al", "X = FACTORIAL(2.5)\n").err().unwrap().to_string();
    assert!(e.contains("FACTORIAL of 2.5"), "{e}");
}

/// A matrix value's entries as numbers.
fn numbers(m: &lang::LoadedModel, name: &str) -> Vec<f64> {
    match m.value(name) {
        Some(Value::Matrix { data, .. }) => m.model.ar.eval(&data, |_| None).unwrap(),
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn taylor_inv_eig_and_jacobians_equal_their_hand_values() {
    let src = "VARIABLES X, Y\nCONSTANTS A, B\n\
               T1 = TAYLOR(COS(X), 0:2, X=0)\nT2 = TAYLOR(COS(X*Y), 0:4, X=0, Y=0)\n\
               T3 = TAYLOR(EXP(X), 1:3, X=1)\nIM = INV([1,2;3,4])\nIS = INV([A, B; B, A])\n\
               EV = EIG([2,1;1,2])\nJ = D([X^2*Y; SIN(X)], [X, Y])\n\
               V1 = EVALUATE(T1, X=0.3)\nV2 = EVALUATE(T2, X=0.5, Y=0.4)\nV3 = EVALUATE(T3, X=2)\n\
               VS = EVALUATE(IS, A=3, B=1)\nVJ = EVALUATE(J, X=0.5, Y=2)\n";
    let m = lang::load("alg.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    assert!((number(&m, "V1") - (1.0 - 0.09 / 2.0)).abs() < 1e-15);
    // cos(xy) to total order 4: 1 - (xy)^2 / 2.
    assert!((number(&m, "V2") - (1.0 - 0.04 / 2.0)).abs() < 1e-15);
    // Orders 1 to 3 of e^x about 1 at x = 2: e (1 + 1/2 + 1/6).
    let e = std::f64::consts::E;
    assert!((number(&m, "V3") - e * (1.0 + 0.5 + 1.0 / 6.0)).abs() < 1e-14);
    assert_eq!(numbers(&m, "IM"), [-2.0, 1.0, 1.5, -0.5]);
    assert_eq!(numbers(&m, "VS"), [3.0 / 8.0, -1.0 / 8.0, -1.0 / 8.0, 3.0 / 8.0]);
    let ev = numbers(&m, "EV");
    assert!((ev[0] - 1.0).abs() < 1e-14 && (ev[1] - 3.0).abs() < 1e-14, "{ev:?}");
    let j = numbers(&m, "VJ");
    let want = [2.0 * 0.5 * 2.0, 0.25, 0.5_f64.cos(), 0.0];
    assert!(j.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-15), "{j:?}");
}

#[test]
fn inv_of_a_singular_matrix_is_an_error_and_complex_eigenvalues_are_shown() {
    let e = lang::load("s.al", "M = INV([1,2;2,4])\n").err().unwrap().to_string();
    assert!(e.contains("INV of a singular matrix"), "{e}");
    let m = lang::load("c.al", "E = EIG([0,-1;1,0])\n").unwrap();
    assert_eq!(m.value("E"), Some(Value::Shown("[0 - 1i; 0 + 1i]".into())));
    let e = lang::load("y.al", "CONSTANTS A\nE = EIG([A,0;0,1])\n").err().unwrap().to_string();
    assert!(e.contains("matrix of numbers") && e.contains("kane linearize"), "{e}");
}

#[test]
fn an_index_range_inside_a_name_declares_each_name() {
    // RRF{2}O: the points RRF1O and RRF2O; with a space, `RRF{2} O` is a mistake.
    let m = lang::load(
        "r.al",
        "NEWTONIAN N\nPOINTS RRF{2}O\nCONSTANTS L\nP_RRF1O_RRF2O> = L*N1>\nX = DOT(P_RRF1O_RRF2O>, N1>)\n",
    )
    .unwrap_or_else(|r| panic!("{}", r.render()));
    assert_eq!(m.model.ar.to_text(scalar(&m, "X")), "L");
    let e = lang::load("s.al", "NEWTONIAN N\nPOINTS RRF{2} O\n").err().unwrap().to_string();
    assert!(e.contains("expected"), "{e}");
}

#[test]
fn frame_origins_dyadic_dots_and_derivatives_by_a_specified() {
    let src = "NEWTONIAN N\nFRAMES A, B\nPOINTS P, R\nVARIABLES Q{2}\nCONSTANTS L, K\n\
               SIMPROT(N, A, 3, Q1)\nSIMPROT(A, B, 1, Q2)\n\
               P_NO_P> = L*A1>\nP_P_R> = L*B2>\nX1 = DOT(P_NO_R>, N1>)\nP_AO_R> = K*A3>\n\
               X2 = DOT(P_AO_R>, A3>)\nV_R_N> = DT(P_NO_R>, N)\n\
               D1>> = 2*A1>*A1> + B2>*B3>\nX3 = DOT(DOT(D1>>, B3>), B2>)\nX4 = DOT(DOT(B2>, D1>>), B3>)\n\
               SPECIFIED S\nS = SIN(Q1)*L\nE = D(S^2, S)\n";
    let m = lang::load("o.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    let text = |n: &str| m.model.ar.to_text(scalar(&m, n));
    // P_NO_R> goes through P: L A1> + L B2>, along N1> L cos Q1 - L sin Q1 cos Q2.
    assert_eq!(text("X1"), "L*cos(Q1) - L*sin(Q1)*cos(Q2)");
    assert_eq!(text("X2"), "K");
    // D1>> . B3> = B2> (A1> . B3> = 0); from the left, B2> . D1>> = B3> (A1> . B2> = 0).
    assert_eq!(text("X3"), "1");
    assert_eq!(text("X4"), "1");
    // d(S^2)/dS = 2 S: a SPECIFIED quantity stays itself, its formula kept for the equations.
    assert_eq!(text("E"), "2*S");
}

#[test]
fn a_specified_torque_given_a_formula_after_kane_drives_the_equations_and_the_code() {
    // A rod hinged at O (mass centre at L) under a SPECIFIED torque T, whose formula (a spring
    // and a damper) comes after KANE(), as Autolev writes the formulas its CODE evaluates.
    let src = "NEWTONIAN N\nBODIES A\nPOINTS O\nCONSTANTS L, M, G, K, C\nSPECIFIED T\nVARIABLES Q', U'\n\
               SIMPROT(N, A, 3, Q)\nQ' = U\nP_O_AO> = L*A1>\nV_O_N> = 0>\nV_AO_N> = DT(P_O_AO>, N)\n\
               MASS A = M\nINERTIA A, 0, M*L^2/12, M*L^2/12\nGRAVITY(-G*N2>)\nTORQUE_A> = T*N3>\n\
               ZERO = FR() + FRSTAR()\nKANE()\nPOWER = T*U\nT = -K*Q - C*U\nOUTPUT POWER\n\
               INPUT L = 1, M = 3, G = 9.81, K = 2, C = 0.5, Q = 0.1, U = 0.4\n";
    let m = lang::load("t.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    let inputs: Vec<(String, f64)> = m.inputs.iter().map(|i| (i.name.clone(), i.value)).collect();
    let rates = {
        let by = |s: kane_model::expr::SymbolId| {
            let n = m.model.ar.symbol_info(s).name.clone();
            inputs.iter().find(|i| i.0 == n).map(|i| i.1)
        };
        m.equations.as_ref().unwrap().rates_at(&m.model.ar, &by).unwrap()
    };
    // (M L^2 / 12 + M L^2) U' = -M G L cos Q - K Q - C U.
    let want = (-3.0 * 9.81 * 0.1_f64.cos() - 2.0 * 0.1 - 0.5 * 0.4) / (3.0 / 12.0 + 3.0);
    assert!((rates.speeds[0] - want).abs() < 1e-13, "{} vs {want}", rates.speeds[0]);
    // The generated code reads K and C, not T; POWER (assigned before T's formula) has it.
    let mut spec = m.into_spec("t").unwrap();
    let lowered = kane_model::program::lower(&mut spec).unwrap();
    let params: Vec<&str> = lowered.params.iter().map(|s| spec.symbol_name(*s)).collect();
    assert!(params.contains(&"K") && params.contains(&"C") && !params.contains(&"T"), "{params:?}");
    let power = spec.outputs.iter().find(|o| o.name == "POWER").unwrap().components[0];
    let ar = &spec.model.ar;
    let named =
        |s: kane_model::expr::SymbolId| inputs.iter().find(|i| i.0 == ar.symbol_info(s).name).map(|i| i.1);
    let value = ar.eval(&[power], named).unwrap()[0];
    assert!((value - (-2.0 * 0.1 - 0.5 * 0.4) * 0.4).abs() < 1e-15, "{value}");
}

#[test]
fn cross_with_a_dyadic_and_an_orientation_tree_not_rooted_at_n() {
    // B is oriented in A before A is oriented in N: the tree is re-rooted at N.
    let src = "NEWTONIAN N\nFRAMES A, B\nVARIABLES Q{2}'\nSIMPROT(A, B, 3, Q2)\nSIMPROT(N, A, 3, Q1)\n\
               W = DOT(W_B_N>, N3>)\nX = DOT(B1>, N1>)\n\
               L>> = CROSS(A3>, A1>*A1>)\nR>> = CROSS(A1>*A1>, A3>)\n\
               XL = DOT(DOT(L>>, A1>), A2>)\nXR = DOT(A1>, DOT(R>>, A2>))\n";
    let m = lang::load("c.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    let text = |n: &str| m.model.ar.to_text(scalar(&m, n));
    assert_eq!(text("W"), "Q2' + Q1'");
    assert_eq!(text("X"), "cos(Q1 + Q2)");
    // A3> x (A1> A1>) = A2> A1>; (A1> A1>) x A3> = -A1> A2>.
    assert_eq!(text("XL"), "1");
    assert_eq!(text("XR"), "-1");
}

#[test]
fn spline_through_a_cubic_is_the_cubic_with_its_derivatives() {
    // f(x) = x^3 - 2 x^2 + 0.5 x - 1 sampled at unevenly spaced points.
    let f = |x: f64| [x * x * x - 2.0 * x * x + 0.5 * x - 1.0, 3.0 * x * x - 4.0 * x + 0.5, 6.0 * x - 4.0];
    let knots = [0.0, 0.3, 0.35, 1.0, 1.7, 2.0];
    let values: Vec<String> = knots.iter().map(|x| format!("{:?}", f(*x)[0])).collect();
    let list: Vec<String> = knots.iter().map(|x| format!("{x:?}")).collect();
    for x in [0.0, 0.31, 1.0, 1.23, 2.0] {
        let src = format!(
            "VARIABLES X\nY = SPLINE(X, [{}], [{}])\nDY = D(Y, X)\nDDY = D(DY, X)\n\
             V = EVALUATE(Y, X = {x})\nDV = EVALUATE(DY, X = {x})\nDDV = EVALUATE(DDY, X = {x})\n",
            list.join(", "),
            values.join(", ")
        );
        let m = lang::load("s.al", &src).unwrap();
        for (name, want) in ["V", "DV", "DDV"].iter().zip(f(x)) {
            let got = number(&m, name);
            assert!((got - want).abs() < 1e-12, "{name} at {x}: {got} vs {want}");
        }
    }
    let e =
        lang::load("s.al", "VARIABLES X\nY = SPLINE(X, [0, 1, 1], [0, 1, 2])\n").err().unwrap().to_string();
    assert!(e.contains("SPLINE's points must increase: point 3 (1) follows 1"), "{e}");
}

#[test]
fn coef_of_a_power_and_of_a_name_in_a_polynomial() {
    let src =
        "VARIABLES X, Y\nCONSTANTS A, B\nE = A*X^2 + B*X + X*Y + 3\nC1 = COEF(E, X)\nC2 = COEF(E, X^2)\n\
               L = COEF(B*X + A*Y, [X, Y])\n";
    let m = lang::load("c.al", src).unwrap_or_else(|r| panic!("{}", r.render()));
    let text = |name: &str| m.model.ar.to_text(scalar(&m, name));
    assert_eq!(text("C1"), "Y + B");
    assert_eq!(text("C2"), "A");
    let Some(Value::Matrix { data, .. }) = m.value("L") else { panic!("a row of coefficients") };
    assert_eq!(data.iter().map(|x| m.model.ar.to_text(*x)).collect::<Vec<_>>(), ["B", "A"]);
    let e = lang::load("c.al", "VARIABLES X\nE = SIN(X) + X\nC = COEF(E, X)\n").err().unwrap().to_string();
    assert!(e.contains("not a polynomial in `X`"), "{e}");
}
