//! Rust names for model symbols.

use proc_macro2::{Ident, Span};

const KEYWORDS: &[&str] = &[
    "as", "break", "const", "continue", "crate", "else", "enum", "extern", "false", "fn", "for", "if",
    "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return", "self", "static",
    "struct", "super", "trait", "true", "type", "unsafe", "use", "where", "while", "async", "await", "dyn",
    "abstract", "become", "box", "do", "final", "macro", "override", "priv", "typeof", "unsized", "virtual",
    "yield", "try", "t", "y", "dy", "p", "out",
];

/// A lower-case Rust identifier for a symbol: `Q1'` -> `q1_d`, `U2''` -> `u2_dd`. Never starts
/// with `_`, so it cannot meet the generated locals (`__x0`, `__m0_1`, ...).
pub fn rust_ident(name: &str) -> Ident {
    let primes = name.chars().rev().take_while(|c| *c == '\'').count();
    let base = name.trim_end_matches('\'');
    let mut s: String =
        base.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect();
    if primes > 0 {
        s.push('_');
        s.push_str(&"d".repeat(primes));
    }
    if s.is_empty() || !s.starts_with(|c: char| c.is_ascii_alphabetic()) {
        s.insert_str(0, "v_");
    }
    if KEYWORDS.contains(&s.as_str()) {
        s.push('_');
    }
    Ident::new(&s, Span::call_site())
}

/// An upper-case constant name for a state index: `q1` -> `Q1`.
pub fn const_ident(name: &str) -> Ident {
    let id = rust_ident(name).to_string().to_ascii_uppercase();
    Ident::new(&id, Span::call_site())
}
