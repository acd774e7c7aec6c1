//! Idioms of research Autolev files, each in a small file of our own: they run as written, with
//! Autolev's meaning (assigned kinematics, the language's commands and functions).

use kane_model::expr::ExprId;
use kane_model::lang::{self, LoadedModel, Severity, Value};

/// Checks `src`, failing the test on an error; the checked model and its warnings' text.
fn checks(src: &str) -> (LoadedModel, String) {
    match lang::check("idiom.al", src) {
        Ok(c) => (c.model, c.warnings.to_string()),
        Err(r) => panic!("{r}"),
    }
}

/// The report of a file that must not check.
fn fails(src: &str) -> String {
    match lang::check("idiom.al", src) {
        Ok(_) => panic!("checked:\n{src}"),
        Err(r) => r.to_string(),
    }
}

/// Values for symbols by name (`Q1` = 0.3, ...); others 0.
fn at<'a>(
    m: &'a LoadedModel,
    values: &'a [(&str, f64)],
) -> impl Fn(kane_model::expr::SymbolId) -> Option<f64> + 'a {
    move |s| {
        let name = &m.model.ar.symbol_info(s).name;
        Some(values.iter().find(|(n, _)| n.eq_ignore_ascii_case(name)).map_or(0.0, |(_, v)| *v))
    }
}

fn scalar(m: &LoadedModel, name: &str) -> ExprId {
    match m.value(name) {
        Some(Value::Scalar(x)) => x,
        other => panic!("{name}: {other:?}"),
    }
}

/// The value of the scalar `name` at `values`.
fn number(m: &LoadedModel, name: &str, values: &[(&str, f64)]) -> f64 {
    m.model.ar.eval(&[scalar(m, name)], at(m, values)).unwrap()[0]
}

/// The measure numbers of the vector `name` in `frame` at `values`.
fn measures(m: &mut LoadedModel, name: &str, frame: &str, values: &[(&str, f64)]) -> [f64; 3] {
    let Some(Value::Vector(v)) = m.value(name) else { panic!("{name} is not a vector") };
    in_frame(m, &v, frame, values)
}

/// The velocity of `point` in N at `values`, in N.
fn velocity(m: &mut LoadedModel, point: &str, values: &[(&str, f64)]) -> [f64; 3] {
    let (p, n) = (m.model.point(point).unwrap(), m.model.frame("N").unwrap());
    let v = m.model.velocity(p, n).unwrap();
    in_frame(m, &v, "N", values)
}

fn in_frame(
    m: &mut LoadedModel,
    v: &kane_model::mechanics::Vector,
    frame: &str,
    values: &[(&str, f64)],
) -> [f64; 3] {
    let f = m.model.frame(frame).unwrap();
    let e = m.model.express(v, f).unwrap();
    let x = m.model.ar.eval(&e, at(m, values)).unwrap();
    [x[0], x[1], x[2]]
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12)
}

/// A disc of radius R rolling on N's X axis: its contact point is located with N's unit vector.
const ROLLING_DISC: &str = "NEWTONIAN N
BODIES D
POINTS DN
CONSTANTS R, M, G
VARIABLES Q1', Q2', U1', U2'
SIMPROT(N, D, 3, Q2)
Q1' = U1
Q2' = U2
P_NO_DO> = Q1*N1> + R*N2>
V_DO_N> = U1*N1>
W_D_N> = U2*N3>
P_DO_DN> = -R*N2>
V2PTS(N, D, DO, DN)
MASS D = M
INERTIA D, 1, 1, 1
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
";

#[test]
fn a_contact_points_velocity_is_that_of_the_bodys_point_there() {
    let (mut m, warnings) = checks(ROLLING_DISC);
    assert!(warnings.is_empty(), "{warnings}");
    // The material point of D at the contact, not the contact's rate (U1 N1>).
    let v = velocity(&mut m, "DN", &[("U1", 0.5), ("U2", 2.0), ("R", 0.3)]);
    assert!(close(v, [0.5 + 0.3 * 2.0, 0.0, 0.0]), "{v:?}");
}

#[test]
fn a_velocity_assigned_as_the_rate_of_a_position_checks() {
    let src = ROLLING_DISC.replace("V_DO_N> = U1*N1>", "V_DO_N> = DT(P_NO_DO>, N)");
    let (mut m, _) = checks(&src);
    let v = velocity(&mut m, "DO", &[("U1", 0.5)]);
    assert!(close(v, [0.5, 0.0, 0.0]), "{v:?}");
}

