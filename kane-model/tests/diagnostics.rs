//! Each class of mistake in a model file, with the message a user sees (insta snapshots).

use kane_model::lang;

fn rendered(src: &str) -> String {
    match lang::load("model.al", src) {
        Ok(_) => panic!("expected errors"),
        Err(report) => format!("{report}\n{}", report.render()),
    }
}

#[test]
fn undefined_name_suggests_the_nearest_known_name() {
    insta::assert_snapshot!(rendered("CONSTANTS MASS1, L\nE = MAS1*L\n"));
}

#[test]
fn scalar_where_a_vector_is_needed() {
    insta::assert_snapshot!(rendered("NEWTONIAN N\nPOINTS O, P\nCONSTANTS L\nP_O_P> = L\n"));
}

#[test]
fn orientation_loop() {
    insta::assert_snapshot!(rendered(
        "NEWTONIAN N\nFRAMES A, B\nVARIABLES Q1, Q2\nSIMPROT(N, A, 1, Q1)\nSIMPROT(A, B, 2, Q2)\nSIMPROT(B, N, 3, Q1)\n"
    ));
}

#[test]
fn point_with_no_path() {
    insta::assert_snapshot!(rendered("NEWTONIAN N\nPOINTS O, P\nV_O_N> = 0>\nV> = V_P_N>\n"));
}

#[test]
fn energy_check_without_speeds() {
    insta::assert_snapshot!(rendered("VARIABLES X\nE = NICHECK()\n"));
}

#[test]
fn syntax_errors_are_all_reported() {
    insta::assert_snapshot!(rendered("CONSTANTS A, B\nE = (A + \nF = A B\nG = A $ B\n"));
}

#[test]
fn several_errors_in_one_run() {
    let src = "NEWTONIAN N\nBODIES B\nMASS C = 1\nE = ZZ + 1\nKANE()\n";
    let report = lang::load("m.al", src).err().expect("errors");
    let text = report.to_string();
    assert!(text.contains("m.al:3:6: error: `C` is not a body or particle"), "{text}");
    assert!(text.contains("m.al:4:5: error: `ZZ` is not defined"), "{text}");
    assert!(text.contains("m.al:5:1: error: no generalized speeds"), "{text}");
}
