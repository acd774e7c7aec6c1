//! Diagnostics with source spans: what is wrong, where, and what to do.

use std::fmt;

use miette::{GraphicalReportHandler, GraphicalTheme, LabeledSpan, NamedSource, SourceSpan};

use super::token::Span;

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// The file is wrong: it does not load, or `kane check` fails.
    Error,
    /// Suspicious but accepted (`kane check` prints it and succeeds).
    Warning,
}

impl Severity {
    /// `error` or `warning`.
    pub fn label(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// One error (or warning) found in a model file.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Where in the source.
    pub span: Span,
    /// What is wrong.
    pub message: String,
    /// What to do about it.
    pub help: Option<String>,
    /// Error or warning.
    pub severity: Severity,
    /// Other places involved, each with what it contributes.
    pub notes: Vec<(Span, String)>,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { span, message: message.into(), help: None, severity: Severity::Error, notes: Vec::new() }
    }

    /// A warning at `span`.
    pub fn warning(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic { severity: Severity::Warning, ..Diagnostic::error(span, message) }
    }

    /// Adds another place involved, with what it contributes.
    pub fn with_note(mut self, span: Span, note: impl Into<String>) -> Diagnostic {
        self.notes.push((span, note.into()));
        self
    }

    /// Adds a hint.
    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }
}

/// Most diagnostics a report shows; the rest are counted ("and N more").
pub const MAX_SHOWN: usize = 50;

/// 1-based line and column of a byte offset.
pub fn line_column(src: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(src.len());
    let before = &src[..offset];
    let line = before.matches('\n').count() + 1;
    let col = before.rfind('\n').map_or(offset, |i| offset - i - 1) + 1;
    (line, col)
}

/// Diagnostics of one file, displayable as `file:line:col: error: message` lines (warnings and
/// notes likewise) and renderable with source excerpts.
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
        for d in self.diagnostics.iter().take(MAX_SHOWN) {
            let (line, col) = line_column(&self.source, d.span.start);
            writeln!(f, "{}:{line}:{col}: {}: {}", self.file, d.severity.label(), d.message)?;
            for (span, note) in &d.notes {
                let (line, col) = line_column(&self.source, span.start);
                writeln!(f, "{}:{line}:{col}: note: {note}", self.file)?;
            }
            if let Some(h) = &d.help {
                writeln!(f, "  help: {h}")?;
            }
        }
        if let Some(rest) = self.not_shown() {
            writeln!(f, "{rest}")?;
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
    fn severity(&self) -> Option<miette::Severity> {
        Some(match self.d.severity {
            Severity::Error => miette::Severity::Error,
            Severity::Warning => miette::Severity::Warning,
        })
    }
    fn help<'b>(&'b self) -> Option<Box<dyn fmt::Display + 'b>> {
        self.d.help.as_ref().map(|h| Box::new(h.clone()) as Box<dyn fmt::Display>)
    }
    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        Some(self.src)
    }
    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let len = self.src.inner().len().max(1);
        let source_span = move |s: &Span| SourceSpan::from(s.start..s.end.max(s.start + 1).min(len));
        let here = LabeledSpan::new_with_span(Some("here".into()), source_span(&self.d.span));
        let notes = self
            .d
            .notes
            .iter()
            .map(move |(s, n)| LabeledSpan::new_with_span(Some(n.clone()), source_span(s)));
        Some(Box::new(std::iter::once(here).chain(notes)))
    }
}

impl Report {
    /// Each error rendered with the source line, a marker under the fault and the hint.
    pub fn render(&self) -> String {
        let src = NamedSource::new(self.file.clone(), self.source.clone());
        let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor());
        let mut out = String::new();
        for d in self.diagnostics.iter().take(MAX_SHOWN) {
            let (line, col) = line_column(&self.source, d.span.start);
            let md = MietteDiag { d, src: &src, location: format!("{}:{line}:{col}", self.file) };
            if handler.render_report(&mut out, &md).is_err() {
                out.push_str(&format!("{md}\n"));
            }
        }
        if let Some(rest) = self.not_shown() {
            out.push_str(&rest);
            out.push('\n');
        }
        out
    }

    /// `{file}: and N more errors (and M warnings) not shown ...` past [`MAX_SHOWN`].
    fn not_shown(&self) -> Option<String> {
        let rest = self.diagnostics.get(MAX_SHOWN..).filter(|r| !r.is_empty())?;
        let errors = rest.iter().filter(|d| d.severity == Severity::Error).count();
        let warnings = rest.len() - errors;
        Some(format!(
            "{}: and {errors} more errors and {warnings} more warnings not shown (the first {MAX_SHOWN} are); fix these and check again",
            self.file
        ))
    }
}
