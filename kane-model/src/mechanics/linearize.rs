//! Linearization of `q' = k(q, u)`, `M u' = f` about an operating point: the state matrix A.

use nalgebra::{DMatrix, DVector};

use crate::expr::{ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::kane::KaneEquations;
use super::model::Model;

impl Model {
    /// The state matrix `A = d(x')/dx` for `x = (q, u)` at the point where symbols take the values
    /// `value_of` gives (every coordinate, speed and constant needs one).
    ///
    /// With `u'_0 = M^-1 f`: the speed rows are `M^-1 (df/dx - dM/dx u'_0)`.
    pub fn linearize(
        &mut self,
        eqs: &KaneEquations,
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
    ) -> Result<DMatrix<f64>> {
        let nq = eqs.coordinates.len();
        let nu = eqs.speeds.len();
        let state: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
        let nx = state.len();
        let eval = |ar: &crate::expr::Arena, e: ExprId| -> Result<f64> { Ok(ar.eval(&[e], value_of)?[0]) };
        let mass = DMatrix::from_fn(nu, nu, |i, j| eval(&self.ar, eqs.mass_matrix[i][j]).unwrap_or(f64::NAN));
        let forcing = DVector::from_fn(nu, |i, _| eval(&self.ar, eqs.forcing[i]).unwrap_or(f64::NAN));
        if mass.iter().chain(forcing.iter()).any(|x| !x.is_finite()) {
            // Re-evaluate one entry to surface the precise error (a missing value, say).
            for row in &eqs.mass_matrix {
                for &e in row {
                    eval(&self.ar, e)?;
                }
            }
            for &e in &eqs.forcing {
                eval(&self.ar, e)?;
            }
        }
        let lu = mass.clone().lu();
        let udot0 = lu.solve(&forcing).ok_or(MechanicsError::SingularMassMatrix)?;
        let mut a = DMatrix::zeros(nx, nx);
        for (j, &x) in state.iter().enumerate() {
            for (i, &k) in eqs.kinematics.iter().enumerate() {
                let d = self.ar.diff(k, x)?;
                a[(i, j)] = eval(&self.ar, d)?;
            }
            let mut rhs = DVector::zeros(nu);
            for r in 0..nu {
                let df = self.ar.diff(eqs.forcing[r], x)?;
                let mut v = eval(&self.ar, df)?;
                for s in 0..nu {
                    let dm = self.ar.diff(eqs.mass_matrix[r][s], x)?;
                    if !self.ar.is_zero(dm) {
                        v -= eval(&self.ar, dm)? * udot0[s];
                    }
                }
                rhs[r] = v;
            }
            let col = lu.solve(&rhs).ok_or(MechanicsError::SingularMassMatrix)?;
            for r in 0..nu {
                a[(nq + r, j)] = col[r];
            }
        }
        Ok(a)
    }
}