#[test]
fn a_velocity_that_contradicts_the_positions_is_an_error_naming_both_lines() {
    let src = ROLLING_DISC.replace("V_DO_N> = U1*N1>", "V_DO_N> = U2*N1>");
    let text = fails(&src);
    assert!(text.contains("idiom.al:10:1: error: `V_DO_N> = U2*N1>` contradicts"), "{text}");
    assert!(text.contains("idiom.al:9:1: note:"), "{text}");
}

/// A body B turning about N3 carrying a rotor RW whose orientation is not tracked.
fn rotor(inertia: &str) -> String {
    format!(
        "NEWTONIAN N\nBODIES B, RW\nVARIABLES Q1', U1', U2'\nCONSTANTS J, K\n\
         SIMPROT(N, B, 3, Q1)\nSIMPROT(B, RW, 1, 0)\nQ1' = U1\nW_B_N> = U1*B3>\nW_RW_B> = U2*B1>\nV_BO_N> = 0>\nV_RWO_N> = 0>\n\
         MASS B = 1, RW = 1\nINERTIA B, 1, 2, 3\nINERTIA RW, {inertia}\n\
         ZERO = FR() + FRSTAR()\nKANE()\n"
    )
}

#[test]
fn an_untracked_rotor_symmetric_about_its_axis_checks() {
    let (m, warnings) = checks(&rotor("J, K, K"));
    assert!(warnings.is_empty(), "{warnings}");
    assert_eq!(m.equations.unwrap().speeds.len(), 2);
}

#[test]
fn an_untracked_rotor_that_is_not_symmetric_is_an_error() {
    let text = fails(&rotor("J, K, 2*K"));
    assert!(text.contains("`W_RW_B> = U2*B1>`"), "{text}");
    assert!(text.contains("idiom.al:6:1"), "names the SIMPROT line: {text}");
}

#[test]
fn the_gimbal_with_its_rotor_off_the_gimbal_centre_stays_an_error() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/gimbal_gyroscope.al");
    let src = std::fs::read_to_string(path).unwrap();
    assert!(src.contains("P_O_DO> = 0>   "));
    let text = fails(&src.replace("P_O_DO> = 0>   ", "P_O_DO> = 0.05*C2>"));
    assert!(text.contains("`A_DO_A> = 0>` contradicts the acceleration of DO in A"), "{text}");
}

#[test]
fn vector_of_measure_numbers_in_a_frame() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nSIMPROT(N, A, 3, Q)\nX> = VECTOR(A, 1, 2, 3)\n";
    let (mut m, _) = checks(src);
    let v = measures(&mut m, "X>", "A", &[("Q", 0.4)]);
    assert!(close(v, [1.0, 2.0, 3.0]), "{v:?}");
}

#[test]
fn exit_ends_the_file() {
    let (m, _) = checks("CONSTANTS A\nX = 2*A\nEXIT\nX = UNDEFINED_NAME\n");
    assert_eq!(number(&m, "X", &[("A", 1.5)]), 3.0);
}

#[test]
fn units_with_dotted_products_and_lists() {
    let (m, _) = checks("CONSTANTS I, A, B\nUNITS I = KG.M^2, [A, B] = M\n");
    assert_eq!(m.units.get("I").map(String::as_str), Some("KG*M^2"));
    assert_eq!(m.units.get("A").map(String::as_str), Some("M"));
    assert_eq!(m.units.get("B").map(String::as_str), Some("M"));
}

#[test]
fn a_matrix_may_be_named_like_a_frame() {
    let (m, _) = checks("NEWTONIAN N\nFRAMES A, B\nA = [1, 2; 3, 4]\nX = A[2, 1]\n");
    assert_eq!(number(&m, "X", &[]), 3.0);
}

#[test]
fn orientations_may_be_written_from_the_leaves() {
    let src = "NEWTONIAN N\nFRAMES C, F\nVARIABLES Q1', Q2'\nSIMPROT(N, F, 1, Q1)\nSIMPROT(C, F, 2, Q2)\n\
               X = DOT(C3>, N3>)\n";
    let (m, _) = checks(src);
    // c3 = f-frame rotation back by Q2 about F2, then by Q1 about N1: c3 . n3 = cos Q1 cos Q2.
    let x = number(&m, "X", &[("Q1", 0.3), ("Q2", 0.5)]);
    assert!((x - 0.3f64.cos() * 0.5f64.cos()).abs() < 1e-12, "{x}");
}

