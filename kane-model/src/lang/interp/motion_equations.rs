//! Equations of motion a file forms itself: `ZERO = FR() + FRSTAR()` (changed or not) then
//! `SOLVE(ZERO, U1', U2', ...)` for the rates of every independent speed, without KANE().
//!
//! In: the equations and their unknowns. Out: Kane's equations `M u' = f` read off them (the
//! coefficients of the rates and the rest), as KANE() would give them.

use crate::expr::{Equivalence, EquivalenceConfig, ExprId, SymbolId};

use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::{At, IResult, Interpreter};

impl Interpreter {
    /// Whether `unknowns` are the rates of the independent speeds, each once (the model's loads
    /// and constraints applied, as FR() applies them).
    pub(super) fn are_speed_rates(&mut self, unknowns: &[SymbolId]) -> bool {
        if !self.prepared {
            return false;
        }
        let speeds = self.model.independent_speeds();
        let Ok(rates) =
            speeds.iter().map(|u| self.model.ar.derivative_symbol(*u)).collect::<Result<Vec<_>, _>>()
        else {
            return false;
        };
        let mut seen: Vec<SymbolId> = Vec::with_capacity(unknowns.len());
        for s in unknowns {
            if !rates.contains(s) || seen.contains(s) {
                return false;
            }
            seen.push(*s);
        }
        seen.len() == rates.len()
    }

    /// `M u' = f` from `zero = f - M u' = 0`, the rows as written: the model's constraints
    /// must be absent (with them, write `ZERO = FR() + FRSTAR()` unchanged, or call KANE()).
    pub(super) fn equations_of_motion(&mut self, zero: &[ExprId], span: &Span) -> IResult<()> {
        let mut eqs = self.model.kane_unformed().at(span)?;
        if eqs.constraints.is_some() {
            return Err(Diagnostic::error(
                span.clone(),
                "SOLVE for the speeds' rates of equations other than FR() + FRSTAR() in a model with motion constraints is not supported",
            )
            .with_help("add forces and torques to the model before FR() and write ZERO = FR() + FRSTAR(), or call KANE()"));
        }
        let n = eqs.speed_derivatives.len();
        if zero.len() != n {
            return Err(Diagnostic::error(
                span.clone(),
                format!(
                    "{} equations for the rates of {n} speeds: SOLVE needs one equation per speed",
                    zero.len()
                ),
            ));
        }
        let (mut mass_matrix, mut forcing) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for &row in zero {
            let (coeffs, rest) = self.model.ar.linear_coefficients(row, &eqs.speed_derivatives).at(span)?;
            let negated =
                coeffs.iter().map(|c| self.model.ar.neg(*c)).collect::<Result<Vec<_>, _>>().at(span)?;
            mass_matrix.push(negated);
            forcing.push(rest);
        }
        self.check_symmetric(&mass_matrix, span)?;
        eqs.mass_matrix = mass_matrix;
        eqs.forcing = forcing;
        eqs.formed = true;
        self.equations = Some(eqs);
        Ok(())
    }

    /// The generated solvers factor `M` as symmetric: a matrix that is not is an error.
    fn check_symmetric(&mut self, m: &[Vec<ExprId>], span: &Span) -> IResult<()> {
        let config = EquivalenceConfig::default();
        for (r, row) in m.iter().enumerate() {
            for (s, &upper) in row.iter().enumerate().skip(r + 1) {
                if matches!(
                    self.model.ar.equivalent(upper, m[s][r], &config).at(span)?,
                    Equivalence::Differs { .. }
                ) {
                    return Err(Diagnostic::error(
                        span.clone(),
                        format!(
                            "the coefficients of the speeds' rates are not symmetric (row {}, column {} differs from row {}, column {}), as Kane's mass matrix is",
                            r + 1, s + 1, s + 1, r + 1
                        ),
                    )
                    .with_help("keep each equation's rates as FRSTAR() gives them; add only forces to FR() + FRSTAR()"));
                }
            }
        }
        Ok(())
    }
}
