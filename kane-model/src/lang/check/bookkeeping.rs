//! The summary line of a file's bookkeeping commands: which were applied (UNITSYSTEM) and
//! which ignored (they change only Autolev's own printing, saving and pausing).

use super::super::diagnostic::line_column;
use super::super::interp::LoadedModel;

/// `applied: UNITSYSTEM (line 2); ignored (Autolev's session only): AUTOZ (line 8), ...`, or
/// `None` when the file has no bookkeeping commands.
pub fn bookkeeping_summary(model: &LoadedModel, source: &str) -> Option<String> {
    let list = |applied: bool| {
        let items: Vec<String> = model
            .bookkeeping
            .iter()
            .filter(|b| b.applied == applied)
            .map(|b| format!("{} (line {})", b.command, line_column(source, b.span.start).0))
            .collect();
        items.join(", ")
    };
    let mut parts = Vec::new();
    let applied = list(true);
    if !applied.is_empty() {
        parts.push(format!("applied: {applied}"));
    }
    let ignored = list(false);
    if !ignored.is_empty() {
        parts
            .push(format!("ignored (they change only Autolev's own printing, saving or pausing): {ignored}"));
    }
    let code = |solved: bool| -> Vec<String> {
        model
            .code
            .iter()
            .filter(|c| c.system.is_some() == solved)
            .map(|c| format!("CODE {} (line {}) {}", c.kind, line_column(source, c.span.start).0, c.file))
            .collect()
    };
    let (solved, other) = (code(true), code(false));
    if !solved.is_empty() {
        parts.push(format!("solved numerically by `kane solve` (no file written): {}", solved.join(", ")));
    }
    if !other.is_empty() {
        parts.push(format!(
            "not written (`kane gen` writes the equations of motion as Rust): {}",
            other.join(", ")
        ));
    }
    (!parts.is_empty()).then(|| parts.join("; "))
}

#[cfg(test)]
mod tests {
    use super::bookkeeping_summary;

    #[test]
    fn applied_and_ignored_commands_are_listed_with_their_lines() {
        let src = "UNITSYSTEM KG, METER, SEC\nAUTOZ ON\nCONSTANTS M;\nENCODE M\nPAUSE\n";
        let m = crate::lang::load("b.al", src).unwrap();
        assert_eq!(
            bookkeeping_summary(&m, src).unwrap(),
            "applied: UNITSYSTEM (line 1); ignored (they change only Autolev's own printing, saving or \
             pausing): AUTOZ (line 2), PAUSE (line 5)"
        );
        let code = "CONSTANTS M\nE = M\nCODE ALGEBRAIC(E, M) a.c\n";
        let with_code = crate::lang::load("c.al", code).unwrap();
        assert_eq!(
            bookkeeping_summary(&with_code, code).unwrap(),
            "solved numerically by `kane solve` (no file written): CODE ALGEBRAIC (line 3) a.c"
        );
        let plain = crate::lang::load("p.al", "CONSTANTS M\n").unwrap();
        assert_eq!(bookkeeping_summary(&plain, "CONSTANTS M\n"), None);
    }
}
