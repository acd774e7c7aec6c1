//! Reading a hand file: each statement evaluated in the model's names and sorted by what it
//! gives (speed derivatives, `Fr + Fr*` rows, vectors or scalars of the model).

use crate::expr::ExprId;
use crate::mechanics::{FrameId, KaneEquations, Vector};

use super::super::ast::{Expr, ExprKind, Stmt, StmtKind, Target};
use super::super::diagnostic::Diagnostic;
use super::super::interp::value::Value;
use super::super::interp::Interpreter;

/// What one statement of a hand file gives.
pub(super) enum Given {
    /// `U1' = h`: the derivative of speed `row`.
    Udot(usize, ExprId),
    /// `ZERO[r] = g`: row `r` (0-based) of `Fr + Fr* = 0`.
    Zero(usize, ExprId),
    /// `V_P_A> = v`: a vector of the model, with the model's value and the frame of the first
    /// unit vector the hand file writes.
    Vector { name: String, hand: Vector, derived: Vector, frame: Option<FrameId> },
    /// `K1 = x`: a scalar the model names, with the model's value.
    Scalar { name: String, hand: ExprId, derived: ExprId },
}

/// The statements of `stmts` as [`Given`]s, or every error found.
pub(super) fn read(
    it: &mut Interpreter,
    eqs: &KaneEquations,
    stmts: &[Stmt],
) -> Result<Vec<Given>, Vec<Diagnostic>> {
    let speed_names: Vec<String> =
        eqs.speeds.iter().map(|s| it.model.ar.symbol_info(*s).name.to_ascii_uppercase()).collect();
    let mut out = Vec::new();
    let mut diags = Vec::new();
    for s in stmts {
        let StmtKind::Assign { target, value, .. } = &s.kind else {
            diags.push(
                Diagnostic::error(s.span.clone(), "a hand file holds equations only")
                    .with_help("write U1' = ..., ZERO[1] = ..., V_P_A> = ... or a named quantity = ..."),
            );
            continue;
        };
        match given(it, &speed_names, target, value) {
            Ok(g) => out.push(g),
            Err(d) => diags.push(d),
        }
    }
    if diags.is_empty() {
        Ok(out)
    } else {
        Err(diags)
    }
}

/// The model's own value of the name a target writes.
fn derived_value(it: &mut Interpreter, target: &Target) -> Result<Value, Diagnostic> {
    let kind = ExprKind::Name { name: target.name.clone(), primes: 0, suffix: target.suffix };
    it.eval(&Expr { kind, span: target.span.clone() })
}

/// One statement `target = value`.
fn given(
    it: &mut Interpreter,
    speeds: &[String],
    target: &Target,
    value: &Expr,
) -> Result<Given, Diagnostic> {
    let hand = it.eval(value)?;
    let key = target.name.to_ascii_uppercase();
    let scalar = |v: &Value| match v {
        Value::Scalar(x) => Ok(*x),
        other => Err(Diagnostic::error(
            value.span.clone(),
            format!("`{}` needs a scalar, not {}", target.name, other.kind()),
        )),
    };
    if target.primes == 1 && target.index.is_none() {
        let r = speeds.iter().position(|u| *u == key).ok_or_else(|| {
            Diagnostic::error(
                target.span.clone(),
                format!("`{}` is not a generalized speed of the model", target.name),
            )
            .with_help(format!("the speeds are {}", speeds.join(", ")))
        })?;
        return Ok(Given::Udot(r, scalar(&hand)?));
    }
    if let Some(index) = &target.index {
        let n = speeds.len();
        let r = match (key.as_str(), index.as_slice()) {
            ("ZERO", [i]) => it.index_value(i)?,
            _ => 0,
        };
        if r < 1 || r as usize > n {
            return Err(Diagnostic::error(
                target.span.clone(),
                format!("expected ZERO[i] with 1 <= i <= {n}"),
            ));
        }
        return Ok(Given::Zero(r as usize - 1, scalar(&hand)?));
    }
    if target.primes > 0 {
        return Err(Diagnostic::error(target.span.clone(), "expected U' = ... (a speed derivative)"));
    }
    let name = format!("{}{}", target.name, ">".repeat(target.suffix as usize));
    match (hand, derived_value(it, target)?) {
        (Value::Vector(hand), Value::Vector(derived)) => {
            Ok(Given::Vector { name, hand, derived, frame: written_frame(it, value) })
        }
        (Value::Scalar(hand), Value::Scalar(derived)) => Ok(Given::Scalar { name, hand, derived }),
        (h, d) => Err(Diagnostic::error(
            value.span.clone(),
            format!("the model's `{name}` is {}, the hand file gives {}", d.kind(), h.kind()),
        )
        .with_help("compare scalars with scalars and vectors with vectors")),
    }
}

/// The frame of the first unit vector (`D2>`) written in `e`, left to right.
fn written_frame(it: &Interpreter, e: &Expr) -> Option<FrameId> {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match &e.kind {
            ExprKind::Name { name, suffix: 1, .. } => {
                let key = name.to_ascii_uppercase();
                if it.unit_vector(&key).is_some() {
                    return it.frame_of(&key[..key.len() - 1]);
                }
            }
            ExprKind::Neg(x) => stack.push(x),
            ExprKind::Binary(_, a, b) => stack.extend([b.as_ref(), a.as_ref()]),
            ExprKind::Call { args, .. } => stack.extend(args.iter().rev()),
            _ => {}
        }
    }
    None
}
