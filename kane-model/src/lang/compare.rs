//! Checking hand-derived equations against the derived ones.
//!
//! A hand file holds one scalar equation per generalized speed, in the model language, either as
//! `U1' = ...` (the speed derivatives) or as `ZERO[1] = ...` (the expressions `Fr + Fr*` that
//! vanish, written with the speed derivatives `U1'`).

use crate::expr::{Equivalence, EquivalenceConfig, ExprId};

use super::ast::StmtKind;
use super::diagnostic::{Diagnostic, Report};
use super::interp::value::Value;
use super::interp::Interpreter;
use super::parser;

/// The verdict on one hand-derived equation.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// Which equation: `U1'` or `ZERO[1]`.
    pub label: String,
    /// What the derived equations say about it.
    pub verdict: Equivalence,
}

/// Runs `model` (which must call KANE()), then checks each equation of `hand` against Kane's
/// equations: `U_r' = h_r` is checked as `sum_s M_rs h_s - f_r = 0` for each row the hand file
/// gives all speeds for; `ZERO[r] = g` as `g = f_r - sum_s M_rs u_s'`.
pub fn compare(
    model_file: &str,
    model: &str,
    hand_file: &str,
    hand: &str,
) -> Result<Vec<Comparison>, Report> {
    let (stmts, errors) = parser::parse(model);
    let report = |file: &str, src: &str, diagnostics: Vec<Diagnostic>| Report {
        file: file.to_string(),
        source: src.to_string(),
        diagnostics,
    };
    if !errors.is_empty() {
        return Err(report(model_file, model, errors));
    }
    let mut it = Interpreter::new();
    it.run(&stmts);
    if !it.errors.is_empty() {
        return Err(report(model_file, model, std::mem::take(&mut it.errors)));
    }
    let Some(eqs) = it.equations.clone() else {
        return Err(report(
            model_file,
            model,
            vec![Diagnostic::error(0..0, "the model file derives no equations")
                .with_help("call KANE() in the model file")],
        ));
    };
    let (hand_stmts, errors) = parser::parse(hand);
    if !errors.is_empty() {
        return Err(report(hand_file, hand, errors));
    }
    let n = eqs.speeds.len();
    let speed_names: Vec<String> =
        eqs.speeds.iter().map(|s| it.model.ar.symbol_info(*s).name.to_ascii_uppercase()).collect();
    let mut udot_given: Vec<Option<(ExprId, super::token::Span)>> = vec![None; n];
    let mut zero_given: Vec<(usize, ExprId, super::token::Span)> = Vec::new();
    let mut diags = Vec::new();
    for s in &hand_stmts {
        let StmtKind::Assign { target, value, .. } = &s.kind else {
            diags.push(
                Diagnostic::error(s.span.clone(), "a hand file holds equations only")
                    .with_help("write U1' = ... or ZERO[1] = ..."),
            );
            continue;
        };
        let v = match it.eval(value) {
            Ok(Value::Scalar(x)) => x,
            Ok(other) => {
                diags.push(Diagnostic::error(
                    value.span.clone(),
                    format!("an equation needs a scalar, not {}", other.kind()),
                ));
                continue;
            }
            Err(d) => {
                diags.push(d);
                continue;
            }
        };
        let key = target.name.to_ascii_uppercase();
        if target.primes == 1 && target.index.is_none() {
            match speed_names.iter().position(|u| *u == key) {
                Some(r) => udot_given[r] = Some((v, s.span.clone())),
                None => diags.push(
                    Diagnostic::error(
                        target.span.clone(),
                        format!("`{}` is not a generalized speed of the model", target.name),
                    )
                    .with_help(format!("the speeds are {}", speed_names.join(", "))),
                ),
            }
        } else if key == "ZERO" && target.index.as_ref().is_some_and(|i| i.len() == 1) {
            let idx = target.index.as_ref().map(|i| it.index_value(&i[0]));
            match idx {
                Some(Ok(r)) if r >= 1 && (r as usize) <= n => {
                    zero_given.push((r as usize - 1, v, s.span.clone()))
                }
                _ => {
                    diags.push(Diagnostic::error(target.span.clone(), format!("ZERO[i] needs 1 <= i <= {n}")))
                }
            }
        } else {
            diags.push(
                Diagnostic::error(
                    target.span.clone(),
                    "expected U' = ... (a speed derivative) or ZERO[i] = ...",
                )
                .with_help("one equation per generalized speed"),
            );
        }
    }
    if !diags.is_empty() {
        return Err(report(hand_file, hand, diags));
    }
    let cfg = EquivalenceConfig::default();
    let fail =
        |e: crate::expr::ExprError| report(hand_file, hand, vec![Diagnostic::error(0..0, e.to_string())]);
    let mut out = Vec::new();
    let ar = &mut it.model.ar;
    let udot_syms: Vec<ExprId> = eqs.speed_derivatives.iter().map(|s| ar.symbol_expr(*s)).collect();
    if udot_given.iter().any(Option::is_some) {
        if let Some(missing) = udot_given.iter().position(Option::is_none) {
            return Err(report(
                hand_file,
                hand,
                vec![Diagnostic::error(0..0, format!("no equation for {}'", speed_names[missing]))
                    .with_help("the U' = ... form needs one equation for every generalized speed")],
            ));
        }
        let given: Vec<ExprId> = udot_given.iter().flatten().map(|(e, _)| *e).collect();
        for (r, name) in speed_names.iter().enumerate() {
            let mut terms = Vec::with_capacity(n);
            for (s, h) in given.iter().enumerate() {
                terms.push(ar.mul(&[eqs.mass_matrix[r][s], *h]).map_err(fail)?);
            }
            let lhs = ar.add(&terms).map_err(fail)?;
            let verdict = ar.equivalent(lhs, eqs.forcing[r], &cfg).map_err(fail)?;
            out.push(Comparison { label: format!("{name}'"), verdict });
        }
    }
    for (r, g, _) in zero_given {
        let mut terms = vec![eqs.forcing[r]];
        for (s, udot) in udot_syms.iter().enumerate() {
            let t = ar.mul(&[eqs.mass_matrix[r][s], *udot]).map_err(fail)?;
            terms.push(ar.neg(t).map_err(fail)?);
        }
        let derived = ar.add(&terms).map_err(fail)?;
        let verdict = ar.equivalent(g, derived, &cfg).map_err(fail)?;
        out.push(Comparison { label: format!("ZERO[{}]", r + 1), verdict });
    }
    Ok(out)
}
