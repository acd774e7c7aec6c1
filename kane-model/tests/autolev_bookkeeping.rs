//! Research Autolev files keep books: a unit system, session settings, `;` terminators and
//! compound unit tags. They load; UNITSYSTEM converts INPUT values into its units;
//! the rest is reported as ignored; and one mistake gives one error, with a did-you-mean.

mod common;

use common::kane;
use kane_model::lang;

const FILE: &str = "tests/data/bookkeeping_pendulum.al";

fn input(m: &lang::LoadedModel, name: &str) -> f64 {
    m.inputs.iter().find(|i| i.name == name).unwrap_or_else(|| panic!("no INPUT {name}")).value
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[test]
fn inputs_are_converted_into_the_unit_system() {
    let m = lang::load(FILE, include_str!("data/bookkeeping_pendulum.al")).unwrap();
    // UNITSYSTEM G, CM, SEC: grams, centimetres, seconds; angles in radians.
    assert!(close(input(&m, "M"), 2000.0));
    assert!(close(input(&m, "L"), 50.0));
    assert!(close(input(&m, "G"), 981.0));
    assert!(close(input(&m, "IZZ"), 0.04 * 1e7), "kg m^2 is 1e7 g cm^2");
    assert!(close(input(&m, "Q"), std::f64::consts::PI / 6.0));
    assert!(close(input(&m, "U"), 2.0 * std::f64::consts::PI), "60 rpm is 2 pi rad/s");
    let units: Vec<Option<&str>> = m.outputs.iter().map(|(_, u)| u.as_deref()).collect();
    assert_eq!(units, [Some("RAD"), Some("RAD/SEC"), Some("CM")]);
}

#[test]
fn check_reports_the_bookkeeping_and_eval_is_the_hand_result() {
    let (ok, out, err) = kane(&["check", FILE]);
    assert!(ok, "{err}");
    let summary = out.lines().find(|l| l.contains(": bookkeeping ")).expect("a bookkeeping line");
    assert!(summary.contains("applied: UNITSYSTEM (line 3)"), "{summary}");
    for ignored in ["AUTOZ (line 4)", "AUTOEPSILON (line 6)", "PAUSE (line 22)", "SAVE (line 27)"] {
        assert!(summary.contains(ignored), "{ignored} in {summary}");
    }
    // Pivoted at O, mass centre at L: (IZZ + M L^2) U' = -M G L cos(Q), in any consistent units.
    let (ok, out, err) = kane(&["eval", FILE, "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let udot = v["udot"][0].as_f64().unwrap();
    let (m, l, g, izz) = (2000.0, 50.0, 981.0, 0.04e7);
    let want = -m * g * l * (std::f64::consts::PI / 6.0).cos() / (izz + m * l * l);
    assert!(close(udot, want), "{udot} vs {want}");
}

#[test]
fn one_mistake_gives_one_error_with_a_did_you_mean() {
    let src =
        include_str!("data/bookkeeping_pendulum.al").replace("SIMPROT(N, B, 3, Q);", "SIMPORT(N, B, 3, Q);");
    let e = lang::load("typo.al", &src).err().expect("an error").to_string();
    assert_eq!(e.matches("error:").count(), 1, "follow-on errors are not reported: {e}");
    assert!(e.contains("unknown command `SIMPORT`") && e.contains("did you mean `SIMPROT`?"), "{e}");
    let e =
        lang::load("typo.al", &src.replace("SIMPORT", "SIMPROT").replace("PAUSE", "PAUSEX")).err().unwrap();
    let e = e.to_string();
    assert!(e.contains("unknown command `PAUSEX`") && e.contains("did you mean `PAUSE`?"), "{e}");
    let e = lang::load(
        "typo.al",
        &src.replace("SIMPORT", "SIMPROT").replace("BODIES B;", "BODIES B C D E F G H;"),
    );
    let e = e.err().expect("a declaration error").to_string();
    assert_eq!(e.matches("error:").count(), 1, "names of a bad declaration raise no more errors: {e}");
}

#[test]
fn a_unit_system_names_mass_length_and_time_once_each() {
    let e = lang::load("u.al", "UNITSYSTEM KG, N, SEC\n").err().unwrap().to_string();
    assert!(e.contains("u.al:1:16") && e.contains("`N` is not a unit of mass, length or time"), "{e}");
    let e = lang::load("u.al", "CONSTANTS K\nINPUT K = 3 M/FURLONG\n").err().unwrap().to_string();
    assert!(e.contains("unknown unit `FURLONG`"), "{e}");
}

#[test]
fn a_plain_input_is_in_the_unit_units_declares_for_angles_and_their_rates() {
    let src = "NEWTONIAN N\nVARIABLES Q', U', X'\nUNITS Q = DEG, U = DEG/S, X = CM\nQ' = U\nX' = U\nINPUT Q = 90, U = 60, X = 5\n";
    let m = lang::load("units.al", src).unwrap();
    assert!(close(input(&m, "Q"), std::f64::consts::FRAC_PI_2), "90 deg");
    assert!(close(input(&m, "U"), std::f64::consts::PI / 3.0), "60 deg/s");
    assert!(close(input(&m, "X"), 5.0), "a length is kept as written");
}
