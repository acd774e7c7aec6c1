//! `kane check`: assigned kinematics that contradict positions and orientations are errors naming
//! both lines (unless marked `% override`), and implausible INPUT values are warnings naming the
//! parameter and its INPUT line; through the library and through the `kane` command.

mod common;
use common::kane;

use kane_model::lang::{self, Severity};

const MODELS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/models");

fn model(name: &str) -> String {
    std::fs::read_to_string(format!("{MODELS}/{name}")).expect("read model")
}

/// The paper's gimbal with the rotor's mass centre moved off O (A_DO_A> = 0> kept).
fn offset_gimbal() -> String {
    let src = model("gimbal_gyroscope.al");
    assert!(src.contains("P_O_DO> = 0>   "));
    src.replace("P_O_DO> = 0>   ", "P_O_DO> = 0.1*D2>")
}

/// The 1-based line of the first line starting with `start`.
fn line_of(src: &str, start: &str) -> usize {
    src.lines().position(|l| l.starts_with(start)).expect("line present") + 1
}

#[test]
fn offset_rotor_is_an_error_naming_both_lines() {
    let src = offset_gimbal();
    let report = match lang::check("gimbal.al", &src) {
        Err(r) => r,
        Ok(_) => panic!("the offset rotor checked"),
    };
    let text = report.to_string();
    let (a, p, v) = (line_of(&src, "A_DO_A>"), line_of(&src, "P_O_DO>"), line_of(&src, "V_O_A>"));
    assert!(
        text.contains(&format!(
            "gimbal.al:{a}:1: error: `A_DO_A> = 0>` contradicts the acceleration of DO in A"
        )),
        "{text}"
    );
    assert!(
        text.contains(&format!("gimbal.al:{p}:1: note: `P_O_DO> = 0.1*D2>` implies the other value")),
        "{text}"
    );
    assert!(text.contains(&format!("gimbal.al:{v}:1: note: `V_O_A> = 0>`")), "{text}");
    assert!(text.contains("% override"), "{text}");
    let errors: Vec<_> = report.diagnostics.iter().filter(|d| d.severity == Severity::Error).collect();
    assert_eq!(errors.len(), 1, "{text}");
}

#[test]
fn the_paper_files_check_without_errors_or_warnings() {
    for name in ["gimbal_gyroscope.al", "heavy_top.al", "free_body.al"] {
        let checked = lang::check(name, &model(name)).unwrap_or_else(|r| panic!("{r}"));
        assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings);
        assert!(checked.model.equations.is_some());
    }
}

#[test]
fn override_marker_accepts_the_offset_rotor() {
    let src = offset_gimbal().replace("A_DO_A> = 0>   ", "A_DO_A> = 0>   % override: rotor offset ignored ");
    let checked = lang::check("gimbal.al", &src).unwrap_or_else(|r| panic!("{r}"));
    assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings);
    // Any other comment does not.
    let src = offset_gimbal().replace("A_DO_A> = 0>   ", "A_DO_A> = 0>   % overridden? no ");
    assert!(lang::check("gimbal.al", &src).is_err());
}

const PENDULUM: &str = "NEWTONIAN N\nBODIES B\nPOINT O\nVARIABLES Q', U'\nCONSTANTS M, L, G\n\
    SIMPROT(N, B, 3, Q)\nQ' = U\nW_B_N> = U*N3>\nV_O_N> = 0>\nP_O_BO> = L*B1>\n\
    V2PTS(N, B, O, BO)\nMASS B = M\nINERTIA B, 0, 0, 0\nGRAVITY(-G*N2>)\n\
    ZERO = FR() + FRSTAR()\nKANE()\nINPUT M = 1, L = 1, G = 9.81\n";

#[test]
fn a_consistent_pendulum_checks() {
    let checked = lang::check("p.al", PENDULUM).unwrap_or_else(|r| panic!("{r}"));
    assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings);
}

