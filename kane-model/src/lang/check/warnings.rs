//! Implausible INPUT values as warnings: [`crate::plausibility`] at the INPUT values, each
//! placed at the INPUT item of the parameter it blames.
//!
//! In: a loaded model. Out: warnings naming the parameter, at its INPUT line (or at the MASS or
//! INERTIA statement when no INPUT gives a value).

use crate::plausibility::plausibility;

use super::super::diagnostic::Diagnostic;
use super::super::interp::LoadedModel;
use super::super::token::Span;

/// Warnings for the implausible INPUT values of `m`.
pub(crate) fn input_warnings(m: &LoadedModel) -> Vec<Diagnostic> {
    let issues = plausibility(&m.model, |n| m.input(n));
    issues
        .into_iter()
        .map(|issue| {
            let span = std::iter::once(&issue.parameter)
                .chain(&issue.involved)
                .find_map(|n| input_span(m, n))
                .or_else(|| m.sources.inertial.get(&issue.parameter.to_ascii_uppercase()).cloned())
                .unwrap_or(0..0);
            Diagnostic::warning(span, format!("implausible value of {}: {}", issue.parameter, issue.message))
        })
        .collect()
}

/// The last INPUT item giving `name` a value.
fn input_span(m: &LoadedModel, name: &str) -> Option<Span> {
    m.inputs.iter().rev().find(|i| i.name.eq_ignore_ascii_case(name)).map(|i| i.span.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_sits_at_the_input_or_else_at_the_mass_statement() {
        let src = "NEWTONIAN N\nBODIES B\nCONSTANTS M\nMASS B = M\nINPUT M = -1\n";
        let m = crate::lang::load("t.al", src).unwrap();
        let w = input_warnings(&m);
        assert_eq!(w.len(), 1);
        assert_eq!(&src[w[0].span.clone()], "M = -1");
        let src = "NEWTONIAN N\nBODIES B\nMASS B = -1\n";
        let m = crate::lang::load("t.al", src).unwrap();
        let w = input_warnings(&m);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].message.starts_with("implausible value of B: the mass of B is -1"), "{}", w[0].message);
        assert_eq!(super::super::super::line_column(src, w[0].span.start).0, 3);
    }
}
