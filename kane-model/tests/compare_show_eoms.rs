//! `kane compare` saying how hand equations differ, `kane show`, and `kane eoms` simplified,
//! end to end through the built binary.

mod common;
use common::kane;

const GIMBAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/models/gimbal_gyroscope.al");

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn k1_written_for_k2_prints_the_differing_term() {
    let (ok, out, _) = kane(&["compare", GIMBAL, &data("gimbal_hand_k1_for_k2.al")]);
    assert!(!ok, "a difference must fail the command");
    assert!(out.contains("ZERO[1]: DIFFERS: hand - derived = (K2 - K1)*sin(Q2)^2*U1'\n"), "{out}");
    assert!(out.contains("ZERO[2]: proven equal") && out.contains("ZERO[3]: proven equal"), "{out}");
    assert!(out.contains("1 of 3 differ"), "{out}");
    insta::assert_snapshot!("compare_k1_for_k2", out);
}

#[test]
fn every_equation_negated_is_equal_up_to_sign_only_when_asked() {
    let (ok, out, _) = kane(&["compare", GIMBAL, &data("gimbal_hand_negated.al")]);
    assert!(!ok, "a sign difference passes only with --up-to-sign: {out}");
    assert!(
        out.contains("3 of 3 differ (3 only in sign: hand = -derived; an equation negated as a whole"),
        "{out}"
    );
    let (ok, out, err) = kane(&["compare", GIMBAL, &data("gimbal_hand_negated.al"), "--up-to-sign"]);
    assert!(ok, "{out}{err}");
    assert_eq!(out.matches("equal up to sign (hand = -derived), proven").count(), 3, "{out}");
    assert!(out.contains("equal up to sign: every equation is the derived one negated"), "{out}");
}