#[test]
fn a_velocity_contradicting_the_positions_names_both_lines() {
    let src = PENDULUM.replace("V2PTS(N, B, O, BO)", "V_BO_N> = L*U*B1>");
    let text = lang::check("p.al", &src).err().expect("an error").to_string();
    assert!(
        text.contains("p.al:11:1: error: `V_BO_N> = L*U*B1>` contradicts the velocity of BO in N"),
        "{text}"
    );
    assert!(text.contains("p.al:10:1: note: `P_O_BO> = L*B1>`"), "{text}");
    assert!(text.contains("p.al:9:1: note: `V_O_N> = 0>`"), "{text}");
}

#[test]
fn an_angular_velocity_contradicting_the_orientation_names_both_lines() {
    let src = PENDULUM.replace("W_B_N> = U*N3>", "W_B_N> = 2*U*N3>");
    let text = lang::check("p.al", &src).err().expect("an error").to_string();
    assert!(
        text.contains("p.al:8:1: error: `W_B_N> = 2*U*N3>` contradicts the angular velocity of B in N"),
        "{text}"
    );
    assert!(text.contains("p.al:6:1: note: `SIMPROT(N, B, 3, Q)`"), "{text}");
}

/// The warnings of a file that loads and checks.
fn warnings(src: &str) -> String {
    let checked = lang::check("w.al", src).unwrap_or_else(|r| panic!("{r}"));
    assert!(checked.warnings.diagnostics.iter().all(|d| d.severity == Severity::Warning));
    checked.warnings.to_string()
}

#[test]
fn negative_masses_are_warnings_at_their_input_and_zero_is_massless() {
    let w = warnings(&PENDULUM.replace("INPUT M = 1,", "INPUT M = -2,"));
    assert!(w.contains("w.al:17:7: warning: implausible value of M: the mass of B is -2"), "{w}");
    let w = warnings(&PENDULUM.replace("INPUT M = 1,", "INPUT M = 0,"));
    assert!(!w.contains("implausible"), "a massless body is an idealisation, not an error: {w}");
}

#[test]
fn a_triangle_inequality_violation_is_a_warning_naming_the_moment() {
    let src = model("free_body.al").replace("INPUT I1 = 1, I2 = 2, I3 = 3", "INPUT I1 = 1, I2 = 1, I3 = 3");
    let line = line_of(&src, "INPUT I1");
    let w = warnings(&src);
    assert!(w.contains(&format!("w.al:{line}:23: warning: implausible value of I3:")), "{w}");
    assert!(w.contains("triangle inequality"), "{w}");
    assert_eq!(w.matches("warning").count(), 1, "{w}");
}

#[test]
fn non_unit_euler_parameters_are_a_warning() {
    let src = model("heavy_top.al").replace("E4 = 0.8660254037844386", "E4 = 0.9");
    let line = line_of(&src, "INPUT E1");
    let w = warnings(&src);
    assert!(
        w.contains(&format!("w.al:{line}:7: warning: implausible value of E1: the Euler parameters of R")),
        "{w}"
    );
    assert!(w.contains("E4 = 0.9"), "{w}");
    // Unit within 1e-9 is accepted.
    assert_eq!(warnings(&model("heavy_top.al").replace("E4 = 0.8660254037844386", "E4 = 0.86602540378")), "");
}

