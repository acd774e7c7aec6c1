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
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{}:{}:{}: error: {}", self.file, self.line, self.column, self.message)?;
        write!(f, "  help: {}", self.help)
    }
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
    SceneError { file: file.to_string(), line, column, message, help: help.to_string() }
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
