//! Generated code: deterministic, formatted, and pinned by a snapshot.

fn gimbal_source() -> String {
    let src = include_str!("../models/gimbal_gyroscope.al");
    let loaded = kane_model::lang::load("gimbal_gyroscope.al", src).unwrap();
    let mut spec = loaded.into_spec("gimbal_gyroscope").unwrap();
    let emitted = kane_model::codegen::generate(&mut spec, &Default::default()).unwrap();
    kane_model::codegen::to_source(&emitted).unwrap()
}

#[test]
fn the_same_model_gives_byte_identical_code() {
    assert_eq!(gimbal_source(), gimbal_source());
}

#[test]
fn generated_gimbal_module_snapshot() {
    insta::assert_snapshot!(gimbal_source());
}

#[test]
fn a_model_without_kane_is_refused() {
    let loaded = kane_model::lang::load("m.al", "NEWTONIAN N\nCONSTANTS A\n").unwrap();
    let err = loaded.into_spec("m").err().unwrap();
    assert_eq!(
        err.to_string(),
        "the model derives no equations: form them in the model file (ZERO = FR() + FRSTAR(), then KANE())"
    );
}

#[test]
fn build_script_form_writes_an_includable_module() {
    let out = std::env::temp_dir().join(format!("kane-build-{}.rs", std::process::id()));
    kane_model::generate::build_script("models/gimbal_gyroscope.al", &out, &Default::default()).unwrap();
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(!text.starts_with("//!"), "an include!d file must not open with an inner doc comment");
    assert!(text.contains("pub fn rhs<T: ::kane_model::__private::num_traits::Float>"), "{}", &text[..200]);
    syn::parse_file(&text).unwrap();
    std::fs::remove_file(&out).ok();
}
