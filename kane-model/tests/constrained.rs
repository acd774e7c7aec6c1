//! Motion constraints solved numerically where the equations are evaluated: `kane eval` of a
//! constrained file against a hand derivation, a named error where the constraints lose rank,
//! and the constraints printed by `kane eoms`.

mod common;
use common::kane;

const SLAVED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/slaved_particles.al");
const DISC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/rolling_disc.al");

/// `u1'` of the slaved particles by hand: the constraint `sin(q1) u2 = q1 u1` makes `u2 = c u1`
/// with `c = q1 / sin(q1)`, so the one degree of freedom has mass `m (1 + c^2)` and
/// `m (1 + c^2) u1' + m c c' u1^2 = -k q1`.
fn by_hand(q1: f64, u1: f64, m: f64, k: f64) -> (f64, f64) {
    let c = q1 / q1.sin();
    let dc = (q1.sin() - q1 * q1.cos()) / q1.sin().powi(2);
    ((-k * q1 - m * c * dc * u1 * u1) / (m * (1.0 + c * c)), c * u1)
}

#[test]
fn eval_solves_the_dependent_speed_numerically() {
    for (q1, u1) in [(0.5, 0.3), (-1.1, 2.0), (2.0, -0.7)] {
        let sets = [format!("Q1={q1}"), format!("U1={u1}")];
        let (ok, out, err) = kane(&["eval", SLAVED, "--json", "--set", &sets[0], "--set", &sets[1]]);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let (udot, u2) = by_hand(q1, u1, 1.0, 2.0);
        let got_udot = v["udot"][0].as_f64().unwrap();
        let got_u2 = v["dependent_values"][0].as_f64().unwrap();
        assert!((got_udot - udot).abs() < 1e-13 * udot.abs().max(1.0), "{got_udot} vs {udot}");
        assert!((got_u2 - u2).abs() < 1e-13 * u2.abs().max(1.0), "{got_u2} vs {u2}");
        assert_eq!(v["dependent_speeds"][0], "U2");
    }
}

#[test]
fn eval_names_the_configuration_where_the_constraints_lose_rank() {
    let (ok, out, err) = kane(&["eval", SLAVED, "--set", "Q1=0"]);
    assert!(!ok && out.is_empty(), "{out}");
    assert!(err.contains("the constraints lose rank at Q1 = 0, Q2 = 0"), "{err}");
}

#[test]
fn eoms_prints_the_constraints_and_the_equations_over_all_speeds() {
    let (ok, out, err) = kane(&["eoms", DISC]);
    assert!(ok, "{err}");
    assert!(out.contains("dependent speeds U4, U5"), "{out}");
    assert!(out.contains("CONSTRAINT[1] = U4 - R*cos(Q1)*U3"), "{out}");
    assert!(out.contains("M[5,5] = M"), "{out}");
    let (ok, out, _) = kane(&["check", DISC]);
    assert!(ok && out.contains("3 speeds (U1, U2, U3) and 2 dependent (U4, U5)"), "{out}");
    // Exactly upright, a symmetric state, the rates are finite.
    let (ok, out, err) = kane(&["eval", DISC, "--json", "--set", "Q2=0"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["udot"].as_array().unwrap().iter().all(|x| x.as_f64().is_some_and(f64::is_finite)), "{out}");
}

#[test]
fn accelerations_a_file_writes_after_constrain_give_the_same_equations() {
    const OWN: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/rolling_disc_own_accelerations.al");
    for state in [["Q2=0", "U2=0.1"], ["Q2=0.4", "U2=-1.5"]] {
        let args = |file| vec!["eval", file, "--json", "--set", state[0], "--set", state[1]];
        let (ok_a, a, err_a) = kane(&args(DISC));
        let (ok_b, b, err_b) = kane(&args(OWN));
        assert!(ok_a && ok_b, "{err_a}{err_b}");
        let (a, b): (serde_json::Value, serde_json::Value) =
            (serde_json::from_str(&a).unwrap(), serde_json::from_str(&b).unwrap());
        for (x, y) in a["udot"].as_array().unwrap().iter().zip(b["udot"].as_array().unwrap()) {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!((x - y).abs() < 1e-12 * x.abs().max(1.0), "{x} vs {y}");
        }
    }
}

#[test]
fn linearize_gives_the_upright_discs_lean_and_yaw_coupling() {
    // Upright rolling at spin w (R = 0.5, g = 9.81): U1' = -2 w U2, U2' = 4 g/(5 R) Q2 + 6 w/5 U1,
    // so lean oscillates when w^2 > g / (3 R), the textbook criterion for a thin disc.
    for w in [4.0, 2.0] {
        let spin = format!("U3={w}");
        let args =
            ["linearize", DISC, "--json", "--set", "Q2=0", "--set", "U1=0", "--set", "U2=0", "--set", &spin];
        let (ok, out, err) = kane(&args);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let a = |i: usize, j: usize| v["A"][i][j].as_f64().unwrap();
        let states: Vec<&str> = v["states"].as_array().unwrap().iter().map(|s| s.as_str().unwrap()).collect();
        assert_eq!(states, ["Q1", "Q2", "Q3", "X", "Y", "U1", "U2", "U3"]);
        let close = |x: f64, y: f64| (x - y).abs() < 1e-12 * y.abs().max(1.0);
        assert!(close(a(5, 6), -2.0 * w) && close(a(6, 5), 1.2 * w), "{out}");
        assert!(close(a(6, 1), 4.0 * 9.81 / 2.5), "{out}");
        // lambda^2 of the lean-yaw pair: a(6,1) + a(6,5) a(5,6).
        let lambda2 = a(6, 1) + a(6, 5) * a(5, 6);
        assert_eq!(lambda2 < 0.0, w * w > 9.81 / 1.5, "w = {w}: lambda^2 = {lambda2}");
    }
}

#[test]
fn linearize_takes_constants_as_inputs() {
    // d(u1')/dK = -q1 / (m (1 + c^2)) for the slaved particles, c = q1 / sin(q1).
    let (ok, out, err) = kane(&["linearize", SLAVED, "--json", "--input", "K"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let c = 0.5 / 0.5f64.sin();
    let want = -0.5 / (1.0 + c * c);
    let got = v["B"][2][0].as_f64().unwrap();
    assert!((got - want).abs() < 1e-14, "{got} vs {want}: {out}");
    assert_eq!(v["inputs"][0], "K");
    let (ok, _, err) = kane(&["linearize", SLAVED, "--input", "NOPE"]);
    assert!(!ok && err.contains("--input NOPE: not a constant or input the equations read"), "{err}");
}
