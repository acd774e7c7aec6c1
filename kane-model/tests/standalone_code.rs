//! The standalone programs `kane code` writes: their text for a pendulum and for a linear and a
//! nonlinear system (snapshots), the names CODE statements may give, and what a program is
//! refused for.

use std::path::Path;

use kane_model::generate::{CodeFile, StandaloneFile};
use kane_model::standalone::{Language, StandaloneError};

const PENDULUM: &str = "NEWTONIAN N\nBODIES A\nVARIABLES Q', U'\nCONSTANTS L, M, G\nSPECIFIED TQ\n\
    SIMPROT(N, A, 3, Q)\nQ' = U\nW_A_N> = U*N3>\nP_NO_AO> = -L*A2>\nMASS A = M\n\
    INERTIA A, 0, 0, M*L^2/12\nGRAVITY(-G*N2>)\nTORQUE_A> = TQ*N3>\nZERO = FR() + FRSTAR()\nKANE()\n\
    UNITS Q = DEG, U = RAD/SEC\nINPUT L = 1, M = 1, G = 9.81, Q = 30, U = 0\n\
    INPUT TFINAL = 2, INTEGSTP = 0.1\nOUTPUT Q, U\nCODE DYNAMICS() swing.m\n";

fn pendulum() -> StandaloneFile {
    StandaloneFile::load(Path::new("pendulum.al"), PENDULUM).unwrap()
}

#[test]
fn the_pendulum_program_in_c() {
    insta::assert_snapshot!(pendulum().program(Language::C, "swing").unwrap());
}

#[test]
fn the_pendulum_program_in_matlab() {
    insta::assert_snapshot!(pendulum().program(Language::Matlab, "swing").unwrap());
}

#[test]
fn the_pendulum_program_in_fortran() {
    insta::assert_snapshot!(pendulum().program(Language::Fortran, "swing").unwrap());
}

#[test]
fn the_pendulum_program_in_python() {
    insta::assert_snapshot!(pendulum().program(Language::Python, "swing").unwrap());
}

const SYSTEMS: &str = "CONSTANTS A, B, R\nVARIABLES X, Y\nEQN[1] = A*X + B*Y - R\nEQN[2] = X - Y\n\
    NL[1] = A*X^3 + B*Y^2 - R\nNL[2] = A*SIN(X)^2 + B*COS(2*Y) - R^2\n\
    INPUT A = 2, B = 3, R = 1, X = 30 DEG, Y = 3.14\n\
    CODE ALGEBRAIC(EQN, X, Y) lin.c\nCODE NONLINEAR(NL, X, Y) nl.c\n";

fn system_program(i: usize, language: Language) -> String {
    let code = CodeFile::load(Path::new("systems.al"), SYSTEMS).unwrap();
    code.system_program(i, language, "solve").unwrap().unwrap()
}

#[test]
fn the_linear_system_program_in_c() {
    insta::assert_snapshot!(system_program(0, Language::C));
}

#[test]
fn the_nonlinear_system_program_in_every_language() {
    for language in Language::ALL {
        insta::assert_snapshot!(format!("nonlinear_{}", language.extension()), system_program(1, language));
    }
}

#[test]
fn the_outputs_program_evaluates_once_and_says_so() {
    let c = pendulum().outputs_program(Language::C, "at_start").unwrap();
    assert!(c.contains("evaluates them once") && c.contains("T_FINAL = 0.0"), "{c}");
}

#[test]
fn a_file_without_equations_of_motion_writes_no_dynamics_program() {
    let file = StandaloneFile::load(Path::new("systems.al"), SYSTEMS).unwrap();
    let refused = file.outputs_program(Language::C, "x");
    assert!(matches!(refused, Err(StandaloneError::NoDynamics)), "{refused:?}");
}

#[test]
fn languages_come_from_extensions_in_any_case() {
    assert_eq!(Language::of_file("PHASE3.M"), Some(Language::Matlab));
    assert_eq!(Language::of_file("out.C"), Some(Language::C));
    assert_eq!(Language::of_file("run.py"), Some(Language::Python));
    assert_eq!(Language::of_file("x.f90"), Some(Language::Fortran));
    assert_eq!(Language::of_file("X.FOR"), Some(Language::Fortran));
    assert_eq!(Language::of_file("x.jl"), None);
    assert_eq!(Language::of_file("noextension"), None);
    assert_eq!(Language::named("Octave"), Some(Language::Matlab));
}

