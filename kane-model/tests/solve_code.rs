//! `kane solve`: the systems a file names in CODE ALGEBRAIC and CODE NONLINEAR, solved at its
//! INPUT values, against hand solutions (a beam's reactions, a two-link arm's inverse
//! kinematics, the public corpus's linear system); what cannot be solved is named.

mod common;
use common::kane;

const BEAM: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/beam_reactions.al");
const ARM: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/arm_reach.al");
const RULETEST11: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/autolev-corpus/ruletest11.al");

/// The values of the first system `kane solve FILE --json ARGS` prints.
fn solved(file: &str, args: &[&str]) -> Vec<f64> {
    let mut all = vec!["solve", file, "--json"];
    all.extend(args);
    let (ok, out, err) = kane(&all);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    v["systems"][0]["values"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

fn close(got: f64, want: f64, tol: f64) -> bool {
    (got - want).abs() <= tol * want.abs().max(1.0)
}

#[test]
fn linear_systems_equal_their_hand_solutions() {
    // RA = W (L - A) / L, RB = W A / L.
    for (l, w, a) in [(4.0, 1000.0, 1.0), (2.5, 30.0, 2.0)] {
        let sets = [format!("L={l}"), format!("W={w}"), format!("A={a}")];
        let args: Vec<&str> = sets.iter().flat_map(|s| ["--set", s.as_str()]).collect();
        let x = solved(BEAM, &args);
        assert!(close(x[0], w * (l - a) / l, 1e-14) && close(x[1], w * a / l, 1e-14), "{x:?}");
    }
    let x = solved(RULETEST11, &[]);
    assert!(close(x[0], 2.0 / 7.0, 1e-14) && close(x[1], 9.0 / 7.0, 1e-14), "{x:?}");
    let (ok, out, _) = kane(&["check", BEAM]);
    assert!(
        ok && out.contains("solved numerically by `kane solve` (no file written): CODE ALGEBRAIC (line 8)"),
        "{out}"
    );
}

#[test]
fn a_nonlinear_system_converges_to_the_closed_form_from_its_input_start() {
    let (l1, l2, x, y) = (0.5_f64, 0.4_f64, 0.6_f64, 0.3_f64);
    let q2 = ((x * x + y * y - l1 * l1 - l2 * l2) / (2.0 * l1 * l2)).acos();
    let q1 = y.atan2(x) - (l2 * q2.sin()).atan2(l1 + l2 * q2.cos());
    let got = solved(ARM, &[]);
    assert!(close(got[0], q1, 1e-13) && close(got[1], q2, 1e-13), "{got:?} vs {q1}, {q2}");
    // Started with the elbow down, it finds the mirror solution.
    let got = solved(ARM, &["--set", "Q2=-1"]);
    assert!(close(got[1], -q2, 1e-13), "{got:?}");
    let (ok, out, err) = kane(&["solve", ARM]);
    assert!(ok && out.contains("% CODE NONLINEAR (line 9):") && out.contains("Q1 = "), "{out}{err}");
}

/// `kane solve` (or check) of the arm file with `from` replaced by `to`: its error.
fn failing(command: &str, from: &str, to: &str) -> String {
    let dir = std::env::temp_dir().join(format!("kane-solve-{}-{}", std::process::id(), to.len()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("arm.al");
    let text = std::fs::read_to_string(ARM).unwrap().replace(from, to);
    std::fs::write(&file, text).unwrap();
    let (ok, out, err) = kane(&[command, file.to_str().unwrap()]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!ok, "{out}");
    err
}

#[test]
fn what_cannot_be_solved_is_named() {
    let err = failing("solve", "INPUT Q1 = 20 DEG, Q2 = 60 DEG", "INPUT Q2 = 60 DEG");
    assert!(err.contains("arm.al:9: CODE NONLINEAR: CODE NONLINEAR needs a starting value for Q1"), "{err}");
    // Out of reach: no solution exists.
    let err = failing("solve", "X = 0.6", "X = 1.6");
    assert!(err.contains("did not converge") || err.contains("singular"), "{err}");
    let err = failing("check", "CODE NONLINEAR", "CODE ALGEBRAIC");
    assert!(err.contains("EQN[1] is not linear in the unknowns") && err.contains("CODE NONLINEAR"), "{err}");
    let err = failing("check", "CODE NONLINEAR(EQN, Q1, Q2)", "CODE NONLINEAR(EQN, Q1)");
    assert!(err.contains("EQN has 2, 1 unknowns named"), "{err}");
}
