//! The override marker: a trailing comment `% override` on an assignment's line accepts a
//! velocity, acceleration or angular velocity that contradicts the kinematics on purpose.
//!
//! In: the source and a span. Out: whether the span's line carries the marker.

use super::super::token::Span;

/// The word a comment starts with to mark a deliberate override.
pub const MARKER: &str = "override";

/// True when the line holding `span` ends in a comment starting with `override`
/// (case-insensitive), e.g. `A_DO_A> = 0>   % override: the offset is ignored on purpose`.
pub(crate) fn is_override(source: &str, span: &Span) -> bool {
    let line = line_at(source, span.start);
    let Some((_, comment)) = line.split_once('%') else { return false };
    let word = comment.trim_start();
    word.len() >= MARKER.len()
        && word[..MARKER.len()].eq_ignore_ascii_case(MARKER)
        && !word[MARKER.len()..].starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
}

/// The line holding byte `offset`, without its newline.
pub(crate) fn line_at(source: &str, offset: usize) -> &str {
    let offset = offset.min(source.len());
    let start = source[..offset].rfind('\n').map_or(0, |i| i + 1);
    let end = source[offset..].find('\n').map_or(source.len(), |i| offset + i);
    &source[start..end]
}

/// The statement on the line holding `span`, without its comment.
pub(crate) fn statement_text<'a>(source: &'a str, span: &Span) -> &'a str {
    let line = line_at(source, span.start);
    line.split_once('%').map_or(line, |(code, _)| code).trim()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_marker_is_a_trailing_comment_word() {
        let src = "A_DO_A> = 0>   % Override: on purpose\nV_O_A> = 0> % 22\nW> = 0> % overrides\n";
        assert!(is_override(src, &(0..7)));
        assert!(is_override(src, &(3..4)));
        let second = src.find("V_O").unwrap();
        assert!(!is_override(src, &(second..second + 5)));
        let third = src.find("W>").unwrap();
        assert!(!is_override(src, &(third..third + 2)));
        assert!(!is_override("A_DO_A> = 0>", &(0..7)));
    }

    #[test]
    fn statement_text_drops_the_comment() {
        let src = "X = 1\nP_O_DO> = 0.1*D2>   % added\n";
        assert_eq!(statement_text(src, &(8..9)), "P_O_DO> = 0.1*D2>");
        assert_eq!(line_at(src, 0), "X = 1");
    }
}
