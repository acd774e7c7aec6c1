//! Generated abuse of the parser: deep nesting is refused with a located error, not a
//! stack overflow; long flat sums load (they are balanced trees, evaluated without deep
//! recursion). These run on test threads, whose stacks are smaller than the main thread's.

use kane_model::lang;

/// The text of `load`'s errors (panics if the file loads).
fn errors(src: &str) -> String {
    match lang::load("deep.al", src) {
        Ok(_) => panic!("expected an error"),
        Err(report) => report.to_string(),
    }
}

#[test]
fn ten_thousand_nested_parentheses_are_refused_at_their_place() {
    let src = format!("CONSTANTS K\nX = {}K{}\n", "(".repeat(10_000), ")".repeat(10_000));
    let e = errors(&src);
    // "X = " is four columns; the 257th parenthesis is the first too deep.
    assert!(
        e.starts_with("deep.al:2:261: error: this expression is nested more than 256 levels deep"),
        "{e}"
    );
    assert!(e.contains("help:") && e.contains("assignments of their own"), "{e}");
}

#[test]
fn deep_signs_calls_brackets_and_products_are_refused_too() {
    for (what, body) in [
        ("signs", format!("{}K", "-".repeat(10_000))),
        ("calls", format!("{}K{}", "SIN(".repeat(5_000), ")".repeat(5_000))),
        ("brackets", format!("{}K{}", "[".repeat(5_000), "]".repeat(5_000))),
        ("powers", format!("K{}", "^K".repeat(10_000))),
        ("products", vec!["K"; 20_000].join("*")),
    ] {
        let e = errors(&format!("CONSTANTS K\nX = {body}\n"));
        assert!(e.starts_with("deep.al:2:") && e.contains("nested more than 256 levels deep"), "{what}: {e}");
    }
}

#[test]
fn nesting_within_the_limit_loads() {
    let src = format!(
        "CONSTANTS K\nX = {}K{}\nY = {}K{}\n",
        "(".repeat(250),
        ")".repeat(250),
        "SIN(".repeat(200),
        ")".repeat(200)
    );
    assert!(lang::load("deep.al", &src).is_ok());
}

#[test]
fn a_twenty_thousand_term_sum_loads() {
    let terms: Vec<String> =
        (0..20_000).map(|i| format!("{}K{}", if i % 3 == 2 { "-" } else { "+" }, i % 7 + 1)).collect();
    let src = format!("CONSTANTS K{{1:7}}\nX = {}\n", terms.concat());
    assert!(lang::load("sum.al", &src).is_ok());
}

/// A 20,000-term torque through Kane's method: derived, checked and its equations built.
#[test]
fn a_model_with_a_twenty_thousand_term_load_derives() {
    let gimbal = include_str!("../models/gimbal_gyroscope.al");
    let terms: Vec<String> = (1..=20_000).map(|i| format!("Y*Q1^{i}")).collect();
    let src = gimbal.replace("TORQUE_B> = Y*A2>", &format!("TORQUE_B> = ({})*A2>", terms.join("+")));
    assert_ne!(src, gimbal);
    let loaded = lang::load("gimbal_sum.al", &src).unwrap();
    assert_eq!(loaded.equations.unwrap().speeds.len(), 3);
}
