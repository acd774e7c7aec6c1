//! The `kane` command end to end: check, eval (against the hand-derived gimbal), compare, and
//! errors that name the file, line and column.

mod common;
use common::kane;

const GIMBAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/models/gimbal_gyroscope.al");
const HAND: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/gimbal_hand.al");
const HAND_WRONG: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/gimbal_hand_wrong.al");

#[test]
fn check_summarises_the_gimbal() {
    let (ok, out, _) = kane(&["check", GIMBAL]);
    assert!(ok);
    assert!(out.contains("3 coordinates (Q1, Q2, Q3), 3 speeds (U1, U2, U3), 3 bodies"), "{out}");
}

#[test]
fn eval_agrees_with_the_hand_derived_gimbal_at_random_states() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(21);
    for _ in 0..5 {
        let names =
            ["M1", "M2", "M3", "H1", "H2", "H3", "L", "W", "Y", "Z", "Q1", "Q2", "Q3", "U1", "U2", "U3"];
        let vals: Vec<f64> = names.iter().map(|_| rng.random_range(0.2..1.5)).collect();
        let sets: Vec<String> =
            names.iter().zip(&vals).map(|(n, v)| format!("{}={v}", n.to_lowercase())).collect();
        let mut args = vec!["eval", GIMBAL, "--json"];
        for s in &sets {
            args.push("--set");
            args.push(s);
        }
        let (ok, out, err) = kane(&args);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let g = |n: &str| vals[names.iter().position(|x| *x == n).unwrap()];
        let (m1, m2, m3, h1, h2, h3, l, w) =
            (g("M1"), g("M2"), g("M3"), g("H1"), g("H2"), g("H3"), g("L"), g("W"));
        let (y, z, q2, u1, u2, u3) = (g("Y"), g("Z"), g("Q2"), g("U1"), g("U2"), g("U3"));
        let i1 = 2.0 / 3.0 * m1 * (h1 * w - w * w);
        let j1 = 2.0 / 3.0 * m2 * (h2 * w - w * w);
        let j2 = m2 * h2 * h2 / 6.0 - m2 * (h2 - w).powi(2) / 6.0;
        let k1 = m3 * l * l / 2.0;
        let k2 = m3 * l * l / 4.0 + m3 * h3 * h3 / 12.0;
        let (s, c) = (q2.sin(), q2.cos());
        let f = [
            -y + 2.0 * (j1 + k1 - j2 - k2) * s * c * u1 * u2 + k1 * s * u2 * u3,
            -z + (j2 + k2 - j1 - k1) * s * c * u1 * u1 - k1 * s * u1 * u3,
            k1 * s * u1 * u2,
        ];
        let m11 = i1 + j1 * c * c + j2 * s * s + k1 * c * c + k2 * s * s;
        let mass = [[m11, 0.0, k1 * c], [0.0, j1 + k2, 0.0], [k1 * c, 0.0, k1]];
        for r in 0..3 {
            let got = v["forcing"][r].as_f64().unwrap();
            assert!((got - f[r]).abs() < 1e-12 * f[r].abs().max(1.0), "f{r}: {got} vs {}", f[r]);
            for s2 in 0..3 {
                let got = v["mass_matrix"][r][s2].as_f64().unwrap();
                assert!((got - mass[r][s2]).abs() < 1e-12 * mass[r][s2].abs().max(1.0));
            }
        }
        assert_eq!(v["coordinates"], serde_json::json!(["Q1", "Q2", "Q3"]));
        assert_eq!(v["qdot"][2].as_f64().unwrap(), u3);
    }
}

#[test]
fn eval_takes_inputs_from_the_file_and_converts_degrees() {
    let (ok, out, err) = kane(&["eval", GIMBAL, "--json", "--set", "Q2=0.5"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // Z = 10 from INPUT; at U = (0, 0, 10) the only force is -Z on row 2.
    assert_eq!(v["forcing"][1].as_f64().unwrap(), -10.0);
    let (ok, _, err) = kane(&["eval", GIMBAL, "--set", "NOPE=1"]);
    assert!(!ok && err.contains("the model has no symbol `NOPE`"), "{err}");
}

#[test]
fn compare_proves_the_hand_derivation_and_finds_a_wrong_one() {
    let (ok, out, err) = kane(&["compare", GIMBAL, HAND]);
    assert!(ok, "{out}{err}");
    assert_eq!(out.matches("proven equal").count(), 3, "{out}");
    let (ok, out, _) = kane(&["compare", GIMBAL, HAND_WRONG]);
    assert!(!ok);
    assert!(out.contains("ZERO[1]: proven equal") && out.contains("ZERO[3]: DIFFERS: hand"), "{out}");
}

#[test]
fn errors_name_file_line_and_column() {
    let dir = std::env::temp_dir().join(format!("kane-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.al");
    std::fs::write(&bad, "NEWTONIAN N\nFRAMES A\nSIMPROT(N, A, 3, QQ)\n").unwrap();
    let (ok, _, err) = kane(&["check", bad.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("bad.al:3:18: `QQ` is not defined"), "{err}");
    assert!(err.contains("help:"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_closed_pipe_ends_the_command_quietly() {
    use std::io::Read;
    use std::process::{Command, Stdio};
    let bicycle = concat!(env!("CARGO_MANIFEST_DIR"), "/models/whipple_bicycle.al");
    let mut child = Command::new(env!("CARGO_BIN_EXE_kane"))
        .args(["eoms", bicycle])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Read a little, then close the pipe, as `kane eoms FILE | head -1` does.
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && !err.contains("panicked"), "{:?} {err}", out.status);
}

#[test]
fn linearize_says_where_it_linearised() {
    let pendulum = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/examples/pendulum.al");
    let (ok, out, err) = kane(&["linearize", pendulum, "--set", "Q=0.25"]);
    assert!(ok, "{err}");
    assert!(out.contains("at t = 0: Q = 0.25, U = 0"), "{out}");
    assert!(out.contains("inputs: none"), "{out}");
    let (ok, out, err) = kane(&["linearize", pendulum, "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["t"], 0.0);
    assert!((v["point"]["Q"].as_f64().unwrap() - 30f64.to_radians()).abs() < 1e-15, "{out}");
}
