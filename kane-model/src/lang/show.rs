//! `kane show`: any quantity of a model (scalar, vector, dyadic, matrix), simplified.

use crate::expr::{Arena, ExprError, ExprId, Node};
use crate::mechanics::{Dyadic, FrameId, Model, Vector};

use super::ast::StmtKind;
use super::diagnostic::Diagnostic;
use super::interp::value::Value;
use super::present::Presenter;
use super::session::{report, Session};
use super::{parser, Report};

/// `name = value` for the quantity `name` of the model in `source` (any expression the file
/// could write, e.g. `I1`, `A_P_A>`, `I_D_DO>>`), simplified and in the file's names. Vectors
/// are written in `frame` when one is given, otherwise in the frames they are held in.
pub fn show(file: &str, source: &str, name: &str, frame: Option<&str>) -> Result<String, Report> {
    let mut s = Session::open(file, source)?;
    let arg = "command line";
    let (stmts, errors) = parser::parse(name);
    if !errors.is_empty() {
        return Err(report(arg, name, errors));
    }
    let [stmt] = stmts.as_slice() else {
        return Err(report(arg, name, vec![Diagnostic::error(0..name.len(), "expected one quantity")]));
    };
    let StmtKind::Expr(e) = &stmt.kind else {
        return Err(report(
            arg,
            name,
            vec![Diagnostic::error(stmt.span.clone(), "expected a quantity")
                .with_help("give a name such as I1, V_P_A> or I_D_DO>>")],
        ));
    };
    let value = s.it.eval(e).map_err(|d| report(arg, name, vec![d]))?;
    let frame = match frame {
        Some(f) => Some(s.it.frame_of(&f.to_ascii_uppercase()).ok_or_else(|| {
            report(arg, f, vec![Diagnostic::error(0..f.len(), format!("`{f}` is not a frame or body"))])
        })?),
        None => None,
    };
    let exclude = name.trim().trim_end_matches('>').to_string();
    let fail = |e: String| report(arg, name, vec![Diagnostic::error(0..name.len(), e)]);
    let p = s.presenter(Some(&exclude)).map_err(|e| fail(e.to_string()))?;
    let text = value_text(&mut s.it.model, &p, &value, frame).map_err(fail)?;
    Ok(format!("{} = {text}", name.trim()))
}

/// The text of a value.
fn value_text(m: &mut Model, p: &Presenter, v: &Value, frame: Option<FrameId>) -> Result<String, String> {
    let err = |e: ExprError| e.to_string();
    match v {
        Value::Scalar(x) => p.text(&mut m.ar, *x).map_err(err),
        Value::Shown(text) => Ok(text.clone()),
        Value::Vector(v) => {
            let v = match frame {
                Some(f) => m.express_vector(v, f).map_err(|e| e.to_string())?,
                None => v.clone(),
            };
            vector_text(m, p, &v).map_err(err)
        }
        Value::Dyadic(d) => dyadic_text(m, p, d).map_err(err),
        Value::Vectors { rows, cols, data } => {
            let mut out = Vec::with_capacity(*rows);
            for r in 0..*rows {
                let row = (0..*cols)
                    .map(|c| value_text(m, p, &Value::Vector(data[r * cols + c].clone()), frame))
                    .collect::<Result<Vec<_>, _>>()?;
                out.push(row.join(", "));
            }
            Ok(format!("[{}]", out.join("; ")))
        }
        Value::Matrix { rows, cols, data } => {
            let mut out = Vec::with_capacity(*rows);
            for r in 0..*rows {
                let row = (0..*cols)
                    .map(|c| p.text(&mut m.ar, data[r * cols + c]))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(err)?;
                out.push(row.join(", "));
            }
            Ok(format!("[{}]", out.join("; ")))
        }
    }
}

/// `coefficient*unit` terms joined into one sum; zero coefficients left out.
fn join_terms(ar: &mut Arena, p: &Presenter, terms: Vec<(ExprId, String)>) -> Result<String, ExprError> {
    let mut s = String::new();
    for (x, unit) in terms {
        let c = p.tidy(ar, x)?;
        if c.is_zero() {
            continue;
        }
        let text = ar.collected_text(&c);
        // One term that prints as a sum (a parameter-only group, or an unsimplified whole).
        let t = &c.terms[0];
        let many = c.terms.len() > 1 || (!t.negative && matches!(ar.node(t.value), Node::Sum(_)));
        let (neg, body) = match (many, text.strip_prefix('-')) {
            (false, Some(rest)) => (true, rest.to_string()),
            (false, None) => (false, text),
            (true, _) => (false, format!("({text})")),
        };
        let body = if body == "1" { unit } else { format!("{body}*{unit}") };
        s.push_str(match (s.is_empty(), neg) {
            (true, true) => "-",
            (true, false) => "",
            (false, true) => " - ",
            (false, false) => " + ",
        });
        s.push_str(&body);
    }
    Ok(if s.is_empty() { "0>".into() } else { s })
}

/// A vector as `c1*A1> + c2*A2> + ...`.
fn vector_text(m: &mut Model, p: &Presenter, v: &Vector) -> Result<String, ExprError> {
    let mut terms = Vec::new();
    for (f, xs) in v.terms() {
        for (k, x) in xs.iter().enumerate() {
            terms.push((*x, format!("{}{}>", m.frame_name(*f), k + 1)));
        }
    }
    join_terms(&mut m.ar, p, terms)
}

/// A dyadic as `c11*B1>*B1> + ...`.
fn dyadic_text(m: &mut Model, p: &Presenter, d: &Dyadic) -> Result<String, ExprError> {
    let mut terms = Vec::new();
    for (a, b, xs) in d.terms() {
        for (i, row) in xs.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                let unit = format!("{}{}>*{}{}>", m.frame_name(*a), i + 1, m.frame_name(*b), j + 1);
                terms.push((*x, unit));
            }
        }
    }
    let s = join_terms(&mut m.ar, p, terms)?;
    Ok(if s == "0>" { "0>>".into() } else { s })
}
