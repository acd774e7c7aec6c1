//! Auxiliary speeds and loads solved with the speed rates (`CONSTRAIN(AUXILIARY[U2])`,
//! `KANE(ETOR)`): a double pendulum whose elbow follows a prescribed angle, against the same
//! pendulum with a free elbow driven by the torque found; the equations printed; misuse named.

mod common;
use common::kane;

const PRESCRIBED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/prescribed_elbow.al");
const FREE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/free_elbow.al");
const DISC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/rolling_disc.al");
const DISC_CONTACT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/rolling_disc_contact.al");

/// `kane eval FILE --json --set ...` parsed.
fn eval(file: &str, sets: &[String]) -> serde_json::Value {
    let mut args = vec!["eval", file, "--json"];
    for s in sets {
        args.extend(["--set", s.as_str()]);
    }
    let (ok, out, err) = kane(&args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

fn number(v: &serde_json::Value, key: &str, i: usize) -> f64 {
    v[key][i].as_f64().unwrap()
}

#[test]
fn the_solved_torque_drives_the_free_pendulum_along_the_prescribed_motion() {
    let (amp, w) = (0.5_f64, 2.0_f64);
    for (t, q1, u1) in [(0.4_f64, 0.3, 0.0), (1.3, -0.8, 2.5), (2.9, 2.0, -1.2)] {
        let at = [format!("T={t}"), format!("Q1={q1}"), format!("U1={u1}")];
        let prescribed = eval(PRESCRIBED, &at);
        assert_eq!(prescribed["loads"][0], "ETOR");
        let torque = number(&prescribed, "load_values", 0);
        let (ea, ea1, ea2) = (amp * (w * t).sin(), amp * w * (w * t).cos(), -amp * w * w * (w * t).sin());
        let state = [q1, ea, u1, ea1, torque];
        let sets: Vec<String> =
            state.iter().zip(["Q1", "Q2", "U1", "U2", "T2"]).map(|(v, n)| format!("{n}={v}")).collect();
        let free = eval(FREE, &sets);
        let (u1dot, free_u1dot) = (number(&prescribed, "udot", 0), number(&free, "udot", 0));
        assert!((u1dot - free_u1dot).abs() < 1e-12 * u1dot.abs().max(1.0), "{u1dot} vs {free_u1dot}");
        let elbow = number(&free, "udot", 1);
        assert!(
            (elbow - ea2).abs() < 1e-12 * ea2.abs().max(1.0),
            "the elbow's acceleration {elbow} vs {ea2}"
        );
    }
}

#[test]
fn contact_forces_brought_into_evidence_leave_the_rolling_disc_s_motion_as_it_was() {
    for (q2, u2, u3) in [(0.2, 0.1, 4.0), (0.0, 0.0, 3.0), (-0.7, 1.5, -2.0)] {
        let sets = [format!("Q2={q2}"), format!("U2={u2}"), format!("U3={u3}")];
        let (plain, contact) = (eval(DISC, &sets), eval(DISC_CONTACT, &sets));
        assert_eq!(contact["loads"], serde_json::json!(["FC1", "FC2", "FC3"]));
        for i in 0..3 {
            let (a, b) = (number(&plain, "udot", i), number(&contact, "udot", i));
            assert!((a - b).abs() < 1e-13 * a.abs().max(1.0), "U{}': {a} vs {b}", i + 1);
        }
        for i in 0..2 {
            assert_eq!(number(&plain, "dependent_values", i), number(&contact, "dependent_values", i));
        }
        assert!(number(&contact, "load_values", 2).is_finite());
    }
}

#[test]
fn check_accepts_the_auxiliary_speed_and_eoms_prints_its_equation() {
    let (ok, out, err) = kane(&["check", PRESCRIBED]);
    assert!(ok && out.contains("1 speed (U1)"), "{out}{err}");
    let (ok, out, err) = kane(&["eoms", PRESCRIBED]);
    assert!(ok, "{err}");
    assert!(
        out.contains(
            "Loads solved with the speed rates (KANE): ETOR, from the equations of the auxiliary speeds U2"
        ),
        "{out}"
    );
    let aux = out.lines().find(|l| l.starts_with("ZERO[2] = ")).expect("the auxiliary speed's equation");
    assert!(aux.contains("ETOR") && aux.contains("U1'"), "{aux}");
}

/// The prescribed-elbow file with `from` replaced by `to`, checked.
fn check_changed(from: &str, to: &str) -> String {
    let dir = std::env::temp_dir().join(format!("kane-aux-{}-{}", std::process::id(), to.len()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("changed.al");
    let text = std::fs::read_to_string(PRESCRIBED).unwrap().replace(from, to);
    assert!(text.contains(to));
    std::fs::write(&file, text).unwrap();
    let (ok, out, err) = kane(&["check", file.to_str().unwrap()]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!ok, "{out}");
    err
}

#[test]
fn misuse_is_named() {
    let err = check_changed("CONSTRAIN(AUXILIARY[U2])", "% no auxiliary speeds");
    assert!(
        err.contains("KANE names 1 loads but CONSTRAIN(AUXILIARY[...]) declared 0 auxiliary speeds"),
        "{err}"
    );
    let err = check_changed("KANE(ETOR)", "KANE(L)");
    assert!(err.contains("KANE solves for time-dependent quantities"), "{err}");
    let err = check_changed("CONSTRAIN(AUXILIARY[U2])", "CONSTRAIN(AUXILIARY[Q1])");
    assert!(err.contains("`Q1` is not a generalized speed"), "{err}");
}
