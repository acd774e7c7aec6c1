//! Loads given twice: a second `TORQUE_B> = ...` (or `FORCE_P> = ...`) adds to the first, and
//! the same FORCE or TORQUE statement written twice doubles the load; both are warnings naming
//! the two lines, since a copied line silently doubling a torque looks like a different model.
//!
//! In: a loaded model and its source. Out: a warning at each repeated load, with a note at the
//! line it repeats.

use super::super::diagnostic::{line_column, Diagnostic};
use super::super::interp::{LoadSource, LoadedModel};
use super::marker::statement_text;

/// Warnings for loads given again.
pub(crate) fn repeated_loads(m: &LoadedModel, source: &str) -> Vec<Diagnostic> {
    let loads = &m.sources.loads;
    let mut out = Vec::new();
    for (k, later) in loads.iter().enumerate() {
        let Some(first) = loads[..k].iter().find(|earlier| repeats(earlier, later, source)) else { continue };
        let (line, _) = line_column(source, first.span.start);
        let (again, _) = line_column(source, later.span.start);
        let what = if statement_text(source, &first.span) == statement_text(source, &later.span) {
            "the same load statement"
        } else {
            "a second assignment of the load"
        };
        out.push(
            Diagnostic::warning(
                later.span.clone(),
                format!("{} is given on line {line} and again on line {again} ({what}): the two add up", later.name),
            )
            .with_note(first.span.clone(), format!("{} first given here", later.name))
            .with_help(format!(
                "delete line {again} if it is a copy; to give {} as a sum of loads, write it once as that sum",
                later.name
            )),
        );
    }
    out
}

/// Whether `later` repeats `earlier`: the same load assigned twice, or the same statement.
fn repeats(earlier: &LoadSource, later: &LoadSource, source: &str) -> bool {
    earlier.name.eq_ignore_ascii_case(&later.name)
        && ((earlier.assigned && later.assigned)
            || statement_text(source, &earlier.span) == statement_text(source, &later.span))
}
