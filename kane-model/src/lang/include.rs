//! Other files a model file runs: `RUN FILE.AL` runs that file's statements in place, and a
//! call of an Autolev macro, `contact(RHeel)`, runs the file `contact.a` with `#1#`, `#2#`, ...
//! replaced by the call's arguments as written (Autolev's textual substitution).
//!
//! In: the model file's name (a path) and text. Out: one text (the model file, then each file
//! run, appended), its statements in running order with spans into that text, the parse errors,
//! and the parts of the text each file holds, for diagnostics that name the right file.
//!
//! A file named by RUN is looked for beside the model file, then in each folder above it (as
//! Autolev, started in a project's folder, reads names relative to it); a macro file likewise.

use super::file_search::find;
use std::path::{Path, PathBuf};

use super::ast::{Expr, ExprKind, Stmt, StmtKind};
use super::diagnostic::{Diagnostic, SourcePart};
use super::parser;

/// Deepest nesting of files run from files run.
const MAX_DEPTH: usize = 16;

/// A model file with the files it runs.
pub(crate) struct Expanded {
    /// The model file's text, then each file run (a newline before each).
    pub(crate) source: String,
    /// The statements, in the order they run.
    pub(crate) stmts: Vec<Stmt>,
    /// Syntax errors, and files that could not be read.
    pub(crate) errors: Vec<Diagnostic>,
    /// Where each file's text is in `source` (the model file's first).
    pub(crate) parts: Vec<SourcePart>,
    /// Whether an EXIT ended the run.
    exited: bool,
}

/// `source` of the model file `file` with the files it runs.
pub(crate) fn expand(file: &str, source: &str) -> Expanded {
    let mut out = Expanded {
        source: source.to_string(),
        stmts: Vec::new(),
        errors: Vec::new(),
        parts: vec![SourcePart { range: 0..source.len(), file: file.to_string() }],
        exited: false,
    };
    let (stmts, errors) = parser::parse(source);
    out.errors = errors;
    let dir = Path::new(file).parent().map(Path::to_path_buf);
    out.stmts = splice(&mut out, stmts, dir.as_deref(), 0);
    out
}

/// `stmts` with each RUN and macro call replaced by the statements of the file it runs, up to
/// an EXIT (which ends Autolev's run: what follows it, here or in a file that ran this one, is
/// not read).
fn splice(out: &mut Expanded, stmts: Vec<Stmt>, dir: Option<&Path>, depth: usize) -> Vec<Stmt> {
    let mut kept = Vec::with_capacity(stmts.len());
    for s in stmts {
        if out.exited {
            break;
        }
        if matches!(&s.kind, StmtKind::Session(c) if c == "EXIT") {
            let (at, end) = (
                s.span.start,
                out.parts
                    .iter()
                    .find(|p| p.range.contains(&s.span.start))
                    .map_or(usize::MAX, |p| p.range.end),
            );
            out.errors.retain(|d| d.span.start < at || d.span.start >= end);
            out.exited = true;
            kept.push(s);
            break;
        }
        let found = match &s.kind {
            StmtKind::Run(name) => Some(run_file(name, dir, &s)),
            StmtKind::Expr(Expr { kind: ExprKind::Call { name, args }, .. })
                if macro_file(name, dir).is_some() =>
            {
                macro_file(name, dir).map(|path| macro_text(&path, args, &out.source, &s))
            }
            // The statement is read again from the model's folder (for the calls left in it).
            _ => super::user_functions::expand(&s, &out.source, dir).map(|r| {
                r.map(|e| {
                    let call = out.source.get(s.span.clone()).unwrap_or("").trim();
                    Included {
                        label: format!("{} (from `{call}`)", e.path.display()),
                        path: dir.unwrap_or(Path::new("")).join("statement"),
                        text: e.text,
                    }
                })
            }),
        };
        let Some(found) = found else {
            kept.push(s);
            continue;
        };
        match found.and_then(|f| if depth < MAX_DEPTH { Ok(f) } else { Err(too_deep(&s)) }) {
            Ok(Included { path, label, text }) => {
                out.source.push('\n');
                let at = out.source.len();
                out.source.push_str(&text);
                out.parts.push(SourcePart { range: at..out.source.len(), file: label });
                let (inner, errors) = parser::parse_from(&out.source, at);
                out.errors.extend(errors);
                let inner_dir = path.parent().map(Path::to_path_buf);
                kept.extend(splice(out, inner, inner_dir.as_deref(), depth + 1));
            }
            Err(d) => out.errors.push(d),
        }
    }
    kept
}

