//! Nonholonomic (motion) constraints `A_d u_d + A_i u_i + b = 0`, kept as coefficients.
//!
//! Velocities and accelerations keep the dependent speeds `u_d` and their rates as symbols;
//! Kane's equations are formed over all speeds, and the constraint block
//! ([`super::SpeedConstraints`]) reduces them to the independent speeds numerically wherever
//! they are evaluated (a factorisation of `A_d` at each evaluation, never a symbolic inverse,
//! whose denominators vanish at symmetric states where `A_d` is regular). FR() and FRSTAR() of
//! the language, which are symbolic, use Cramer's rule, whose only denominator is `det A_d`.

use crate::expr::{ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::model::{Model, MotionConstraints};

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
        let qdot = self.kinematics_map();
        let residuals = self.ar.subs_many(constraints, &qdot)?;
        // Auxiliary speeds are zero in every motion the constraints restrict.
        let auxiliary = self.auxiliary_zero_map()?;
        let residuals = self.ar.subs_many(&residuals, &auxiliary)?;
        let independent: Vec<SymbolId> = self.speeds.iter().copied().filter(|s| !dep.contains(s)).collect();
        let (mut a_dependent, mut a_independent, mut b) = (Vec::new(), Vec::new(), Vec::new());
        for &r in &residuals {
            let all: Vec<SymbolId> = dep.iter().chain(&independent).copied().collect();
            let (coeffs, rest) = self.ar.linear_coefficients(r, &all)?;
            a_dependent.push(coeffs[..dep.len()].to_vec());
            a_independent.push(coeffs[dep.len()..].to_vec());
            b.push(rest);
        }
        if (0..dep.len()).any(|j| a_dependent.iter().all(|row| self.ar.is_zero(row[j]))) {
            return Err(MechanicsError::SingularConstraints);
        }
        self.constraints =
            Some(MotionConstraints { dependent: dep, residuals, a_dependent, a_independent, b });
        self.clear_kinematics_caches();
        Ok(())
    }

    /// Records a holonomic (configuration) constraint `residual(q, t) = 0`; its value along a
    /// simulation is an output that shows how well the motion keeps it.
    pub fn add_configuration_constraint(&mut self, residual: ExprId) {
        self.configuration_constraints.push(residual);
    }

    /// The motion constraints' residuals (linear in the speeds), in the order DEPENDENT gave
    /// them; empty without constraints.
    pub fn motion_residuals(&self) -> &[ExprId] {
        self.constraints.as_ref().map_or(&[], |c| &c.residuals)
    }

    /// The configuration constraints' residuals.
    pub fn configuration_residuals(&self) -> &[ExprId] {
        &self.configuration_constraints
    }

    /// The coordinates the configuration constraints determine, one per constraint: those whose
    /// rate is a dependent speed (`q' = u_d`) and that the constraints read, in the order the
    /// coordinates were declared.
    pub fn dependent_coordinates(&self) -> Result<Vec<SymbolId>> {
        if self.configuration_constraints.is_empty() {
            return Ok(Vec::new());
        }
        let dependent = self.dependent_speeds();
        let read = self.ar.free_symbols(&self.configuration_constraints);
        let found: Vec<SymbolId> = self
            .coordinates
            .iter()
            .copied()
            .filter(|q| read.contains(q))
            .filter(|q| {
                let rate = self.kinematics.get(q).and_then(|r| self.ar.as_symbol(*r));
                rate.is_some_and(|u| dependent.contains(&u))
            })
            .collect();
        if found.len() != self.configuration_constraints.len() {
            let names: Vec<&str> = found.iter().map(|q| self.ar.symbol_info(*q).name.as_str()).collect();
            return Err(MechanicsError::ConfigurationUnderdetermined {
                constraints: self.configuration_constraints.len(),
                found: found.len(),
                names: if names.is_empty() { "none".into() } else { names.join(", ") },
            });
        }
        Ok(found)
    }

    /// The speeds that remain independent.
    pub fn independent_speeds(&self) -> Vec<SymbolId> {
        match &self.constraints {
            Some(c) => self.speeds.iter().copied().filter(|s| !c.dependent.contains(s)).collect(),
            None => self.speeds.clone(),
        }
    }

    /// The dependent speeds and their rates as expressions in the independent speeds and rates
    /// (what Autolev prints after CONSTRAIN: `U2 = ...`, `U2' = ...`), keyed by the dependent
    /// speeds' and rates' symbols; empty without motion constraints. By Cramer's rule.
    pub fn dependent_speed_solution(&mut self) -> Result<rustc_hash::FxHashMap<ExprId, ExprId>> {
        let mut map = rustc_hash::FxHashMap::default();
        let Some(c) = self.constraints.clone() else { return Ok(map) };
        let independent = self.independent_speeds();
        let mut rhs = Vec::with_capacity(c.b.len());
        for (row, &b) in c.a_independent.iter().zip(&c.b) {
            let mut terms = vec![b];
            for (&a, &u) in row.iter().zip(&independent) {
                let u = self.ar.symbol_expr(u);
                terms.push(self.ar.mul(&[a, u])?);
            }
            let sum = self.ar.add(&terms)?;
            rhs.push(self.ar.neg(sum)?);
        }
        let solved = self.ar.solve_cramer(&c.a_dependent, &rhs)?;
        for (&u, &x) in c.dependent.iter().zip(&solved) {
            map.insert(self.ar.symbol_expr(u), x);
        }
        for (&u, &x) in c.dependent.iter().zip(&solved) {
            let rate = self.dt(x)?;
            // The kinematic equations may bring dependent speeds back in.
            let rate = self.ar.subs(rate, &map)?;
            let key = self.ar.derivative_symbol(u)?;
            map.insert(self.ar.symbol_expr(key), rate);
        }
        Ok(map)
    }

    /// The dependent speeds, in the order CONSTRAIN named them.
    pub fn dependent_speeds(&self) -> Vec<SymbolId> {
        self.constraints.as_ref().map(|c| c.dependent.clone()).unwrap_or_default()
    }

    /// The speeds Kane's equations are formed over: the independent ones, the dependent, then
    /// the auxiliary.
    pub(crate) fn kane_speeds(&self) -> Vec<SymbolId> {
        let mut all = self.independent_speeds();
        all.extend(self.dependent_speeds());
        all.extend(&self.auxiliary.speeds);
        all
    }

    /// Substitution of each declared coordinate derivative `q'` by its kinematic equation, the
    /// equations' own right-hand sides read through the others (`Q6' = f(Q7')` given before
    /// `Q7' = U7` reads `f(U7)`, as Autolev's code evaluates `Q7'` first).
    pub(crate) fn kinematics_map(&mut self) -> rustc_hash::FxHashMap<ExprId, ExprId> {
        let mut map = rustc_hash::FxHashMap::default();
        let rules: Vec<(SymbolId, ExprId)> = self.kinematics.iter().map(|(q, r)| (*q, *r)).collect();
        for (q, rhs) in rules {
            let name = format!("{}'", self.ar.symbol_info(q).name);
            if let Some(qd) = self.ar.lookup(&name) {
                let key = self.ar.symbol_expr(qd);
                map.insert(key, rhs);
            }
        }
        // A chain of equations is at most as long as there are coordinates.
        for _ in 0..map.len() {
            let mut changed = false;
            let entries: Vec<(ExprId, ExprId)> = map.iter().map(|(k, v)| (*k, *v)).collect();
            for (k, v) in entries {
                let Ok(read) = self.ar.subs(v, &map) else { continue };
                if read != v {
                    map.insert(k, read);
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        map
    }

    /// The motion constraints `A_d u_d + A_i u_i + b = 0` over the independent speeds `u_i` in
    /// their order, when the model has any.
    pub(crate) fn motion_constraint_rows(&self) -> Option<MotionConstraints> {
        self.constraints.clone()
    }

    /// `v` with the kinematic equations applied.
    pub(crate) fn eliminate_dependent_vector(&mut self, v: &super::Vector) -> Result<super::Vector> {
        let map = self.kinematics_map();
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

    /// `x = C^T y` for the constrained partial velocities' map `C = [I; -A_d^-1 A_i]`, by
    /// Cramer's rule: `y` has one entry per Kane speed (independent, then dependent), `x` one
    /// per independent speed. Symbolic, for FR() and FRSTAR(); evaluation never goes this way.
    pub(crate) fn constrain_symbolically(&mut self, y: &[ExprId]) -> Result<Vec<ExprId>> {
        let Some(c) = self.constraints.clone() else { return Ok(y.to_vec()) };
        // The auxiliary speeds' entries come last and stay as they are.
        let (y, auxiliary) = y.split_at(y.len() - self.auxiliary.speeds.len());
        let ni = y.len() - c.dependent.len();
        let (yi, yd) = y.split_at(ni);
        // x_r = y_r - sum_k (A_i)_kr z_k with A_d^T z = y_d, z = adj(A_d)^T y_d / det A_d.
        let ad_t: Vec<Vec<ExprId>> =
            (0..yd.len()).map(|i| (0..yd.len()).map(|j| c.a_dependent[j][i]).collect()).collect();
        let z = self.ar.solve_cramer(&ad_t, yd)?;
        let mut x = Vec::with_capacity(ni);
        for (r, &y_r) in yi.iter().enumerate() {
            let mut terms = vec![y_r];
            for (k, &z_k) in z.iter().enumerate() {
                let t = self.ar.mul(&[c.a_independent[k][r], z_k])?;
                terms.push(self.ar.neg(t)?);
            }
            x.push(self.ar.add(&terms)?);
        }
        x.extend(auxiliary);
        Ok(x)
    }
}
