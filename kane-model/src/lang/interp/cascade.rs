//! Follow-on errors: once a statement fails, a later failing statement that uses what it
//! mentions (a frame it would have oriented, a name it would have declared), or whose error
//! names it, fails because of that one mistake; its error is not reported.

use rustc_hash::FxHashSet;

use super::super::ast::{Stmt, StmtKind};
use super::super::parser::SESSION_COMMANDS;
use super::super::token::Span;

/// The names mentioned by statements that failed so far, upper-cased.
#[derive(Default)]
pub(crate) struct Tainted {
    names: FxHashSet<String>,
}

impl Tainted {
    /// Adds the names in `source[span]`.
    pub(crate) fn add(&mut self, source: &str, span: &Span) {
        let text = source.get(span.start..span.end.min(source.len())).unwrap_or("");
        self.names.extend(identifiers(text).map(|w| w.trim_end_matches('>').to_ascii_uppercase()));
    }

    /// Adds what the failed statement `s` would have set up: the names it declares, the name it
    /// assigns, or, for a command, MASS or INERTIA, every name it mentions. Units, INPUT,
    /// OUTPUT, CODE and session commands set up nothing later statements use.
    pub(crate) fn add_statement(&mut self, source: &str, s: &Stmt) {
        match &s.kind {
            StmtKind::Declare { items, .. } => {
                self.names.extend(items.iter().map(|i| i.name.to_ascii_uppercase()))
            }
            StmtKind::Assign { target, .. } => {
                self.names.insert(target.name.to_ascii_uppercase());
            }
            StmtKind::Expr(_) | StmtKind::Mass(_) | StmtKind::Inertia { .. } => self.add(source, &s.span),
            _ => {}
        }
    }

    /// Adds the names on the line of `source` that holds byte `at`, unless the line is one
    /// whose failure leaves nothing undefined (units, INPUT, OUTPUT, CODE, session commands).
    pub(crate) fn add_line_of(&mut self, source: &str, at: usize) {
        let at = at.min(source.len());
        let start = source[..at].rfind('\n').map_or(0, |i| i + 1);
        let end = source[at..].find('\n').map_or(source.len(), |i| at + i);
        let line = &source[start..end];
        let first = identifiers(line).next().unwrap_or("").trim_end_matches('>').to_ascii_uppercase();
        let sets_nothing = ["UNITS", "UNITSYSTEM", "INPUT", "OUTPUT", "CODE"].contains(&first.as_str())
            || SESSION_COMMANDS.contains(&first.as_str());
        let assigns = line[line.find(|c: char| c.is_ascii_alphabetic()).unwrap_or(0)..]
            .trim_start_matches(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == '>' || c == '\'')
            .trim_start()
            .starts_with('=');
        if assigns {
            self.names.insert(first);
        } else if !sets_nothing {
            self.add(source, &(start..end));
        }
    }

    /// True when `message` names something a failed statement mentioned: a word written with a
    /// capital or a digit (names; prose is lower-case) that is such a name, or is one followed
    /// by an axis digit (`C1>` of frame C), or joins such names with `_` (`P_O_BO>`).
    pub(crate) fn explains(&self, message: &str) -> bool {
        self.mentioned(
            identifiers(message).filter(|w| w.chars().any(|c| c.is_ascii_uppercase() || c.is_ascii_digit())),
        )
    }

    /// True when the statement at `source[span]` uses a name a failed statement mentioned
    /// (it fails because what it uses was never set up).
    pub(crate) fn explains_statement(&self, source: &str, span: &Span) -> bool {
        self.mentioned(identifiers(source.get(span.start..span.end.min(source.len())).unwrap_or("")))
    }

    fn mentioned<'a>(&self, mut words: impl Iterator<Item = &'a str>) -> bool {
        if self.names.is_empty() {
            return false;
        }
        words.any(|w| {
            let upper = w.to_ascii_uppercase();
            // `C1>`: a unit vector of frame C.
            let axis = upper.strip_suffix('>').map(|v| v.trim_end_matches(|c: char| c.is_ascii_digit()));
            let upper = upper.trim_end_matches('>');
            self.names.contains(upper)
                || axis.is_some_and(|frame| self.names.contains(frame))
                || upper.split('_').filter(|p| !p.is_empty()).any(|p| self.names.contains(p))
        })
    }
}

/// The identifiers in `text` (a letter, then letters, digits and `_`), a vector's with its `>`.
fn identifiers(text: &str) -> impl Iterator<Item = &str> {
    let mut out = Vec::new();
    let mut start = None;
    let bytes = text.as_bytes();
    for (i, c) in text.char_indices().chain(std::iter::once((text.len(), ' '))) {
        let inside = c.is_ascii_alphanumeric() || c == '_';
        match (start, inside) {
            (None, true) if c.is_ascii_alphabetic() => start = Some(i),
            (Some(s), false) => {
                let end = if bytes.get(i) == Some(&b'>') { i + 1 } else { i };
                out.push(&text[s..end]);
                start = None;
            }
            _ => {}
        }
    }
    out.into_iter()
}

#[cfg(test)]
mod tests {
    use super::Tainted;

    #[test]
    fn errors_naming_what_a_failed_statement_mentioned_are_follow_ons() {
        let src = "SIMPORT(N, B, 3, Q)\nFRAMES C D\n";
        let mut t = Tainted::default();
        assert!(!t.explains("no orientation path between frames B and N"));
        t.add(src, &(0..19));
        assert!(t.explains("no orientation path between frames B and N"));
        assert!(!t.explains("`C1>` is not defined"));
        t.add_line_of(src, 27);
        assert!(t.explains("`C1>` is not defined"), "a unit vector of frame C");
        assert!(t.explains("`P_O_D>` is not defined"));
        assert!(!t.explains("`E` is not a body"), "prose and other names are not");
        t.add_line_of("X = COS(Y) + BAD(Z)\n", 0);
        assert!(
            t.explains("`X` is not defined") && !t.explains("`Y` is not defined"),
            "an assignment sets its target only"
        );
        let later = "V2PTS(N, D, O, DO)";
        assert!(t.explains_statement(later, &(0..later.len())));
        assert!(!t.explains_statement("MASS E = M", &(0..10)));
    }
}
