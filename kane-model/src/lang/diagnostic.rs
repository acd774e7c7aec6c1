//! Diagnostics with source spans: what is wrong, where, and what to do.

use std::fmt;

use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan, NamedSource, SourceSpan};

use super::token::Span;

/// One error found in a model file.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Where in the source.
    pub span: Span,
    /// What is wrong.
    pub message: String,
    /// What to do about it.
    pub help: Option<String>,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { span, message: message.into(), help: None }
    }

    /// Adds a hint.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }
}

/// 1-based line and column of a byte offset.
pub fn line_column(src: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(src.len());
    let before = &src[..offset];
    let line = before.matches('\n').count() + 1;
    let col = before.rfind('\n').map_or(offset, |i| offset - i - 1) + 1;
    (line, col)
}

/// Diagnostics of one file, displayable as `file:line:col: error: message` lines and renderable
/// with source excerpts.
#[derive(Clone, Debug)]
pub struct Report {
    /// File name as given.
    pub file: String,
    /// Its text.
    pub source: String,
    /// The errors, in source order.
    pub diagnostics: Vec<Diagnostic>,
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for d in &self.diagnostics {
            let (line, col) = line_column(&self.source, d.span.start);
            writeln!(f, "{}:{line}:{col}: error: {}", self.file, d.message)?;
            if let Some(h) = &d.help {
                writeln!(f, "  help: {h}")?;
            }
        }
        Ok(())
    }
}

impl std::error::Error for Report {}

struct MietteDiag<'a> {
    d: &'a Diagnostic,
    src: &'a NamedSource<String>,
    location: String,
}

impl fmt::Debug for MietteDiag<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.d.message)
    }
}

impl fmt::Display for MietteDiag<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.location, self.d.message)
    }
}

impl std::error::Error for MietteDiag<'_> {}

impl miette::Diagnostic for MietteDiag<'_> {
    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.d.help.as_ref().map(|h| Box::new(h.clone()) as Box<dyn fmt::Display>)
    }
    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        Some(self.src)
    }
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let span = SourceSpan::from(
            self.d.span.start..self.d.span.end.max(self.d.span.start + 1).min(self.src.inner().len().max(1)),
        );
        Some(Box::new(std::iter::once(LabeledSpan::new_with_span(Some("here".into()), span))))
    }
}

impl Report {
    /// Each error rendered with the source line, a marker under the fault and the hint.
    pub fn render(&self) -> String {
        let src = NamedSource::new(self.file.clone(), self.source.clone());
        let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor());
        let mut out = String::new();
        for d in &self.diagnostics {
            let (line, col) = line_column(&self.source, d.span.start);
            let md = MietteDiag { d, src: &src, location: format!("{}:{line}:{col}", self.file) };
            if handler.render_report(&mut out, &md).is_err() {
                out.push_str(&format!("{md}\n"));
            }
        }
        out
    }
}