#[test]
fn a_velocity_component_of_the_opposite_sign_differs_even_up_to_sign() {
    let dir = std::env::temp_dir().join(format!("kane-compare-sign-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hand = dir.join("hand.al");
    let right = std::fs::read_to_string(data("gimbal_hand_velocity.al")).unwrap();
    let line = right.lines().find(|l| l.starts_with("V_P_A>")).expect("a velocity line").to_string();
    let (name, value) = line.split_once('=').unwrap();
    std::fs::write(&hand, right.replace(&line, &format!("{name}= -({})", value.trim()))).unwrap();
    for extra in [None, Some("--up-to-sign")] {
        let mut args = vec!["compare", GIMBAL, hand.to_str().unwrap()];
        args.extend(extra);
        let (ok, out, _) = kane(&args);
        assert!(!ok, "{out}");
        assert!(out.contains("V_P_A> . D") && out.contains("DIFFERS in sign: hand = -derived"), "{out}");
        assert!(out.contains("a rate or a quantity of the opposite sign is a different one"), "{out}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn swapped_equations_say_the_order_differs() {
    let (ok, out, err) = kane(&["compare", GIMBAL, &data("gimbal_hand_swapped.al")]);
    assert!(ok, "{out}{err}");
    assert!(out.contains("ZERO[1]: equals derived ZERO[2] (the order of the equations differs)"), "{out}");
    assert!(out.contains("ZERO[2]: equals derived ZERO[1]"), "{out}");
    assert!(out.contains("ZERO[3]: proven equal"), "{out}");
    assert!(out.contains("equal up to the order of the equations"), "{out}");
}

#[test]
fn speed_derivatives_are_checked_through_the_mass_matrix() {
    let free_body = concat!(env!("CARGO_MANIFEST_DIR"), "/models/free_body.al");
    let (ok, out, _) = kane(&["compare", free_body, &data("free_body_hand_udot_wrong.al")]);
    assert!(!ok, "{out}");
    assert_eq!(out.matches("proven equal").count(), 2, "{out}");
    // One rate of three negated is a wrong rate, not equality up to sign.
    assert!(out.contains("W3' (row 3 of M u' = f"), "{out}");
    assert!(out.contains("DIFFERS: hand - derived = 2*(I2 - I1)*W1*W2\n"), "{out}");
}

#[test]
fn a_velocity_is_compared_per_component() {
    let (ok, out, err) = kane(&["compare", GIMBAL, &data("gimbal_hand_velocity.al")]);
    assert!(ok, "{out}{err}");
    assert_eq!(out.matches("V_P_A> . D").count(), 3, "{out}");
    assert!(out.contains("V_P_A> . D3>: proven equal") && out.contains("K1: proven equal"), "{out}");
    assert!(out.contains("W_B_A> . A2>: proven equal"), "{out}");
    let (ok, out, _) = kane(&["compare", GIMBAL, &data("gimbal_hand_velocity_wrong.al")]);
    assert!(!ok);
    assert!(out.contains("V_P_A> . D3>: DIFFERS: hand - derived = -L*U3\n"), "{out}");
    assert!(out.contains("V_P_A> . D2>: proven equal"), "{out}");
}

#[test]
fn differences_are_shown_at_the_files_input_values() {
    let (_, out, _) = kane(&["compare", GIMBAL, &data("gimbal_hand_velocity_wrong.al")]);
    // The first point is the INPUT case itself: L = .3, Q = 0, U3 = 10.
    assert!(out.contains("L = 0.300000, Q1 = 0.000000, Q2 = 0.000000, Q3 = 0.000000"), "{out}");
    assert!(out.contains("U3 = 10.000000: hand 0.000000e0, derived 3.000000e0"), "{out}");
    // Masses stay positive at every point.
    let (_, out, _) = kane(&["compare", GIMBAL, &data("gimbal_hand_k1_for_k2.al")]);
    let m3: f64 = out.split("M3 = ").nth(1).unwrap().split(',').next().unwrap().parse().unwrap();
    assert!((40.0..=60.0).contains(&m3), "M3 = {m3} is not near its INPUT value 50");
}

#[test]
fn hand_file_errors_name_file_line_and_column() {
    let dir = std::env::temp_dir().join(format!("kane-compare-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("hand.al");
    std::fs::write(&bad, "% hand\nV_P_A> = L*U1*A1>\nZERO[1] = K9*U1'\n").unwrap();
    let (ok, _, err) = kane(&["compare", GIMBAL, bad.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("hand.al:3:11: `K9` is not defined"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn show_prints_known_quantities() {
    let (ok, out, err) = kane(&["show", GIMBAL, "I_D_DO>>"]);
    assert!(ok, "{err}");
    assert_eq!(out, "I_D_DO>> = K2*D1>*D1> + K1*D2>*D2> + K2*D3>*D3>\n");
    let (_, out, _) = kane(&["show", GIMBAL, "K2"]);
    assert_eq!(out, "K2 = M3*L^2/4 + M3*H3^2/12\n");
    let (_, out, _) = kane(&["show", GIMBAL, "V_P_A>", "--frame", "D"]);
    assert_eq!(out, "V_P_A> = (-L*cos(Q3)*sin(Q2)*U1 + L*sin(Q3)*U2)*D2> + (L*U3 + L*cos(Q2)*U1)*D3>\n");
    let (_, out, _) = kane(&["show", GIMBAL, "Y*A1> - (I1+K1)*A2> + (I1+K1)*A1>"]);
    assert!(out.ends_with(" = (Y + I1 + K1)*A1> - (I1 + K1)*A2>\n"), "{out}");
    let (ok, _, err) = kane(&["show", GIMBAL, "V_Q_A>"]);
    assert!(!ok && err.contains("`V_Q_A>` is not defined"), "{err}");
}

#[test]
fn eoms_are_simplified_in_the_files_names() {
    let (ok, out, err) = kane(&["eoms", GIMBAL]);
    assert!(ok, "{err}");
    assert!(out.contains("M[1,1] = I1 + J2 + K2 + (J1 + K1 - J2 - K2)*cos(Q2)^2\n"), "{out}");
    assert!(out.contains("M[2,2] = J1 + K2\n"), "{out}");
    assert!(out.contains("f[3] = K1*sin(Q2)*U1*U2\n"), "{out}");
    assert!(
        out.contains("ZERO[1] = -K1*cos(Q2)*U3' - (I1 + J2 + K2 + (J1 + K1 - J2 - K2)*cos(Q2)^2)*U1'"),
        "{out}"
    );
    assert!(out.contains("ZERO[3] = -K1*cos(Q2)*U1' - K1*U3' + K1*sin(Q2)*U1*U2\n"), "{out}");
    assert!(!out.contains("M1") && !out.contains("H1"), "names were expanded: {out}");
    let eoms = out.split("\n% Partial velocities").next().unwrap().to_string();
    insta::assert_snapshot!("eoms_gimbal_text", eoms);
}

/// True when every `{` closes, in order, and `\left` and `\right` pair up.
fn balanced(tex: &str) -> bool {
    let mut depth = 0i32;
    for c in tex.chars() {
        depth += match c {
            '{' => 1,
            '}' => -1,
            _ => 0,
        };
        if depth < 0 {
            return false;
        }
    }
    depth == 0 && tex.matches("\\left").count() == tex.matches("\\right").count()
}

#[test]
fn eoms_latex_is_a_balanced_align_block() {
    let (ok, out, err) = kane(&["eoms", GIMBAL, "--format", "latex"]);
    assert!(ok, "{err}");
    let body: Vec<&str> = out.lines().filter(|l| !l.starts_with('%')).collect();
    assert_eq!(body.first(), Some(&"\\begin{align*}"), "{out}");
    assert_eq!(body.last(), Some(&"\\end{align*}"), "{out}");
    let rows = &body[1..body.len() - 1];
    assert!(rows.len() >= 6, "{out}");
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r.matches('&').count(), 1, "one alignment point per row: {r}");
        assert_eq!(r.ends_with(" \\\\"), i + 1 < rows.len(), "row breaks: {r}");
        assert!(balanced(r), "unbalanced row: {r}");
    }
    assert!(balanced(&out));
    let text_syntax = rows.iter().any(|r| r.contains('\'') || r.contains('*'));
    assert!(!text_syntax, "text syntax leaked into LaTeX: {out}");
    assert!(out.contains("\\dot{Q}_{1} &= U_{1}"), "{out}");
    assert!(out.contains("0 &= -K_{1} \\cos\\left(Q_{2}\\right) \\dot{U}_{1} - K_{1} \\dot{U}_{3}"), "{out}");
}

#[test]
fn angle_differences_and_double_angles_are_proven_and_reduced() {
    let model = data("double_pendulum_absolute.al");
    let (ok, out, err) = kane(&["compare", &model, &data("double_pendulum_hand_rates.al")]);
    assert!(ok, "{out}{err}");
    assert_eq!(out.matches("proven equal").count(), 2, "{out}");
    let (ok, out, _) = kane(&["compare", &model, &data("double_pendulum_hand_sum_for_difference.al")]);
    assert!(!ok, "{out}");
    assert!(out.contains("ZERO[1]: proven equal\n"), "{out}");
    // sin(Q1 + Q2) - sin(Q1 - Q2), reduced: the groups that are zero do not appear.
    assert!(out.contains("ZERO[2]: DIFFERS: hand - derived = 2*L1*L2*M2*cos(Q1)*sin(Q2)*U1^2\n"), "{out}");
}
