//! Kane's equations solved for the speed rates as expressions (Autolev's `SOLVE(ZERO, U1', ...)`
//! read by name afterwards, `D(U1', Q1)` in a file's own linearisation): `M u' = f`, or with
//! motion constraints the dependent speeds `u_d = -A_d^-1 (A_i u_i + b)` and the reduced
//! `(C^T M C) u_i' = C^T (f - M g)` with `C = [I; -A_d^-1 A_i]`, `g = [0; -A_d^-1 bias]`, the
//! symbolic counterpart of [`super::rates`]. Every solve is Gauss-Jordan on the expression
//! graph, so the rates grow with the graph, never multiplied out.
//!
//! In: the equations. Out: [`SymbolicRates`], or an error for loads solved with the rates (those
//! stay numeric) and for a matrix singular in structure.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId};

use super::error::{MechanicsError, Result};
use super::kane::KaneEquations;

/// The speed rates and dependent speeds as expressions of the coordinates, the independent
/// speeds and the parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct SymbolicRates {
    /// `u'` of the independent speeds.
    pub speeds: Vec<ExprId>,
    /// The dependent speeds (empty without constraints).
    pub dependent: Vec<ExprId>,
    /// Their rates.
    pub dependent_rates: Vec<ExprId>,
}

impl KaneEquations {
    /// The rates as expressions.
    pub fn symbolic_rates(&self, ar: &mut Arena) -> Result<SymbolicRates> {
        if self.loads.is_some() {
            return Err(MechanicsError::RatesWithLoads);
        }
        let Some(c) = &self.constraints else {
            let f: Vec<Vec<ExprId>> = self.forcing.iter().map(|x| vec![*x]).collect();
            let speeds = ar.solve_matrix(&self.mass_matrix, &f)?.into_iter().map(|r| r[0]).collect();
            return Ok(SymbolicRates { speeds, dependent: Vec::new(), dependent_rates: Vec::new() });
        };
        let (ni, nd) = (self.speeds.len(), c.dependent.len());
        // u_d = -A_d^-1 (A_i u_i + b), and A_d^-1 A_i, all at once.
        let mut rhs: Vec<Vec<ExprId>> = Vec::with_capacity(nd);
        for (row, b) in c.a_independent.iter().zip(&c.b) {
            let mut terms = vec![*b];
            for (a, u) in row.iter().zip(&self.speeds) {
                let u = ar.symbol_expr(*u);
                terms.push(ar.mul(&[*a, u])?);
            }
            let sum = ar.add(&terms)?;
            let mut r = vec![ar.neg(sum)?];
            for a in row {
                r.push(ar.neg(*a)?);
            }
            rhs.push(r);
        }
        let solved = ar.solve_matrix(&c.a_dependent, &rhs)?;
        let dependent: Vec<ExprId> = solved.iter().map(|r| r[0]).collect();
        let cd: Vec<Vec<ExprId>> = solved.iter().map(|r| r[1..].to_vec()).collect();
        let map: FxHashMap<ExprId, ExprId> =
            c.dependent.iter().zip(&dependent).map(|(s, x)| (ar.symbol_expr(*s), *x)).collect();
        let bias = ar.subs_many(&c.bias, &map)?;
        let bias_rows: Vec<Vec<ExprId>> =
            bias.iter().map(|x| ar.neg(*x).map(|n| vec![n])).collect::<std::result::Result<_, _>>()?;
        let gd: Vec<ExprId> =
            ar.solve_matrix(&c.a_dependent, &bias_rows)?.into_iter().map(|r| r[0]).collect();
        let m: Vec<Vec<ExprId>> =
            self.mass_matrix.iter().map(|r| ar.subs_many(r, &map)).collect::<std::result::Result<_, _>>()?;
        let f = ar.subs_many(&self.forcing, &map)?;
        // C (n x ni) and g (n) over all speeds, independent first.
        let (zero, one) = (ar.zero(), ar.one());
        let mut cm: Vec<Vec<ExprId>> =
            (0..ni).map(|i| (0..ni).map(|j| if i == j { one } else { zero }).collect()).collect();
        cm.extend(cd.iter().cloned());
        let g: Vec<ExprId> = std::iter::repeat_n(zero, ni).chain(gd.iter().copied()).collect();
        let n = ni + nd;
        let mut mc = vec![vec![zero; ni]; n];
        let mut mg = vec![zero; n];
        for i in 0..n {
            for j in 0..ni {
                mc[i][j] = dot(ar, (0..n).map(|k| (m[i][k], cm[k][j])))?;
            }
            mg[i] = dot(ar, (0..n).map(|k| (m[i][k], g[k])))?;
        }
        let mut reduced = vec![vec![zero; ni]; ni];
        let mut forcing = Vec::with_capacity(ni);
        for r in 0..ni {
            for j in 0..ni {
                reduced[r][j] = dot(ar, (0..n).map(|k| (cm[k][r], mc[k][j])))?;
            }
            let rest: Vec<ExprId> =
                (0..n).map(|k| ar.sub(f[k], mg[k])).collect::<std::result::Result<_, _>>()?;
            forcing.push(vec![dot(ar, (0..n).map(|k| (cm[k][r], rest[k])))?]);
        }
        let speeds: Vec<ExprId> = ar.solve_matrix(&reduced, &forcing)?.into_iter().map(|r| r[0]).collect();
        let mut dependent_rates = Vec::with_capacity(nd);
        for (row, gk) in cd.iter().zip(&gd) {
            let carried = dot(ar, row.iter().copied().zip(speeds.iter().copied()))?;
            dependent_rates.push(ar.add(&[carried, *gk])?);
        }
        Ok(SymbolicRates { speeds, dependent, dependent_rates })
    }
}

/// `sum a_k b_k`.
fn dot(ar: &mut Arena, pairs: impl Iterator<Item = (ExprId, ExprId)>) -> Result<ExprId> {
    let mut terms = Vec::new();
    for (a, b) in pairs {
        if !ar.is_zero(a) && !ar.is_zero(b) {
            terms.push(ar.mul(&[a, b])?);
        }
    }
    Ok(ar.add(&terms)?)
}
