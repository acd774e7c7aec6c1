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
fn a_model_without_dynamics_generates_its_encoded_quantities_from_inputs() {
    let src = "NEWTONIAN N\nFRAMES A\nVARIABLES Q'\nCONSTANTS L\nSIMPROT(N, A, 3, Q)\n\
               X = L*COS(Q)\nENCODE X\nCODE ALGEBRAIC() x.c\n";
    let loaded = kane_model::lang::load("m.al", src).unwrap();
    let mut spec = loaded.into_spec("m").unwrap();
    assert!(spec.states().is_empty());
    let emitted = kane_model::codegen::generate(&mut spec, &Default::default()).unwrap();
    let text = kane_model::codegen::to_source(&emitted).unwrap();
    syn::parse_file(&text).unwrap();
    assert!(
        text.contains("pub const N_STATES: usize = 0usize;")
            && text.contains("pub const N_OUTPUTS: usize = 1usize;"),
        "{}",
        &text[..text.len().min(3000)]
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