#[test]
fn a_later_simprot_replaces_the_earlier() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nSIMPROT(N, A, 1, Q)\nSIMPROT(N, A, 3, Q)\n\
               X = DOT(A1>, N2>)\n";
    let (m, _) = checks(src);
    assert!((number(&m, "X", &[("Q", 0.4)]) - 0.4f64.sin()).abs() < 1e-12);
}

#[test]
fn rodrigues_parameters_orient_a_frame() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES G1, G2, G3\nDIRCOS(N, A, RODRIGUES, G1, G2, G3)\n\
               X = DOT(A1>, N2>)\nY = DOT(A1>, N1>)\n";
    let (m, _) = checks(src);
    // About N3 by 0.6 rad: g3 = tan(0.3).
    let g = [("G3", 0.3f64.tan())];
    assert!((number(&m, "X", &g) - 0.6f64.sin()).abs() < 1e-12);
    assert!((number(&m, "Y", &g) - 0.6f64.cos()).abs() < 1e-12);
}

#[test]
fn a_specifieds_derivative_and_an_aliases_derivative_may_be_assigned() {
    let src = "NEWTONIAN N\nBODIES B\nSPECIFIED DA''\nVARIABLES Q4', U4'\nSIMPROT(N, B, 3, Q4)\n\
               V_BO_N> = 0>\nMASS B = 1\nINERTIA B, 1, 1, 1\nDA' = T^3\nQ4' = U4\nLH = Q4\nLH' = U4\n\
               X = DT(DA)\nY = DT(DT(DA))\nZ = DT(LH)\nZERO = FR() + FRSTAR()\nKANE()\nOUTPUT X, Y, Z\n";
    let (m, _) = checks(src);
    let spec = m.into_spec("idiom").unwrap();
    let out = |name: &str, values: &[(&str, f64)]| {
        let o = spec.outputs.iter().find(|o| o.name == name).unwrap();
        let by_name = |s| {
            let n = &spec.model.ar.symbol_info(s).name;
            Some(values.iter().find(|(k, _)| k.eq_ignore_ascii_case(n)).map_or(0.0, |(_, v)| *v))
        };
        spec.model.ar.eval(&o.components, by_name).unwrap()[0]
    };
    assert!((out("X", &[("T", 2.0)]) - 8.0).abs() < 1e-12);
    assert!((out("Y", &[("T", 2.0)]) - 12.0).abs() < 1e-12, "{}", out("Y", &[("T", 2.0)]));
    assert!((out("Z", &[("U4", 0.7)]) - 0.7).abs() < 1e-12);
}

#[test]
fn a_partial_derivative_by_a_specified_given_earlier() {
    let src = "SPECIFIED S\nVARIABLES Q'\nS = Q^2\nX = D(S*Q, S)\n";
    let (m, _) = checks(src);
    assert!((number(&m, "X", &[("Q", 0.5)]) - 0.5).abs() < 1e-12);
}

#[test]
fn solve_of_a_literal_list_for_coordinate_rates() {
    let src = "VARIABLES X', Y', Q', U'\nCONSTANTS R\nQ' = U\n\
               SOLVE([X' - R*U*COS(Q), Y' - R*U*SIN(Q)], [X', Y'])\nV = X'\n";
    let (m, _) = checks(src);
    let x = number(&m, "V", &[("R", 2.0), ("U", 0.5), ("Q", 0.0)]);
    assert!((x - 1.0).abs() < 1e-12, "{x}");
}

#[test]
fn the_rates_solve_gives_are_kinematic_equations_not_speeds() {
    let src = format!("{}VARIABLES X'\nSOLVE([X' - Q1'], [X'])\n", ROLLING_DISC.replace("KANE()\n", ""))
        + "KANE()\n";
    let (m, _) = checks(&src);
    let e = m.equations.unwrap();
    assert_eq!(e.speeds.len(), 2, "U1 and U2 only");
}

#[test]
fn names_used_only_in_mass_and_inertia_are_declared_by_use() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q', U'\nSIMPROT(N, B, 3, Q)\nQ' = U\nW_B_N> = U*N3>\nV_BO_N> = 0>\n\
               MASS B = MB\nINERTIA B, I1, I2, I3\nZERO = FR() + FRSTAR()\nKANE()\n";
    let (m, warnings) = checks(src);
    assert!(warnings.contains("MB"), "{warnings}");
    assert!(warnings.contains("I3"), "{warnings}");
    assert!(m.equations.is_some());
}

#[test]
fn zee_leaves_values_unchanged() {
    let (m, _) = checks("CONSTANTS A\nX = ZEE(A^2 + 1)\n");
    assert_eq!(number(&m, "X", &[("A", 2.0)]), 5.0);
}

