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

/// Where one file's text is in a report's source: the model file, or a file it runs.
#[derive(Clone, Debug, PartialEq)]
pub struct SourcePart {
    /// The bytes of the source that are this file's text.
    pub range: Span,
    /// The file's name (for a macro, with the call it came from).
    pub file: String,
}

/// Diagnostics of one file, displayable as `file:line:col: error: message` lines (warnings and
/// notes likewise) and renderable with source excerpts.
#[derive(Clone, Debug)]
pub struct Report {
    /// File name as given.
    pub file: String,
    /// Its text, followed by the text of each file it runs.
    pub source: String,
    /// The errors, in source order.
    pub diagnostics: Vec<Diagnostic>,
    /// The files run from the model file, with where their text is in `source`.
    pub parts: Vec<SourcePart>,
}

impl Report {
    /// A report on `file`, whose text is `source`, of `diagnostics`.
    pub fn new(file: &str, source: &str, diagnostics: Vec<Diagnostic>) -> Report {
        Report { file: file.to_string(), source: source.to_string(), diagnostics, parts: Vec::new() }
    }

    /// The file holding byte `offset` of the source, its text, and where that text starts.
    fn part_of(&self, offset: usize) -> (&str, &str, usize) {
        match self.parts.iter().skip(1).find(|p| p.range.contains(&offset) || p.range.end == offset) {
            Some(p) => (&p.file, &self.source[p.range.clone()], p.range.start),
            None => {
                let end = self.parts.first().map_or(self.source.len(), |p| p.range.end);
                (&self.file, &self.source[..end.min(self.source.len())], 0)
            }
        }
    }

    /// `file:line:col` of byte `offset` of the source.
    fn location(&self, offset: usize) -> String {
        let (file, text, start) = self.part_of(offset);
        let (line, col) = line_column(text, offset.saturating_sub(start));
        format!("{file}:{line}:{col}")
    }
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for d in self.diagnostics.iter().take(MAX_SHOWN) {
            writeln!(f, "{}: {}: {}", self.location(d.span.start), d.severity.label(), d.message)?;
            for (span, note) in &d.notes {
                writeln!(f, "{}: note: {note}", self.location(span.start))?;
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
    /// Where the text `src` holds starts in the report's source.
    start: usize,
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
        let len = self.src.inner().len();
        let start = self.start;
        let inside = move |s: &Span| s.start >= start && s.start <= start + len;
        let source_span = move |s: &Span| {
            let (a, b) = (s.start - start, s.end.saturating_sub(start));
            SourceSpan::from(a.min(len)..b.max(a + 1).min(len.max(1)))
        };
        let here = LabeledSpan::new_with_span(Some("here".into()), source_span(&self.d.span));
        let notes = self
            .d
            .notes
            .iter()
            .filter(move |(s, _)| inside(s))
            .map(move |(s, n)| LabeledSpan::new_with_span(Some(n.clone()), source_span(s)));
        Some(Box::new(std::iter::once(here).chain(notes)))
    }
}

impl Report {
    /// Each error rendered with the source line, a marker under the fault and the hint.
    pub fn render(&self) -> String {
        let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor());
        let mut out = String::new();
        for d in self.diagnostics.iter().take(MAX_SHOWN) {
            let (file, text, start) = self.part_of(d.span.start);
            let src = NamedSource::new(file, text.to_string());
            let md = MietteDiag { d, src: &src, location: self.location(d.span.start), start };
            if handler.render_report(&mut out, &md).is_err() {
                out.push_str(&format!("{md}\n"));
            }
            // Notes in another file than the error are named by place.
            for (span, note) in d.notes.iter().filter(|(s, _)| self.part_of(s.start).2 != start) {
                out.push_str(&format!("  note: {}: {note}\n", self.location(span.start)));
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
