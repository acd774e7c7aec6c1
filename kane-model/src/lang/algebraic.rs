//! Algebraic and nonlinear equations a file asks to be solved (`CODE ALGEBRAIC(EQN, X, Y)`,
//! `CODE NONLINEAR(EQN, X, Y)`), solved numerically at the file's INPUT values: in come the
//! equations, the unknowns and every other symbol's value; out go the unknowns' values, or an
//! error that says why there are none (a value missing, a singular Jacobian, no convergence).
//!
//! Linear systems are solved by LU with full pivoting; nonlinear ones by Newton's method from
//! the unknowns' INPUT values, the Jacobian derived symbolically, each step halved until the
//! residual falls (at most [`MAX_ITERATIONS`] steps).

use nalgebra::{DMatrix, DVector};
use thiserror::Error;

use crate::expr::{Arena, ExprError, ExprId, SymbolId};
use crate::mechanics::reciprocal_condition;

/// Most Newton steps before a nonlinear solve gives up.
pub const MAX_ITERATIONS: usize = 50;
/// A Jacobian whose reciprocal condition number is below this is singular.
const SINGULAR_RCOND: f64 = 1e-14;
/// Converged when the largest residual is below this times the residual scale.
pub const TOLERANCE: f64 = 1e-13;

/// Linear (CODE ALGEBRAIC) or not (CODE NONLINEAR).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SystemKind {
    /// Linear in the unknowns.
    Linear,
    /// Solved by Newton's method from starting values.
    Nonlinear,
}

/// Equations (each `= 0`) and as many unknowns.
#[derive(Clone, Debug, PartialEq)]
pub struct AlgebraicSystem {
    /// Linear or not.
    pub kind: SystemKind,
    /// The equations.
    pub equations: Vec<ExprId>,
    /// The unknowns.
    pub unknowns: Vec<SymbolId>,
    /// The unknowns' names.
    pub names: Vec<String>,
}

/// A solved system.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The unknowns' values, in the order named.
    pub values: Vec<f64>,
    /// Newton steps taken (1 for a linear system).
    pub iterations: usize,
    /// The largest residual at the solution.
    pub residual: f64,
}

/// Why a system has no solution to print.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum AlgebraicError {
    /// An equation could not be evaluated (a value missing, a division by zero).
    #[error("{0}")]
    Eval(#[from] ExprError),
    /// A nonlinear unknown has no starting value.
    #[error("CODE NONLINEAR needs a starting value for {0}: give it in INPUT or with --set {0}=VALUE")]
    NoStart(String),
    /// The Jacobian is singular where the solve stands.
    #[error("the Jacobian of the equations is singular at {at} (reciprocal condition number {rcond:e}): the equations do not determine the unknowns there{hint}")]
    Singular {
        /// The unknowns' values.
        at: String,
        /// Its reciprocal condition number.
        rcond: f64,
        /// What to try.
        hint: &'static str,
    },
    /// Newton's method did not converge.
    #[error("Newton's method did not converge in {iterations} steps: the largest residual is {residual:e} at {at}; try other starting values, or check that the equations have a solution")]
    NoConvergence {
        /// Steps taken.
        iterations: usize,
        /// The largest residual reached.
        residual: f64,
        /// The unknowns' values there.
        at: String,
    },
}

impl AlgebraicSystem {
    /// Solves the system where `value_of` gives every other symbol's value (and, for a
    /// nonlinear system, the unknowns' starting values).
    pub fn solve(
        &self,
        ar: &mut Arena,
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
    ) -> Result<Solution, AlgebraicError> {
        let n = self.unknowns.len();
        let jacobian: Vec<ExprId> = self
            .equations
            .iter()
            .flat_map(|e| self.unknowns.iter().map(move |u| (*e, *u)))
            .map(|(e, u)| ar.diff(e, u))
            .collect::<Result<_, _>>()?;
        let mut x = vec![0.0; n];
        if self.kind == SystemKind::Nonlinear {
            for (k, u) in self.unknowns.iter().enumerate() {
                x[k] = value_of(*u).ok_or_else(|| AlgebraicError::NoStart(self.names[k].clone()))?;
            }
        }
        let ar = &*ar;
        let eval = |roots: &[ExprId], x: &[f64]| -> Result<Vec<f64>, ExprError> {
            ar.eval(roots, |s| match self.unknowns.iter().position(|u| *u == s) {
                Some(k) => Some(x[k]),
                None => value_of(s),
            })
        };
        let largest = |r: &[f64]| crate::assembly::largest_magnitude(0.0, r);
        let mut r = eval(&self.equations, &x)?;
        let scale = 1.0 + largest(&eval(&jacobian, &x)?) * largest(&x).max(1.0);
        // A linear system takes one step and one step of refinement.
        let steps = if self.kind == SystemKind::Linear { 2 } else { MAX_ITERATIONS };
        for iteration in 0..steps {
            if largest(&r) <= TOLERANCE * scale && iteration > 0 {
                return Ok(Solution { values: x, iterations: iteration, residual: largest(&r) });
            }
            let j = eval(&jacobian, &x)?;
            let step = self.newton_step(&j, &r, &x)?;
            let mut t = 1.0;
            loop {
                let trial: Vec<f64> = x.iter().zip(&step).map(|(a, d)| a + t * d).collect();
                let rt = eval(&self.equations, &trial)?;
                if largest(&rt) < largest(&r) || t < 1e-4 || self.kind == SystemKind::Linear {
                    (x, r) = (trial, rt);
                    break;
                }
                t /= 2.0;
            }
        }
        if largest(&r) <= TOLERANCE * scale || self.kind == SystemKind::Linear {
            return Ok(Solution { values: x, iterations: steps, residual: largest(&r) });
        }
        Err(AlgebraicError::NoConvergence { iterations: steps, residual: largest(&r), at: self.at(&x) })
    }

    /// `dx` with `J dx = -r` (J row-major), or the named singular Jacobian.
    fn newton_step(&self, j: &[f64], r: &[f64], x: &[f64]) -> Result<Vec<f64>, AlgebraicError> {
        let n = r.len();
        let jm = DMatrix::from_row_slice(n, n, j);
        let rcond = reciprocal_condition(n, j);
        let singular = || AlgebraicError::Singular {
            at: self.at(x),
            rcond,
            hint: match self.kind {
                SystemKind::Linear => "",
                SystemKind::Nonlinear => "; try other starting values",
            },
        };
        if rcond.is_nan() || rcond < SINGULAR_RCOND {
            return Err(singular());
        }
        let minus_r = -DVector::from_column_slice(r);
        let dx = jm.full_piv_lu().solve(&minus_r).ok_or_else(singular)?;
        Ok(dx.iter().copied().collect())
    }

    /// `X = 1, Y = 2`.
    fn at(&self, x: &[f64]) -> String {
        self.names.iter().zip(x).map(|(n, v)| format!("{n} = {v}")).collect::<Vec<_>>().join(", ")
    }
}