#[test]
fn the_code_request_and_the_open_input_are_kept() {
    let code = CodeFile::load(Path::new("pendulum.al"), PENDULUM).unwrap();
    assert_eq!(code.requests.len(), 1);
    assert_eq!(code.requests[0].file, "swing.m");
    assert!(code.system_program(0, Language::C, "swing").is_none(), "CODE DYNAMICS() has no system");
    let c = pendulum().program(Language::C, "swing").unwrap();
    assert!(c.contains("OPEN_INPUTS = \"TQ\""), "the open input is named for the warning");
}

#[test]
fn a_matlab_program_needs_a_function_name_not_one_of_its_own_functions() {
    let e = pendulum().program(Language::Matlab, "my-swing").unwrap_err();
    assert!(matches!(e, StandaloneError::FileName(..)), "{e}");
    let e = pendulum().program(Language::Matlab, "rhs").unwrap_err();
    assert!(e.to_string().contains("the program's own functions"), "{e}");
    assert!(pendulum().program(Language::Matlab, "Rhs").is_ok(), "MATLAB's names are case-sensitive");
}

#[test]
fn a_quaternion_output_is_refused_with_the_way_on() {
    // Only built-in models have quaternion outputs: the heavy top's `Q`.
    let mut spec = kane_model::models::builtin_spec("heavy_top_rust").unwrap().unwrap();
    let model = kane_model::program::ProgramModel::new(&mut spec).unwrap();
    let run = kane_model::lang::FileRun { outputs: vec!["Q".into()], ..Default::default() };
    let e = kane_model::standalone::Plan::new(&model, &run).err().expect("refused");
    assert!(matches!(e, StandaloneError::Quaternion(ref name) if name == "Q"), "{e}");
    assert!(e.to_string().contains("direction cosines"), "{e}");
}

#[test]
fn a_forty_link_chain_s_c_rhs_is_one_statement_per_operation_of_the_program() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gyro-sim/tests/data/chain40_rigid.al");
    let file = StandaloneFile::load(&path, &std::fs::read_to_string(&path).unwrap()).unwrap();
    let c = file.program(Language::C, "chain").unwrap();
    let body = c.split("_rhs(double t").nth(1).unwrap().split("\n}\n").next().unwrap();
    let statements = body.lines().filter(|l| l.trim_start().starts_with("const double ")).count();
    let operations = file.model.program().op_counts().rhs;
    // Each statement is one operation of the program; values no result reads are left out.
    assert!(statements <= operations, "{statements} statements for {operations} operations");
    assert!(statements * 2 >= operations, "{statements} statements for {operations} operations");
    eprintln!("40-link chain: {statements} C statements, {operations} lowered operations");
}

#[test]
fn the_fmu_declares_si_units_with_the_file_s_units_for_display() {
    let text = pendulum().fmu().unwrap();
    let md = &text.model_description;
    let q = md.split("name=\"Q\"").nth(1).unwrap().split("</ScalarVariable>").next().unwrap();
    assert!(q.contains("unit=\"rad\" displayUnit=\"DEG\""), "{q}");
    assert!(md.contains("<DisplayUnit name=\"DEG\" factor=\"57.29577951308232\"/>"), "{md}");
    let tq = md.split("name=\"TQ\"").nth(1).unwrap().split("</ScalarVariable>").next().unwrap();
    assert!(tq.contains("causality=\"input\""), "the open SPECIFIED input is an FMU input: {tq}");
    assert!(text.source.contains(&format!(
        "strcmp(guid, \"{}\")",
        md.split("guid=\"").nth(1).unwrap().split('"').next().unwrap()
    )));
}

#[test]
fn an_output_on_two_output_lines_is_computed_once() {
    let text = PENDULUM.replace("OUTPUT Q, U\n", "X = L*SIN(Q)\nOUTPUT Q, X\nOUTPUT X, U\n");
    let program = StandaloneFile::load(Path::new("pendulum.al"), &text).unwrap();
    let fortran = program.program(Language::Fortran, "swing").unwrap();
    let assigned: Vec<&str> = fortran
        .lines()
        .filter_map(|l| l.trim().split_once(" = ").map(|(name, _)| name))
        .filter(|name| name.starts_with('o') && name.contains('_'))
        .collect();
    assert!(!assigned.is_empty(), "the output's temporaries are named o{{k}}_{{i}}:\n{fortran}");
    let mut unique = assigned.clone();
    unique.sort_unstable();
    unique.dedup();
    assert_eq!(unique.len(), assigned.len(), "each temporary assigned once:\n{fortran}");
    assert!(fortran.contains("x,x"), "both columns written:\n{fortran}");
}