/// A file to run: where it is, the name diagnostics give it, and its text.
struct Included {
    path: PathBuf,
    label: String,
    text: String,
}

/// The file `RUN name` names.
fn run_file(name: &str, dir: Option<&Path>, s: &Stmt) -> Result<Included, Diagnostic> {
    let name = name.trim_matches(|c| c == '"' || c == '\'');
    let Some(path) = find(name, dir) else {
        return Err(Diagnostic::error(
            s.span.clone(),
            format!("RUN: no file `{name}` beside the model file or in a folder above it"),
        )
        .with_help(
            "RUN names a model file by its path from the model file's folder (or a folder above it)",
        ));
    };
    let text = std::fs::read_to_string(&path).map_err(|e| {
        Diagnostic::error(s.span.clone(), format!("RUN: cannot read {}: {e}", path.display()))
    })?;
    Ok(Included { label: path.display().to_string(), path, text })
}

/// The macro file `name.a` a call of `name` runs, if there is one.
fn macro_file(name: &str, dir: Option<&Path>) -> Option<PathBuf> {
    [name.to_string(), name.to_ascii_lowercase(), name.to_ascii_uppercase()]
        .iter()
        .find_map(|n| find(&format!("{n}.a"), dir).or_else(|| find(&format!("{n}.A"), dir)))
}

/// The macro at `path` with `#1#`, `#2#`, ... replaced by the arguments' text.
fn macro_text(path: &Path, args: &[Expr], source: &str, s: &Stmt) -> Result<Included, Diagnostic> {
    let body = std::fs::read_to_string(path).map_err(|e| {
        Diagnostic::error(s.span.clone(), format!("cannot read the macro {}: {e}", path.display()))
    })?;
    let mut text = body.clone();
    for (i, a) in args.iter().enumerate() {
        let written = source.get(a.span.clone()).unwrap_or("").trim();
        text = text.replace(&format!("#{}#", i + 1), written);
    }
    if let Some(at) = text.find('#').filter(|at| text[at + 1..].starts_with(|c: char| c.is_ascii_digit())) {
        let end = text[at + 1..].find('#').map_or(text.len(), |e| at + 2 + e);
        return Err(Diagnostic::error(
            s.span.clone(),
            format!(
                "the macro {} uses {} but the call gives {} argument(s)",
                path.display(),
                &text[at..end],
                args.len()
            ),
        ));
    }
    let call = source.get(s.span.clone()).unwrap_or("").trim();
    Ok(Included { label: format!("{} (from `{call}`)", path.display()), path: path.to_path_buf(), text })
}

fn too_deep(s: &Stmt) -> Diagnostic {
    Diagnostic::error(
        s.span.clone(),
        format!("files run from files run are nested more than {MAX_DEPTH} deep"),
    )
    .with_help("a file that runs itself, directly or through others, never ends")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn run_and_macros_splice_their_statements_in_place() {
        let dir = std::env::temp_dir().join(format!("kane-include-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        std::fs::write(dir.join("sub/kin.al"), "Y = 2\n").unwrap();
        std::fs::write(dir.join("contact.a"), "F#1# = #2# + 1\n").unwrap();
        let main = dir.join("sub/main.al");
        let src = "X = 1\nRUN kin.al\ncontact(RHeel, X*Y)\nZ = FRHEEL\n";
        let e = expand(&main.display().to_string(), src);
        assert!(e.errors.is_empty(), "{:?}", e.errors);
        let texts: Vec<&str> = e.stmts.iter().map(|s| e.source[s.span.clone()].trim()).collect();
        assert_eq!(texts, ["X = 1", "Y = 2", "FRHeel = X*Y + 1", "Z = FRHEEL"]);
        assert_eq!(e.parts.len(), 3);
        assert!(e.parts[2].file.contains("contact.a (from `contact(RHeel, X*Y)`)"), "{}", e.parts[2].file);
        let missing = expand(&main.display().to_string(), "RUN nowhere.al\n");
        assert!(missing.errors[0].message.starts_with("RUN: no file `nowhere.al`"), "{:?}", missing.errors);
        std::fs::write(dir.join("self.al"), "RUN self.al\n").unwrap();
        let looped = expand(&dir.join("self.al").display().to_string(), "RUN self.al\n");
        assert!(looped.errors.iter().any(|d| d.message.contains("nested more than")));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