#[test]
fn the_kane_command_fails_on_a_contradiction_and_prints_warnings() {
    let dir = std::env::temp_dir().join(format!("kane-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("offset.al");
    std::fs::write(&bad, offset_gimbal()).unwrap();
    let (ok, _, err) = kane(&["check", bad.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("`A_DO_A> = 0>` contradicts") && err.contains("P_O_DO> = 0.1*D2>"), "{err}");
    let warn = dir.join("warn.al");
    std::fs::write(&warn, PENDULUM.replace("INPUT M = 1,", "INPUT M = -2,")).unwrap();
    let (ok, out, err) = kane(&["check", warn.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(out.contains(": ok: 1 coordinate ("), "{out}");
    assert!(err.contains("implausible value of M"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Deleting `Q2' = U2` from the gimbal used to check: Q2 silently became a generalized speed.
/// Now it is an error naming Q2 at the SIMPROT that turns C with it.
#[test]
fn a_coordinate_without_a_kinematic_equation_is_an_error() {
    let gimbal = model("gimbal_gyroscope.al");
    let src: String =
        gimbal.lines().filter(|l| !l.starts_with("Q2' = U2")).map(|l| format!("{l}\n")).collect();
    assert_eq!(src.lines().count() + 1, gimbal.lines().count());
    let report = match lang::check("gimbal.al", &src) {
        Err(r) => r,
        Ok(c) => panic!("checked without Q2' = U2: {:?}", c.model.equations.map(|e| e.speeds.len())),
    };
    let text = report.to_string();
    let line = line_of(&src, "SIMPROT(B, C, -1, Q2)");
    assert!(
        text.contains(&format!("gimbal.al:{line}:1: error: Q2 orients C but has no kinematic equation")),
        "{text}"
    );
    assert!(text.contains("add Q2' = <a speed> before KANE()"), "{text}");
    // A point placed by a variable without one is named too.
    let src = "NEWTONIAN N\nPOINTS O, P\nPARTICLES R\nVARIABLES X', U'\nCONSTANTS M\nP_O_R> = X*N1>\nV_O_N> = 0>\nV_R_N> = DT(P_O_R>)\nMASS R = M\nZERO = FR() + FRSTAR()\nKANE()\n";
    let text = match lang::check("slide.al", src) {
        Err(r) => r.to_string(),
        Ok(_) => panic!("checked without X' = U"),
    };
    assert!(text.contains("slide.al:6:1: error: X places R from O but has no kinematic equation"), "{text}");
}

/// A load line given twice adds up: a warning naming both lines.
#[test]
fn a_load_given_twice_is_a_warning_naming_both_lines() {
    let gimbal = model("gimbal_gyroscope.al");
    let torque = gimbal.lines().find(|l| l.starts_with("TORQUE_B>")).unwrap();
    let src = gimbal.replace(torque, &format!("{torque}\nTORQUE_B> = Y*A2>"));
    let first = line_of(&src, "TORQUE_B>");
    let checked = lang::check("gimbal.al", &src).unwrap_or_else(|r| panic!("{r}"));
    let text = checked.warnings.to_string();
    assert!(
        text.contains(&format!(
            "gimbal.al:{}:1: warning: TORQUE_B> is given on line {first} and again on line {} (the same load statement): the two add up",
            first + 1,
            first + 1
        )),
        "{text}"
    );
    assert!(text.contains(&format!("gimbal.al:{first}:1: note: TORQUE_B> first given here")), "{text}");
    // The same FORCE command twice, and a force assigned twice with different values.
    let base = "NEWTONIAN N\nPOINTS O\nPARTICLES P\nVARIABLES X', U'\nCONSTANTS M, F\nX' = U\nP_O_P> = X*N1>\nV_O_N> = 0>\nV_P_N> = DT(P_O_P>)\nMASS P = M\n";
    for (loads, what) in [
        ("FORCE(P, F*N1>)\nFORCE(P, F*N1>)\n", "the same load statement"),
        ("FORCE_P> = F*N1>\nFORCE_P> = 2*F*N1>\n", "a second assignment of the load"),
    ] {
        let src = format!("{base}{loads}ZERO = FR() + FRSTAR()\nKANE()\n");
        let text = lang::check("slide.al", &src).unwrap_or_else(|r| panic!("{r}")).warnings.to_string();
        assert!(
            text.contains(&format!(
                "slide.al:12:1: warning: FORCE_P> is given on line 11 and again on line 12 ({what})"
            )),
            "{text}"
        );
    }
    // Forces on two points, or a FORCE command adding a different force, are no warning.
    let src = format!("{base}FORCE(P, F*N1>)\nFORCE(P, M*N1>)\nZERO = FR() + FRSTAR()\nKANE()\n");
    assert!(lang::check("slide.al", &src).unwrap().warnings.diagnostics.is_empty());
}

/// A rod whose mass is written `mass` in MASS, with `inputs` in INPUT.
fn rod(mass: &str, inputs: &str) -> String {
    format!(
        "NEWTONIAN N\nBODIES PC\nCONSTANTS MC, L, G\nVARIABLES Q', U'\nMASS PC = {mass}\n\
         INERTIA PC, 0, MC*L^2/12, MC*L^2/12\nSIMPROT(N, PC, 3, Q)\nQ' = U\nPOINTS O\n\
         P_O_PCO> = L*PC1>\nV_O_N> = 0>\nV2PTS(N, PC, O, PCO)\nGRAVITY(-G*N2>)\n\
         ZERO = FR() + FRSTAR()\nKANE()\nINPUT {inputs}\n"
    )
}

#[test]
fn a_mass_declared_by_its_use_without_a_value_is_a_warning_naming_a_near_name() {
    // Autolev declares the names MASS and INERTIA use (`IC12` beside `IC11` is its idiom), so a
    // name near another is a possible misspelling said in a warning, never an error.
    let src = rod("MCC", "MC = 1, L = 1, G = 9.81");
    let checked = lang::check("typo.al", &src).expect("only a warning");
    let report = checked.warnings.render();
    assert!(report.contains("`MCC` (declared by its use here) has no INPUT value"), "{report}");
    assert!(report.contains("misspelling of `MC`") && report.contains("typo.al:5:11"), "{report}");
    // A mass declared by its use and given in INPUT is fine; without INPUT and with no near name,
    // a warning says runs will need it.
    assert!(lang::check("given.al", &rod("MROD", "MC = 1, L = 1, G = 9.81, MROD = 2")).is_ok());
    let checked = lang::check("open.al", &rod("MROD", "MC = 1, L = 1, G = 9.81")).expect("only a warning");
    let warnings = checked.warnings.render();
    assert!(warnings.contains("`MROD` (declared by its use here) has no INPUT value"), "{warnings}");
    assert!(checked.warnings.diagnostics.iter().all(|d| d.severity == Severity::Warning));
}

/// A planar chain of `n` point masses on massless rods, each link's angle relative to the last.
fn particle_chain(n: usize) -> String {
    let list = |f: &dyn Fn(usize) -> String| (1..=n).map(f).collect::<Vec<_>>().join(", ");
    let mut text = format!(
        "NEWTONIAN N\nFRAMES {}\nPOINTS O\nPARTICLES {}\nCONSTANTS L{{{n}}}, M{{{n}}}, G\nVARIABLES Q{{{n}}}', U{{{n}}}'\n",
        list(&|i| format!("F{i}")),
        list(&|i| format!("P{i}")),
    );
    for i in 1..=n {
        let parent = if i == 1 { "N".to_string() } else { format!("F{}", i - 1) };
        text.push_str(&format!("SIMPROT({parent}, F{i}, 3, Q{i})\nQ{i}' = U{i}\n"));
    }
    text.push_str("V_O_N> = 0>\n");
    for i in 1..=n {
        let from = if i == 1 { "O".to_string() } else { format!("P{}", i - 1) };
        text.push_str(&format!("P_{from}_P{i}> = L{i}*F{i}1>\nV2PTS(N, F{i}, {from}, P{i})\n"));
    }
    text.push_str(&format!("MASS {}\n", list(&|i| format!("P{i} = M{i}"))));
    text.push_str("GRAVITY(-G*N2>)\nZERO = FR() + FRSTAR()\nKANE()\n");
    text
}

#[test]
fn check_leaves_a_large_trees_mass_matrix_unformed_as_gen_does() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("check_large_tree");
    std::fs::create_dir_all(&dir).unwrap();
    let (small, large) = (dir.join("chain3.al"), dir.join("chain120.al"));
    std::fs::write(&small, particle_chain(3)).unwrap();
    std::fs::write(&large, particle_chain(120)).unwrap();
    let (ok, out, err) = kane(&["check", small.to_str().unwrap()]);
    assert!(ok && out.contains("M 3x3 in ") && out.contains("operations, f in"), "{out}{err}");
    let (ok, out, err) = kane(&["check", large.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(out.contains("120 speeds") && out.contains("M 120x120 not formed"), "{out}");
}