#[test]
fn evaluate_with_a_rate_set_to_zero() {
    let (m, _) = checks("VARIABLES Q1'\nX = Q1' + Q1\nY = EVALUATE(X, Q1'=0)\n");
    assert_eq!(number(&m, "Y", &[("Q1", 0.25), ("Q1'", 3.0)]), 0.25);
}

#[test]
fn animate_is_accepted() {
    let src = "NEWTONIAN N\nBODIES B\nPOINTS O\nVARIABLES Q'\nSIMPROT(N, B, 3, Q)\nANIMATE(N, O, B)\n";
    checks(src);
}

#[test]
fn angular_velocity_in_coordinate_rates_without_speeds() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nSIMPROT(N, A, 3, Q)\nX = DOT(W_A_N>, A3>)\n";
    let (m, _) = checks(src);
    assert_eq!(number(&m, "X", &[("Q'", 1.25)]), 1.25);
}

#[test]
fn kindiffs_after_an_angle_is_fixed() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q{4}', U{3}'\nDIRCOS(N, B, BODY123, Q1, Q2, Q3)\n\
               W_B_N> = U1*B1> + U2*B2> + U3*B3>\nQ4 = 0\nKINDIFFS(N, B, BODY123, Q1, Q2, Q3)\n\
               X = Q3'\n";
    let (m, _) = checks(src);
    // About B3 only with Q1 = Q2 = 0: Q3' = U3.
    assert!((number(&m, "X", &[("U3", 0.8)]) - 0.8).abs() < 1e-12);
}

#[test]
fn partial_derivatives_of_a_matrix_by_a_named_list() {
    let src = "VARIABLES Q{2}\nQ = [Q1; Q2]\nF = [Q1^2; Q1*Q2]\nJ = D(F, Q)\nX = J[2, 1]\n";
    let (m, _) = checks(src);
    assert_eq!(number(&m, "X", &[("Q1", 3.0), ("Q2", 5.0)]), 5.0);
}

#[test]
fn coef_of_a_vector() {
    let src = "NEWTONIAN N\nVARIABLES U1, U2\nV> = (U1 + 3*U2)*N1> + 2*U2*N2>\nC> = COEF(V>, U2)\n";
    let (mut m, _) = checks(src);
    assert!(close(measures(&mut m, "C>", "N", &[]), [3.0, 2.0, 0.0]));
}

#[test]
fn exclude_and_include_terms() {
    let (m, _) = checks("VARIABLES U1, U2\nCONSTANTS G\nZ = 2*U1 + 3*U2 + G\nX = EXCLUDE(Z, [U1, U2])\n");
    assert_eq!(number(&m, "X", &[("G", 7.0), ("U1", 1.0), ("U2", 1.0)]), 7.0);
    let (m, _) = checks("VARIABLES U1, U2\nCONSTANTS G\nZ = 2*U1 + 3*U2 + G\nX = INCLUDE(Z, U1)\n");
    assert_eq!(number(&m, "X", &[("G", 7.0), ("U1", 1.0), ("U2", 1.0)]), 2.0);
}

#[test]
fn complex_roots_and_factorial_of_a_symbol_are_shown() {
    let (m, _) = checks("CONSTANTS A\nR = ROOTS([1, 0, 1])\nF = FACTORIAL(A)\n");
    assert!(matches!(m.value("R"), Some(Value::Shown(_))), "{:?}", m.value("R"));
    assert!(matches!(m.value("F"), Some(Value::Shown(_))), "{:?}", m.value("F"));
}

#[test]
fn a_specifieds_formula_may_come_after_kane() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q', U'\nSPECIFIED TQ\nSIMPROT(N, B, 3, Q)\nQ' = U\n\
               W_B_N> = U*N3>\nV_BO_N> = 0>\nMASS B = 1\nINERTIA B, 1, 1, 2\nTORQUE(B, TQ*N3>)\n\
               ZERO = FR() + FRSTAR()\nKANE()\nTQ = 4\n";
    let (m, _) = checks(src);
    let spec = m.into_spec("idiom").unwrap();
    assert!(spec.inputs.is_empty(), "TQ has a formula");
}

#[test]
fn an_open_specified_is_an_input_of_the_spec() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q', U'\nSPECIFIED TQ\nSIMPROT(N, B, 3, Q)\nQ' = U\n\
               W_B_N> = U*N3>\nV_BO_N> = 0>\nMASS B = 1\nINERTIA B, 1, 1, 2\nTORQUE(B, TQ*N3>)\n\
               ZERO = FR() + FRSTAR()\nKANE()\n";
    let (m, _) = checks(src);
    let spec = m.into_spec("idiom").unwrap();
    let names: Vec<&str> = spec.inputs.iter().map(|s| spec.symbol_name(*s)).collect();
    assert_eq!(names, ["TQ"]);
}

