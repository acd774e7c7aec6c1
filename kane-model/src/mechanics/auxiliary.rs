//! Auxiliary speeds and the loads they bring into evidence (Autolev's `AUXILIARY[]`,
//! `CONSTRAIN(AUXILIARY[...])` and `KANE(T1, ...)`).
//!
//! An auxiliary speed enters velocities (a joint's or a contact point's) so that partial
//! velocities exist for it, and is zero in every motion. Kane's equations are formed over the
//! model's speeds and the auxiliary ones; then the auxiliary speeds and their rates are set to
//! zero. The unknown loads `T` (a joint torque that makes a prescribed motion happen, a contact
//! force) enter `f` linearly: `f = f0 + B T`. The speed rows and the auxiliary rows together,
//! `M u' - B T = f0`, are as many equations as there are rates and loads, solved numerically at
//! each evaluation. With motion constraints, `u' = C u_i' + g` and the speed rows are reduced
//! by `C^T` as without loads.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::kane::{KaneEquations, SolvedLoads};
use super::model::Model;

impl Model {
    /// Declares auxiliary speeds (speeds the model declared, zero in every motion); they stop
    /// being states.
    pub fn set_auxiliary_speeds(&mut self, speeds: &[ExprId]) -> Result<()> {
        let mut aux = Vec::with_capacity(speeds.len());
        for &e in speeds {
            match self.ar.as_symbol(e) {
                Some(s) if self.speeds.contains(&s) || self.auxiliary.speeds.contains(&s) => aux.push(s),
                _ => return Err(MechanicsError::NotASpeed(self.ar.to_text(e))),
            }
        }
        self.speeds.append(&mut self.auxiliary.speeds);
        self.speeds.retain(|s| !aux.contains(s));
        self.auxiliary.speeds = aux;
        self.clear_kinematics_caches();
        Ok(())
    }

    /// Declares the loads Kane's equations are solved for together with the speed rates (time
    /// functions the loads and forces of the model contain linearly).
    pub fn set_solved_loads(&mut self, loads: &[ExprId]) -> Result<()> {
        self.auxiliary.loads = loads
            .iter()
            .map(|&e| self.ar.as_symbol(e).ok_or_else(|| MechanicsError::NotAVariable(self.ar.to_text(e))))
            .collect::<Result<_>>()?;
        Ok(())
    }

    /// The auxiliary speeds.
    pub fn auxiliary_speeds(&self) -> &[SymbolId] {
        &self.auxiliary.speeds
    }

    /// Each auxiliary speed and its rate, mapped to zero.
    pub fn auxiliary_zero_map(&mut self) -> Result<FxHashMap<ExprId, ExprId>> {
        let zero = self.ar.zero();
        let mut map = FxHashMap::default();
        for s in self.auxiliary.speeds.clone() {
            map.insert(self.ar.symbol_expr(s), zero);
            let rate = self.ar.derivative_symbol(s)?;
            map.insert(self.ar.symbol_expr(rate), zero);
        }
        Ok(map)
    }

    /// `eqs` formed over the speeds and the auxiliary speeds, split: `M` and `f` over the
    /// speeds (loads zero), the auxiliary rows and `B` into [`SolvedLoads`].
    pub(crate) fn split_auxiliary(&mut self, eqs: &mut KaneEquations) -> Result<()> {
        let (aux, loads) = (self.auxiliary.speeds.clone(), self.auxiliary.loads.clone());
        if aux.is_empty() && loads.is_empty() {
            return Ok(());
        }
        if aux.len() != loads.len() {
            return Err(MechanicsError::AuxiliaryCount { auxiliary: aux.len(), loads: loads.len() });
        }
        let zero = self.auxiliary_zero_map()?;
        let n = eqs.mass_matrix.len() - aux.len();
        let mut mass: Vec<Vec<ExprId>> = Vec::with_capacity(n + aux.len());
        for row in &eqs.mass_matrix {
            mass.push(self.ar.subs_many(&row[..n], &zero)?);
        }
        let forcing = self.ar.subs_many(&eqs.forcing, &zero)?;
        let (mut load_columns, mut f0) =
            (Vec::with_capacity(forcing.len()), Vec::with_capacity(forcing.len()));
        for (r, &f) in forcing.iter().enumerate() {
            let (coeffs, rest) = self.ar.linear_coefficients(f, &loads).map_err(|e| match e {
                crate::expr::ExprError::NotLinear { symbol, .. } => {
                    MechanicsError::LoadNotLinear(symbol, r + 1)
                }
                other => other.into(),
            })?;
            load_columns.push(coeffs);
            f0.push(rest);
        }
        let mass_rows = mass.split_off(n);
        let aux_forcing = f0.split_off(n);
        eqs.mass_matrix = mass;
        eqs.forcing = f0;
        eqs.loads =
            Some(SolvedLoads { loads, auxiliary: aux, mass_rows, forcing: aux_forcing, load_columns });
        Ok(())
    }
}
