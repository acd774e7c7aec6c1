//! Constants a file declares only by using them in MASS or INERTIA (`MASS A = MA`, as Autolev
//! allows): one that no INPUT gives a value is a warning that runs need one, with the declared
//! name one edit away (two for names of six letters or more) as a possible misspelling
//! (`MASS PC = MCC` beside `CONSTANTS MC`); systematic names (`IC12` beside `IC11`) are Autolev's
//! idiom, so never an error. In: a loaded model. Out: the warnings.

use crate::expr::SymbolKind;

use super::super::diagnostic::Diagnostic;
use super::super::interp::{edit_distance, LoadedModel};

/// Diagnostics for the implicit constants without an INPUT value.
pub(crate) fn implicit_constants_without_values(m: &LoadedModel) -> Vec<Diagnostic> {
    let implicit = &m.sources.implicit_constants;
    let declared: Vec<String> = m
        .model
        .ar
        .symbols()
        .filter(|(_, info)| matches!(info.kind, SymbolKind::Constant))
        .map(|(_, info)| info.name.clone())
        .filter(|n| !implicit.iter().any(|(i, _)| i.eq_ignore_ascii_case(n)))
        .collect();
    let mut out = Vec::new();
    for (name, span) in implicit {
        if m.inputs.iter().any(|i| i.name.eq_ignore_ascii_case(name)) {
            continue;
        }
        let upper = name.to_ascii_uppercase();
        let near = declared
            .iter()
            .map(|d| (edit_distance(&upper, &d.to_ascii_uppercase()), d))
            // Short names are close to many others (M1 and C1): only a near miss of a longer one.
            .filter(|(k, _)| (*k == 1 && upper.len() >= 3) || (*k == 2 && upper.len() >= 6))
            .min_by_key(|(k, _)| *k);
        let warning = Diagnostic::warning(
            span.clone(),
            format!(
                "`{name}` (declared by its use here) has no INPUT value: runs need one (--set {name}=VALUE)"
            ),
        );
        out.push(match near {
            Some((_, d)) => warning.with_help(format!(
                "if it is not a misspelling of `{d}`, give it a value in INPUT (Autolev declares names MASS and INERTIA use)"
            )),
            None => warning,
        });
    }
    out
}