#[test]
fn code_dynamics_forms_kanes_equations_from_zero() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q', U'\nSIMPROT(N, B, 3, Q)\nQ' = U\nW_B_N> = U*N3>\nV_BO_N> = 0>\n\
               MASS B = 1\nINERTIA B, 1, 1, 2\nZERO = FR() + FRSTAR()\nCODE DYNAMICS() idiom.c\n";
    let (m, _) = checks(src);
    assert!(m.equations.is_some() || m.into_spec("idiom").is_ok());
}

#[test]
fn a_file_without_dynamics_computes_its_encoded_quantities_from_inputs() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nCONSTANTS L\nSIMPROT(N, A, 3, Q)\n\
               P_NO_P> = L*A1>\nX = [DOT(P_NO_P>, N1>); DOT(P_NO_P>, N2>)]\nXD = DT(X)\n\
               ENCODE X, XD\nCODE ALGEBRAIC() fk.c\n";
    let (m, _) = checks(src);
    let spec = m.into_spec("fk").unwrap();
    assert!(spec.states().is_empty());
    let mut inputs: Vec<&str> = spec.inputs.iter().map(|s| spec.symbol_name(*s)).collect();
    inputs.sort();
    assert_eq!(inputs, ["Q", "Q'"]);
    let names: Vec<&str> = spec.outputs.iter().map(|o| o.name.as_str()).collect();
    assert!(names.contains(&"X_1") && names.contains(&"XD_2"), "{names:?}");
}

#[test]
fn every_independent_problem_is_reported_in_one_run() {
    let src = "CONSTANTS A\nX = UNKNOWN1 + A\nY = 2*A\nZ = UNKNOWN2\n";
    let text = fails(src);
    assert!(text.contains("UNKNOWN1") && text.contains("UNKNOWN2"), "{text}");
    let Err(r) = lang::check("idiom.al", src) else { unreachable!() };
    assert_eq!(r.diagnostics.iter().filter(|d| d.severity == Severity::Error).count(), 2, "{text}");
}

#[test]
fn messages_suggest_nothing_unrelated() {
    let text = fails("X = VECTOR(1, 2)\n");
    assert!(!text.contains("EIG"), "{text}");
    let text = fails("X = ZEEE(2)\n");
    assert!(!text.contains("BEEP"), "{text}");
}

/// The kinematic equations KINDIFFS gives for `orient`ation statements of C in N.
fn kindiffs(orient: &str) -> Vec<f64> {
    let src = format!(
        "NEWTONIAN N\nFRAMES A, B, C\nVARIABLES Q{{3}}', U{{3}}'\n{orient}\
         W_C_N> = U1*C1> + U2*C2> + U3*C3>\nKINDIFFS(N, C, BODY312, Q1, Q2, Q3)\n"
    );
    let (m, _) = checks(&src);
    let values = [("Q1", 0.3), ("Q2", -0.4), ("Q3", 0.7), ("U1", 0.2), ("U2", -1.1), ("U3", 0.5)];
    ["Q1", "Q2", "Q3"]
        .iter()
        .map(|q| {
            let s = m.model.ar.lookup(q).unwrap();
            let rhs = m.model.kinematics(s).unwrap();
            m.model.ar.eval(&[rhs], at(&m, &values)).unwrap()[0]
        })
        .collect()
}

#[test]
fn kindiffs_reads_the_sequence_it_names_through_a_chain_of_simprots() {
    let chain = kindiffs("SIMPROT(N, A, 3, Q1)\nSIMPROT(A, B, 1, Q2)\nSIMPROT(B, C, 2, Q3)\n");
    let direct = kindiffs("DIRCOS(N, C, BODY312, Q1, Q2, Q3)\n");
    assert!(chain.iter().zip(&direct).all(|(a, b)| (a - b).abs() < 1e-12), "{chain:?} {direct:?}");
    // Q2' = cos(Q3) U1 + sin(Q3) U3 for a 3-1-2 sequence.
    assert!((chain[1] - (0.7f64.cos() * 0.2 + 0.7f64.sin() * 0.5)).abs() < 1e-12, "{chain:?}");
}

