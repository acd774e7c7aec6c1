//! The equations of a `CODE ALGEBRAIC(EQN, X, Y)` or `CODE NONLINEAR(EQN, X, Y)` request: the
//! array EQN as it stands at the request, and the unknowns, checked (square; linear in the
//! unknowns for ALGEBRAIC).

use crate::expr::SymbolId;

use super::super::algebraic::{AlgebraicSystem, SystemKind};
use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::{IResult, Interpreter};

impl Interpreter {
    /// The system `CODE kind(args)` asks for.
    pub(crate) fn algebraic_system(
        &mut self,
        kind: &str,
        args: &[Expr],
        span: &Span,
    ) -> IResult<AlgebraicSystem> {
        let usage = || format!("CODE {kind}(EQN, X, Y, ...) names an equation array, then the unknowns");
        let Some((first, unknown_args)) = args.split_first() else {
            return Err(Diagnostic::error(span.clone(), usage()));
        };
        let ExprKind::Name { name, .. } = &first.kind else {
            return Err(Diagnostic::error(first.span.clone(), usage()));
        };
        let equations = self.equations_named(&name.to_ascii_uppercase());
        let mut unknowns: Vec<SymbolId> = Vec::with_capacity(unknown_args.len());
        let mut names = Vec::with_capacity(unknown_args.len());
        for a in unknown_args {
            let x = self.scalar(a)?;
            let Some(s) = self.model.ar.as_symbol(x) else {
                return Err(Diagnostic::error(a.span.clone(), "an unknown must be a name"));
            };
            unknowns.push(s);
            names.push(self.model.ar.symbol_info(s).name.clone());
        }
        if equations.is_empty() || equations.len() != unknowns.len() {
            return Err(Diagnostic::error(
                span.clone(),
                format!(
                    "CODE {kind} solves as many equations as unknowns: {name} has {}, {} unknowns named",
                    equations.len(),
                    unknowns.len()
                ),
            )
            .with_help(format!("assign {name}[1], {name}[2], ... and name one unknown for each")));
        }
        let kind = if kind == "ALGEBRAIC" { SystemKind::Linear } else { SystemKind::Nonlinear };
        if kind == SystemKind::Linear {
            for (i, &e) in equations.iter().enumerate() {
                if self.model.ar.linear_coefficients(e, &unknowns).is_err() {
                    return Err(Diagnostic::error(
                        first.span.clone(),
                        format!(
                            "{name}[{}] is not linear in the unknowns, so CODE ALGEBRAIC cannot solve it",
                            i + 1
                        ),
                    )
                    .with_help("use CODE NONLINEAR, with starting values for the unknowns in INPUT"));
                }
            }
        }
        Ok(AlgebraicSystem { kind, equations, unknowns, names })
    }
}

impl super::LoadedModel {
    /// What `CODE ALGEBRAIC()` evaluates in a file without equations of motion: each OUTPUT
    /// (then ENCODE) quantity's name and value, a matrix entry by entry. An error names a
    /// quantity that is neither a scalar nor a matrix of scalars.
    pub fn output_evaluation(&self) -> Result<Vec<(String, crate::expr::ExprId)>, String> {
        let mut names: Vec<String> = Vec::new();
        for name in self.outputs.iter().map(|(n, _)| n).chain(&self.encoded) {
            if !names.iter().any(|n| n.eq_ignore_ascii_case(name)) {
                names.push(name.clone());
            }
        }
        if names.is_empty() {
            return Err("CODE ALGEBRAIC() evaluates the OUTPUT quantities, and the file names none: \
                        add an OUTPUT line before the CODE statement"
                .into());
        }
        let mut entries: Vec<(String, crate::expr::ExprId)> = Vec::new();
        for name in &names {
            match self.value(name) {
                Some(super::Value::Scalar(e)) => entries.push((name.clone(), e)),
                Some(super::Value::Matrix { rows, cols, data }) => entries.extend(
                    data.into_iter()
                        .enumerate()
                        .map(|(k, e)| (super::super::to_spec::matrix_entry_name(name, rows, cols, k), e)),
                ),
                Some(_) => {
                    return Err(format!(
                        "OUTPUT {name} is not a scalar or a matrix of scalars: output its components"
                    ))
                }
                None => return Err(format!("OUTPUT {name} has no value at the end of the file")),
            }
        }
        Ok(entries)
    }
}
