//! Autolev user functions: a call `NAME(a, b)` where a file `NAME.r` (or `.R`) holds an
//! expression in `#1#`, `#2#`, ... stands for that expression with the arguments as written, in
//! parentheses. In comes a statement; out goes its text with each such call replaced.

use std::path::{Path, PathBuf};

use super::ast::{Expr, ExprKind, Stmt, StmtKind};
use super::diagnostic::Diagnostic;

/// A statement with its user functions written out: the text, and the first function file.
pub(super) struct Expanded {
    /// The function file (the first, when several are called).
    pub(super) path: PathBuf,
    /// The statement's text with every call replaced.
    pub(super) text: String,
}

/// The statement `s` with the calls of user functions found from `dir` written out, or `None`
/// when it calls none.
pub(super) fn expand(s: &Stmt, source: &str, dir: Option<&Path>) -> Option<Result<Expanded, Diagnostic>> {
    let root = match &s.kind {
        StmtKind::Assign { value, .. } => value,
        StmtKind::Expr(e) => e,
        _ => return None,
    };
    let mut calls = Vec::new();
    collect_calls(root, &mut calls);
    // Autolev's own functions are never a file's.
    let builtin = |name: &str| super::interp::KNOWN_CALLS.contains(&name.to_ascii_uppercase().as_str());
    let mut found: Vec<(&Expr, PathBuf)> = calls
        .into_iter()
        .filter(|(_, name)| !builtin(name))
        .filter_map(|(c, name)| function_file(name, dir).map(|p| (c, p)))
        .collect();
    if found.is_empty() {
        return None;
    }
    // Outermost first; a call inside another's arguments is written out with them (the text is
    // read again, so its own expansion follows).
    found.sort_by_key(|(c, _)| c.span.start);
    let mut outer: Vec<(&Expr, PathBuf)> = Vec::new();
    for (c, p) in found {
        if outer.last().is_none_or(|(o, _)| c.span.start >= o.span.end) {
            outer.push((c, p));
        }
    }
    let mut text = source.get(s.span.clone())?.to_string();
    for (call, path) in outer.iter().rev() {
        let ExprKind::Call { args, .. } = &call.kind else { continue };
        let body = match body_with(path, args, source, call) {
            Ok(b) => b,
            Err(d) => return Some(Err(d)),
        };
        let (from, to) = (call.span.start - s.span.start, call.span.end - s.span.start);
        text.replace_range(from..to, &format!("({body})"));
    }
    Some(Ok(Expanded { path: outer[0].1.clone(), text }))
}

/// Every call in `e`, with its name.
fn collect_calls<'e>(e: &'e Expr, out: &mut Vec<(&'e Expr, &'e str)>) {
    match &e.kind {
        ExprKind::Call { name, args } => {
            out.push((e, name));
            args.iter().for_each(|a| collect_calls(a, out));
        }
        ExprKind::Index { args, .. } => args.iter().for_each(|a| collect_calls(a, out)),
        ExprKind::Matrix(rows) => rows.iter().flatten().for_each(|a| collect_calls(a, out)),
        ExprKind::Neg(a) => collect_calls(a, out),
        ExprKind::Binary(_, a, b) | ExprKind::Range(a, b) | ExprKind::NamedArg(a, b) => {
            collect_calls(a, out);
            collect_calls(b, out);
        }
        ExprKind::Number { .. } | ExprKind::Name { .. } => {}
    }
}

/// The file `name.r` defining a user function, if there is one.
fn function_file(name: &str, dir: Option<&Path>) -> Option<PathBuf> {
    [name.to_string(), name.to_ascii_lowercase(), name.to_ascii_uppercase()].iter().find_map(|n| {
        super::file_search::find(&format!("{n}.r"), dir)
            .or_else(|| super::file_search::find(&format!("{n}.R"), dir))
    })
}

/// The function's expression (its lines without `%` comments) with `#i#` replaced by the
/// arguments' text.
fn body_with(path: &Path, args: &[Expr], source: &str, call: &Expr) -> Result<String, Diagnostic> {
    let file = std::fs::read_to_string(path).map_err(|e| {
        Diagnostic::error(call.span.clone(), format!("cannot read the function {}: {e}", path.display()))
    })?;
    let mut body: String = file
        .lines()
        .map(|l| l.split('%').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ");
    for (i, a) in args.iter().enumerate() {
        let written = source.get(a.span.clone()).unwrap_or("").trim();
        body = body.replace(&format!("#{}#", i + 1), &format!("({written})"));
    }
    if body.is_empty() || body.contains('#') {
        return Err(Diagnostic::error(
            call.span.clone(),
            format!(
                "the function {} {} for the {} argument(s) given",
                path.display(),
                if body.is_empty() { "holds no expression" } else { "uses an argument not given" },
                args.len()
            ),
        ));
    }
    Ok(body)
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_user_function_is_written_out_with_its_arguments() {
        let dir = std::env::temp_dir().join(format!("kane-user-fn-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("half_sum.r"), "% the half sum\n(#1# + #2#)/2\n").unwrap();
        // Autolev's own functions are never replaced by a file's.
        std::fs::write(dir.join("sin.r"), "#1#^2\n").unwrap();
        let main = dir.join("main.al");
        let src = "CONSTANTS A, B\nX = 3*HALF_SUM(A, 2*B) + 1\nY = HALF_SUM(HALF_SUM(A, B), 1)\nZ = SIN(A)\n";
        let m = super::super::load(&main.display().to_string(), src).unwrap_or_else(|r| panic!("{r}"));
        let ar = &m.model.ar;
        let value = |name: &str| {
            let Some(super::super::Value::Scalar(x)) = m.value(name) else { panic!("{name}") };
            let v = |s| Some(if ar.symbol_info(s).name == "A" { 2.0 } else { 5.0 });
            ar.eval(&[x], v).unwrap()[0]
        };
        assert_eq!(value("X"), 3.0 * (2.0 + 10.0) / 2.0 + 1.0);
        assert_eq!(value("Y"), ((2.0 + 5.0) / 2.0 + 1.0) / 2.0);
        assert_eq!(value("Z"), 2f64.sin());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
