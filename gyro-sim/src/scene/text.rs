//! A scene's text, for errors at its spans: in come the file's name, its text and a byte span;
//! out goes a [`SceneError`] at that line and column with what is wrong and what to do.

use std::fmt;

/// A scene that cannot be used: where and why, and what to do.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    /// The file.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
    /// What is wrong.
    pub message: String,
    /// What to do.
    pub help: String,
    /// Further mistakes found in the same reading, in the file's order.
    pub more: Vec<SceneError>,
}

impl SceneError {
    /// One error holding every mistake of `errors` (at least one), the first in the file first.
    pub fn all(errors: Vec<SceneError>) -> SceneError {
        let mut errors: Vec<SceneError> = errors
            .into_iter()
            .flat_map(|mut e| {
                let more = std::mem::take(&mut e.more);
                std::iter::once(e).chain(more)
            })
            .collect();
        errors.sort_by_key(|e| (e.line, e.column));
        errors.dedup();
        let mut first = errors.remove(0);
        first.more.extend(errors);
        first
    }

    /// This mistake and the further ones.
    pub fn each(&self) -> impl Iterator<Item = &SceneError> {
        std::iter::once(self).chain(&self.more)
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, e) in self.each().enumerate() {
            if k > 0 {
                writeln!(f)?;
            }
            writeln!(f, "{}:{}:{}: error: {}", e.file, e.line, e.column, e.message)?;
            write!(f, "  help: {}", e.help)?;
        }
        Ok(())
    }
}

/// The result of one check of a scene kept, its error added to `found`.
pub(crate) fn keep<T>(found: &mut Vec<SceneError>, result: Result<T, SceneError>) -> Option<T> {
    result.map_err(|e| found.push(e)).ok()
}

impl std::error::Error for SceneError {}

/// A byte range of a scene's text.
pub(super) type Span = std::ops::Range<usize>;

/// The 1-based line and column of byte `offset` of `src`.
pub(super) fn line_col(src: &str, offset: usize) -> (usize, usize) {
    let before = &src[..offset.min(src.len())];
    let line = before.matches('\n').count() + 1;
    let col = before.rfind('\n').map_or(before.len(), |i| before.len() - i - 1) + 1;
    (line, col)
}

/// An error at a span of a scene's text.
pub(super) fn error_at(file: &str, source: &str, span: Span, message: String, help: &str) -> SceneError {
    let (line, column) = line_col(source, span.start);
    SceneError { file: file.to_string(), line, column, message, help: help.to_string(), more: Vec::new() }
}

/// A parsed scene's text, for errors at spans of it.
pub(super) struct Text<'a> {
    pub(super) file: &'a str,
    pub(super) source: &'a str,
}

impl Text<'_> {
    /// An error at `span` of this text.
    pub(super) fn err(&self, span: Span, message: String, help: &str) -> SceneError {
        error_at(self.file, self.source, span, message, help)
    }
}

/// Whether `name` is a model name as scenes write them: a letter, then letters, digits or `_`.
pub(super) fn is_simple_name(name: &str) -> bool {
    name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}
