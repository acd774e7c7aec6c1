//! Nonholonomic (motion) constraints: dependent speeds eliminated before Kane's method.
//!
//! Constraints `sum_k C_jk u_k + c_j = 0` are solved for the dependent speeds,
//! `u_d = A u_i + b`; velocities, accelerations and kinematic equations are then written in the
//! independent speeds, so their partial velocities are Kane's constrained partial velocities
//! `v_r + sum_d A_dr v_d` and `M u_i' = f` has one row per independent speed.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::model::{Model, MotionConstraints};
use super::vector::Vector;

impl Model {
    /// Declares motion constraints (each expression = 0, linear in the speeds) and the speeds
    /// they determine; call after the speeds and kinematic equations are set.
    pub fn set_motion_constraints(&mut self, constraints: &[ExprId], dependent: &[ExprId]) -> Result<()> {
        let dep: Vec<SymbolId> = dependent
            .iter()
            .map(|e| match self.ar.as_symbol(*e) {
                Some(s) if self.speeds.contains(&s) => Ok(s),
                _ => Err(MechanicsError::NotAVariable(self.ar.to_text(*e))),
            })
            .collect::<Result<_>>()?;
        if constraints.len() != dep.len() {
            return Err(MechanicsError::SingularConstraints);
        }
        // Constraints may be written with coordinate derivatives: apply q' = ... first.
        self.constraints = None;
        let qdot = self.dependent_map();
        let constraints = self.ar.subs_many(constraints, &qdot)?;
        let solution = match self.ar.solve_linear(&constraints, &dep) {
            Err(crate::expr::ExprError::SingularSystem) => return Err(MechanicsError::SingularConstraints),
            other => other?,
        };
        self.constraints = Some(MotionConstraints { dependent: dep, solution });
        let rules: Vec<(SymbolId, ExprId)> = self.kinematics.iter().map(|(q, r)| (*q, *r)).collect();
        for (q, rhs) in rules {
            let e = self.ar.symbol_expr(q);
            self.set_kinematics(e, rhs)?;
        }
        Ok(())
    }

    /// Records a holonomic (configuration) constraint `residual(q, t) = 0`; its value along a
    /// simulation is an output that shows how well the motion keeps it.
    pub fn add_configuration_constraint(&mut self, residual: ExprId) {
        self.configuration_constraints.push(residual);
    }

    /// The configuration constraints' residuals.
    pub fn configuration_residuals(&self) -> &[ExprId] {
        &self.configuration_constraints
    }

    /// The speeds that remain independent.
    pub fn independent_speeds(&self) -> Vec<SymbolId> {
        match &self.constraints {
            Some(c) => self.speeds.iter().copied().filter(|s| !c.dependent.contains(s)).collect(),
            None => self.speeds.clone(),
        }
    }

    /// Each dependent speed with its expression in the independent speeds.
    pub fn dependent_speeds(&self) -> Vec<(SymbolId, ExprId)> {
        match &self.constraints {
            Some(c) => c.dependent.iter().copied().zip(c.solution.iter().copied()).collect(),
            None => Vec::new(),
        }
    }

    /// Substitution of the dependent speeds by their solutions and of each declared coordinate
    /// derivative `q'` by its kinematic equation (written in the independent speeds).
    pub(crate) fn dependent_map(&mut self) -> FxHashMap<ExprId, ExprId> {
        let mut map: FxHashMap<ExprId, ExprId> =
            self.dependent_speeds().into_iter().map(|(s, e)| (self.ar.symbol_expr(s), e)).collect();
        let rules: Vec<(SymbolId, ExprId)> = self.kinematics.iter().map(|(q, r)| (*q, *r)).collect();
        for (q, rhs) in rules {
            let name = format!("{}'", self.ar.symbol_info(q).name);
            if let Some(qd) = self.ar.lookup(&name) {
                let rhs = self.ar.subs(rhs, &map).unwrap_or(rhs);
                let key = self.ar.symbol_expr(qd);
                map.insert(key, rhs);
            }
        }
        map
    }

    /// `e` with the dependent speeds eliminated.
    pub(crate) fn eliminate_dependent(&mut self, e: ExprId) -> Result<ExprId> {
        let map: FxHashMap<ExprId, ExprId> =
            self.dependent_speeds().into_iter().map(|(s, e)| (self.ar.symbol_expr(s), e)).collect();
        Ok(self.ar.subs(e, &map)?)
    }

    /// `v` with the dependent speeds eliminated and the kinematic equations applied.
    pub(crate) fn eliminate_dependent_vector(&mut self, v: &Vector) -> Result<Vector> {
        let map = self.dependent_map();
        if map.is_empty() {
            return Ok(v.clone());
        }
        let mut out = v.clone();
        for (_, m) in out.terms.iter_mut() {
            let r = self.ar.subs_many(m, &map)?;
            m.copy_from_slice(&r);
        }
        Ok(out)
    }
}