#[test]
fn a_claim_is_checked_against_the_angular_velocities_of_its_time() {
    // Line 12 restates W_B_N> (a slip for W_C_N>): an error there, and not at the V2PTS before.
    let src = "NEWTONIAN N\nBODIES B, C\nPOINT O\nMOTIONVARIABLES' Q{2}''\nCONSTANTS L\n\
               SIMPROT(N, B, 3, Q1)\nW_B_N> = Q1'*N3>\nP_O_BO> = L*B1>\nV_O_N> = 0>\nV2PTS(N, B, O, BO)\n\
               SIMPROT(B, C, 3, Q2)\nW_B_N> = (Q1' + Q2')*N3>\n";
    let Err(r) = lang::check("idiom.al", src) else { panic!("checked") };
    let errors: Vec<String> =
        r.diagnostics.iter().filter(|d| d.severity == Severity::Error).map(|d| d.message.clone()).collect();
    assert_eq!(errors.len(), 1, "{r}");
    assert!(errors[0].contains("W_B_N> = (Q1' + Q2')*N3>"), "{r}");
}

/// A fresh folder for one test.
fn folder(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("autolev_idioms").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_run_files_statements_come_where_the_run_is() {
    // The wheel and its angular velocity come from the file RUN reads; the contact follows.
    let dir = folder("run_order");
    let body = "NEWTONIAN N\nBODIES D\nCONSTANTS R\nVARIABLES Q1', Q2', U1', U2'\nSIMPROT(N, D, 3, Q2)\n\
                Q1' = U1\nQ2' = U2\nW_D_N> = U2*N3>\nP_NO_DO> = Q1*N1> + R*N2>\nV_DO_N> = U1*N1>\n";
    std::fs::write(dir.join("wheel.al"), body).unwrap();
    let main = dir.join("main.al");
    let src = "RUN wheel.al\nPOINTS DN\nP_DO_DN> = -R*N2>\nV2PTS(N, D, DO, DN)\n";
    std::fs::write(&main, src).unwrap();
    if let Err(r) = lang::check(main.to_str().unwrap(), src) {
        panic!("{r}");
    }
}

#[test]
fn code_dynamics_of_a_file_that_assigns_every_rate_integrates_them() {
    // A pendulum's equation written by hand: no speeds, no KANE(); Q and W are the states.
    let src =
        "CONSTANTS G\nVARIABLES Q', W'\nQ' = W\nSOLVE(W' + G*SIN(Q), W')\nINPUT G = 9.8, Q = 0.1, W = 0\n\
               OUTPUT Q, W, Q'\nCODE DYNAMICS() pendulum.c\n";
    let (m, _) = checks(src);
    let mut spec = m.into_spec("pendulum").unwrap();
    let states: Vec<String> = spec.states().iter().map(|s| spec.symbol_name(*s).to_string()).collect();
    assert_eq!(states.len(), 2, "{states:?}");
    assert!(states.iter().any(|s| s == "Q") && states.iter().any(|s| s == "W"), "{states:?}");
    let w = spec.model.ar.lookup("W").unwrap();
    let w = spec.model.ar.symbol_expr(w);
    let rate = spec.outputs.iter().find(|o| o.name == "Q'").expect("Q' is an output");
    assert_eq!(rate.components, [w]);
}

#[test]
fn solve_of_zero_after_kane_with_loads_assigns_kanes_rates() {
    // A particle sliding on a table, its normal force brought into evidence by an auxiliary
    // speed: KANE(FN) solves FN; SOLVE(ZERO, U') then assigns U' (ZERO's auxiliary row dropped).
    let src = "NEWTONIAN N\nPARTICLES P\nVARIABLES Q', U', UA'\nCONSTANTS M, G, K\nSPECIFIED FN\nQ' = U\n\
               P_NO_P> = Q*N1>\nV_P_N> = U*N1> + UA*N2>\nA_P_N> = U'*N1> + UA'*N2>\nCONSTRAIN(AUXILIARY[UA])\n\
               MASS P = M\nFORCE_P> = -K*Q*N1> - M*G*N2> + FN*N2>\nZERO = FR() + FRSTAR()\nKANE(FN)\n\
               SOLVE(ZERO, U')\n";
    let (m, _) = checks(src);
    assert!(m.equations.as_ref().is_some_and(|e| e.loads.is_some()));
}

#[test]
fn coef_by_a_rate_solve_gave_takes_the_rate_itself() {
    let src =
        "VARIABLES W'\nCONSTANTS A, B\nZ = A*W' + B\nSOLVE(Z, W')\nC = COEF(Z, W')\nE = EXCLUDE(Z, [W'])\n";
    let (m, _) = checks(src);
    assert_eq!(number(&m, "C", &[("A", 3.0), ("B", 2.0)]), 3.0);
    assert_eq!(number(&m, "E", &[("A", 3.0), ("B", 2.0)]), 2.0);
}

#[test]
fn coef_by_a_coordinates_rate_reads_its_kinematic_equation() {
    let (m, _) = checks("VARIABLES Q', U'\nCONSTANTS A, B\nQ' = U\nE = A*Q' + B\nC = COEF(E, Q')\n");
    assert_eq!(number(&m, "C", &[("A", 3.0)]), 3.0);
}

#[test]
fn exclude_of_an_expression_too_large_to_expand_that_is_polynomial_in_the_names() {
    // (A1 + ... + A10) ... (F1 + ... + F10) expands into a million terms.
    let mut src = String::from("VARIABLES W'\nCONSTANTS G\n");
    let mut factors = Vec::new();
    for c in ['A', 'B', 'C', 'D', 'E', 'F'] {
        src.push_str(&format!("CONSTANTS {c}{{10}}\n"));
        factors.push(format!("({})", (1..=10).map(|i| format!("{c}{i}")).collect::<Vec<_>>().join(" + ")));
    }
    src.push_str(&format!(
        "Z = {}*W' + G*W'^2 + 7\nX = EXCLUDE(Z, [W', G])\nY = INCLUDE(Z, G)\n",
        factors.join("*")
    ));
    let (m, _) = checks(&src);
    assert_eq!(number(&m, "X", &[("W'", 2.0), ("G", 3.0)]), 7.0);
    assert_eq!(number(&m, "Y", &[("W'", 2.0), ("G", 3.0)]), 12.0);
    // Not polynomial in W' (inside a sine): too large to select from, said so.
    let text = fails(&src.replace("G*W'^2", "G*SIN(W')"));
    assert!(text.contains("expanding this expression would give"), "{text}");
}

#[test]
fn a_matrix_of_vectors_dots_into_a_matrix() {
    let src = "NEWTONIAN N\nVARIABLES U1, U2\nCONSTANTS F1, F2\nV> = U1*N1> + 2*U2*N2>\n\
               P = [COEF(V>, U1), COEF(V>, U2)]\nF> = F1*N1> + F2*N2>\nX = DOT(P, F>)\n";
    let (m, _) = checks(src);
    let Some(Value::Matrix { rows: 1, cols: 2, data }) = m.value("X") else { panic!("{:?}", m.value("X")) };
    let v = m.model.ar.eval(&data, at(&m, &[("F1", 3.0), ("F2", 5.0)])).unwrap();
    assert_eq!(v, [3.0, 10.0]);
    let text = fails("NEWTONIAN N\nX = DOT(N1>, [N1>, N2>; N3>])\n");
    assert!(text.contains("matrix rows have different lengths"), "{text}");
}

#[test]
fn exclude_of_u_independent_rates_drops_the_independent_speeds_rates_after_constrain() {
    let src = "NEWTONIAN N\nPARTICLES P\nVARIABLES Q{2}', U{2}'\nCONSTANTS M, G, F\nMASS P = M\n\
               Q1' = U1\nQ2' = U2\nDEPENDENT[1] = U2 - U1\nCONSTRAIN(DEPENDENT[U2])\n\
               P_NO_P> = Q1*N1> + Q2*N2>\nV_P_N> = U1*N1> + U2*N2>\n\
               GRAVITY(-G*N2>)\nFORCE_P> += F*N1>\nZERO = FR() + FRSTAR()\n\
               B = EXCLUDE(ZERO[1], [U_INDEPENDENT'; G])\nC = EXCLUDE(ZERO[1], [U1'; G])\n\
               MU = COEF(ZERO[1], U1')\n";
    let (m, _) = checks(src);
    let values = [("M", 2.0), ("G", 9.81), ("F", 3.0), ("U1'", 5.0), ("U2'", 7.0)];
    assert_eq!(number(&m, "B", &values), 3.0);
    assert_eq!(number(&m, "C", &values), 3.0);
    // After CONSTRAIN, as in Autolev, the dependent rate U2' is U1': COEF gives the whole mass.
    assert_eq!(number(&m, "MU", &values), -4.0);
    // A file that declares the name keeps its own meaning.
    let (m, _) = checks(&src.replace("CONSTANTS M, G, F", "CONSTANTS M, G, F\nVARIABLES U_INDEPENDENT'"));
    assert_eq!(number(&m, "B", &values), 3.0 - 4.0 * 5.0);
}

#[test]
fn input_of_a_name_assigned_an_expression_is_its_value_at_the_inputs() {
    let src = "NEWTONIAN N\nVARIABLES Q', U, W\nCONSTANTS R, A\nA = PI/2\nU = R*Q'\nW = R*COS(Q)\n\
               INPUT R = 2, Q' = 3\nX = INPUT(U)*INPUT(A)\n";
    let (m, _) = checks(src);
    assert!((number(&m, "X", &[]) - 6.0 * std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    // An expression in a name without an INPUT value names that name.
    let text = fails(&src.replace("INPUT(U)*", "INPUT(W)*"));
    assert!(text.contains("`W` has no INPUT value yet (its expression holds `Q`, which has none)"), "{text}");
}

#[test]
fn nicheck_adds_the_work_of_the_active_forces_to_the_kinetic_energy() {
    let src = "NEWTONIAN N\nPARTICLES P\nVARIABLES Q{2}', U{2}'\nCONSTANTS M, G, F\nMASS P = M\n\
               Q1' = U1\nQ2' = U2\nDEPENDENT[1] = U2 - U1\nCONSTRAIN(DEPENDENT[U2])\n\
               P_NO_P> = Q1*N1> + Q2*N2>\nV_P_N> = U1*N1> + U2*N2>\nGRAVITY(-G*N2>)\n\
               FORCE_P> += F*N1>\nZERO = FR() + FRSTAR()\nKANE()\nCHECK = NICHECK()\n";
    let (m, _) = checks(src);
    let values = [("M", 2.0), ("G", 9.81), ("F", 3.0), ("U1", 1.0), ("U2", 1.0), ("WCHECK1", 0.5)];
    // KE = M (U1^2 + U2^2) / 2 = 2.
    assert!((number(&m, "CHECK", &values) - 2.5).abs() < 1e-12);
    // Its rate is minus the power of gravity and F along the constrained motion: -(F - M G) U1.
    let w = m.model.ar.lookup("WCHECK1").unwrap();
    let rate = m.model.kinematics(w).expect("WCHECK1 has a rate");
    let v = m.model.ar.eval(&[rate], at(&m, &values)).unwrap()[0];
    assert!((v - (2.0 * 9.81 - 3.0)).abs() < 1e-12, "{v}");
    // Its initial value is 0.
    assert!(m.inputs.iter().any(|i| i.name == "WCHECK1" && i.value == 0.0));
    let text = fails(&src.replace("NICHECK()", "NICHECK(M)"));
    assert!(text.contains("NICHECK takes no arguments"), "{text}");
}

#[test]
fn a_specifieds_formula_reaches_the_rate_nicheck_adds() {
    let src = "NEWTONIAN N\nBODIES B\nVARIABLES Q', U'\nSPECIFIED TQ\nSIMPROT(N, B, 3, Q)\nQ' = U\n\
               W_B_N> = U*N3>\nV_BO_N> = 0>\nMASS B = 1\nINERTIA B, 1, 1, 2\nTORQUE(B, TQ*N3>)\n\
               ZERO = FR() + FRSTAR()\nKANE()\nCHECK = NICHECK()\nTQ = 4*Q\nOUTPUT CHECK\n";
    let (m, _) = checks(src);
    let spec = m.into_spec("idiom").unwrap();
    assert!(spec.inputs.is_empty(), "TQ has a formula");
    // WCHECK1' = -TQ*U = -4*Q*U, its formula put in.
    let k = spec.equations.coordinates.iter().position(|q| spec.model.ar.symbol_info(*q).name == "WCHECK1");
    let rate = spec.equations.kinematics[k.expect("WCHECK1 is integrated")];
    let v = spec.model.ar.eval_named(rate, &[("Q", 0.5), ("U", 3.0)]).unwrap();
    assert!((v + 6.0).abs() < 1e-12, "{v}");
}

#[test]
fn units_of_an_index_range_give_each_name_its_unit() {
    let (m, _) = checks(
        "NEWTONIAN N\nVARIABLES Q{3}', U{2}'\nUNITS Q{3} = DEG, [U{2}'] = RAD/S^2\nQ1' = U1\nQ2' = U2\nQ3' = U1\nINPUT Q1 = 90, Q2 = 180, Q3 = 45\n",
    );
    let value = |n: &str| m.inputs.iter().find(|i| i.name == n).unwrap().value;
    let pi = std::f64::consts::PI;
    assert!((value("Q1") - pi / 2.0).abs() < 1e-15 && (value("Q2") - pi).abs() < 1e-15);
    assert!((value("Q3") - pi / 4.0).abs() < 1e-15);
}
