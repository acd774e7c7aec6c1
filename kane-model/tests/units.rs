//! Units in model files: an unknown unit in UNITS, INPUT or OUTPUT is an error at its
//! place naming it, with the nearest known unit and the list of known ones; unit expressions
//! keep their grouping.

use kane_model::lang;

const GIMBAL: &str = include_str!("../models/gimbal_gyroscope.al");

fn errors(src: &str) -> String {
    match lang::load("units.al", src) {
        Ok(_) => panic!("expected an error"),
        Err(report) => report.to_string(),
    }
}

fn line_of(src: &str, start: &str) -> usize {
    src.lines().position(|l| l.starts_with(start)).expect("line present") + 1
}

#[test]
fn unknown_units_in_the_gimbal_are_named_with_the_known_ones() {
    let src = GIMBAL.replace("UNITS Q1 = DEG,", "UNITS Q1 = DGE,").replace("T = SEC,", "T = SCE,");
    let e = errors(&src);
    let (time, angle) = (line_of(&src, "UNITS M1"), line_of(&src, "UNITS Q1"));
    assert!(e.contains(&format!("units.al:{time}:38: error: unknown unit `SCE`")), "{e}");
    assert!(e.contains(&format!("units.al:{angle}:12: error: unknown unit `DGE`")), "{e}");
    assert!(e.contains("did you mean `SEC`?") && e.contains("did you mean `DEG`?"), "{e}");
    assert!(e.contains("known units: M, CM, MM") && e.contains("RAD, DEG"), "{e}");
}

#[test]
fn units_of_input_and_output_and_inside_expressions_are_checked() {
    let e = errors("CONSTANTS K\nINPUT K = 3 DGE\n");
    assert!(e.starts_with("units.al:2:7: error: unknown unit `DGE`"), "{e}");
    let e = errors("CONSTANTS K\nOUTPUT K FOO\n");
    assert!(e.starts_with("units.al:2:8: error: unknown unit `FOO`"), "{e}");
    let e = errors("CONSTANTS K\nUNITS K = N*MM/SCE^2\n");
    assert!(e.starts_with("units.al:2:16: error: unknown unit `SCE`"), "{e}");
    let e = errors("CONSTANTS K\nUNITS K = N + M\n");
    assert!(e.starts_with("units.al:2:11: error: this is not a unit"), "{e}");
}

#[test]
fn known_units_load_with_their_grouping() {
    let loaded =
        lang::load("units.al", "CONSTANTS A, B, C\nUNITS A = n*m, B = M/(SEC*SEC), C = RAD/SEC^2\n").unwrap();
    let units = loaded.units;
    assert_eq!(units["A"], "N*M");
    assert_eq!(units["B"], "M/(SEC*SEC)");
    assert_eq!(units["C"], "RAD/SEC^2");
    assert!(lang::load("gimbal.al", GIMBAL).is_ok());
}

/// `kane check`'s errors for `src`.
fn check_errors(src: &str) -> String {
    match lang::check("units.al", src) {
        Ok(_) => panic!("expected an error"),
        Err(report) => report.to_string(),
    }
}

#[test]
fn a_unit_of_another_dimension_than_the_quantitys_use_is_an_error() {
    // L places the rotor's points: a length, not a mass.
    let src = GIMBAL.replace("UNITS L = M", "UNITS L = KG");
    assert_ne!(src, GIMBAL, "the gimbal gives L its unit");
    let e = check_errors(&src);
    assert!(e.contains("error: `L` is a length (it places point"), "{e}");
    assert!(e.contains("its unit KG is not a length"), "{e}");
    let line = line_of(&src, "UNITS L");
    assert!(e.contains(&format!("units.al:{line}:")), "{e}");
    // A mass given in metres, by its INPUT tag.
    let particle = "NEWTONIAN N\nPARTICLES P\nPOINTS O\nCONSTANTS M, R\nV_O_N> = 0>\nP_O_P> = R*N1>\nMASS P = M\nINPUT M = 2 M, R = 0.5 M\n";
    let e = check_errors(particle);
    assert!(e.contains("units.al:8:7: error: `M` is the mass of P, but its unit M is not a mass"), "{e}");
    // The right units pass.
    assert!(lang::check("units.al", &particle.replace("M = 2 M", "M = 2 KG")).is_ok());
    assert!(lang::check("units.al", GIMBAL).is_ok());
}

#[test]
fn inertias_forces_torques_and_angles_are_checked_against_their_units() {
    let base = "NEWTONIAN N\nBODIES B\nPOINTS O\nCONSTANTS M, IB, F, T, L\nVARIABLES Q'\nMOTIONVARIABLES' U'\n\
                Q' = U\nSIMPROT(N, B, 3, Q)\nW_B_N> = U*N3>\nP_O_BO> = L*B1>\nV_O_N> = 0>\nMASS B = M\n\
                INERTIA B, IB, IB, 2*IB\nFORCE_BO> = F*N1>\nTORQUE_B> = T*N3>\nUNITS M = KG, L = M, IB = KG*M^2, F = N, T = N*M, Q = RAD\nKANE()\n";
    lang::check("units.al", base).unwrap_or_else(|r| panic!("{r}"));
    let cases = [
        (
            "IB = KG*M^2",
            "IB = KG*M",
            "`IB` is a moment of inertia (of B), but its unit KG*M is not a moment of inertia",
        ),
        ("F = N", "F = N*M", "`F` is a force (on point BO), but its unit N*M is not a force"),
        ("T = N*M", "T = N", "`T` is a torque (on B), but its unit N is not a torque"),
        ("Q = RAD", "Q = M", "`Q` is an angle (it rotates B), but its unit M is not an angle"),
    ];
    for (good, bad, said) in cases {
        let e = check_errors(&base.replace(good, bad));
        assert!(e.contains(said), "{bad}: {e}");
        let line = line_of(base, "UNITS");
        assert!(e.contains(&format!("units.al:{line}:")), "{e}");
    }
    // Loads are known to a file that forms its equations; degrees and plain numbers are angles too.
    for angle in ["Q = DEG", "Q = 1"] {
        let src = base.replace("Q = RAD", angle);
        assert!(lang::check("units.al", &src).is_ok(), "{angle}");
    }
}
