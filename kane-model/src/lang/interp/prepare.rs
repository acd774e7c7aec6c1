//! Getting the model ready for FR(), FRSTAR(), KE(), MOMENTUM() and KANE(): the loads applied,
//! gravity on each mass, and the generalized coordinates, speeds and constraints decided.
//!
//! In: the forces, torques, gravity, kinematic equations and constraints the file gave so far.
//! Out: the model's loads, coordinates, speeds and motion constraints set (once per change).

use crate::expr::{ExprId, SymbolId, SymbolKind};

use super::super::token::Span;
use super::{At, Binding, IResult, Interpreter};

impl Interpreter {
    /// Applies the loads and decides the generalized coordinates and speeds (once per change).
    pub(crate) fn prepare(&mut self, span: &Span) -> IResult<()> {
        if self.prepared {
            return Ok(());
        }
        self.settle_inertias()?;
        self.apply_loads(span)?;
        self.chain_kinematics()?;
        self.choose_state(span)?;
        if !self.auxiliary_speeds.is_empty() {
            let aux = self.auxiliary_speeds.clone();
            self.model.set_auxiliary_speeds(&aux).at(span)?;
        }
        if !self.dependent.is_empty() || !self.dependent_speeds.is_empty() {
            let (c, d) = (self.dependent.clone(), self.dependent_speeds.clone());
            self.model.set_motion_constraints(&c, &d).at(span)?;
        }
        self.prepared = true;
        Ok(())
    }

    /// The kinematic equations that angular velocities assigned in speeds through chains of
    /// orientations imply, for the chains' coordinates still without one.
    fn chain_kinematics(&mut self) -> IResult<()> {
        for (frame, reference, w, at) in self.chain_speeds.clone() {
            let set = self.model.chain_kinematics(frame, reference, &w).at(&at)?;
            self.kinematic.extend(set);
        }
        Ok(())
    }

    /// The model's loads: the resultant forces and torques, then gravity on every mass given.
    fn apply_loads(&mut self, span: &Span) -> IResult<()> {
        self.model.clear_loads();
        for (p, f) in self.forces.clone() {
            self.model.add_force(p, f);
        }
        for (fr, t) in self.torques.clone() {
            self.model.add_torque(fr, t);
        }
        match self.gravity.clone() {
            Some((g, None)) => self.model.add_gravity_to_given_masses(&g).at(span)?,
            Some((g, Some(only))) => self.model.add_gravity_to(&g, &only).at(span)?,
            None => {}
        }
        Ok(())
    }

    /// Coordinates: variables with a kinematic equation, and variables declared to second order
    /// without one (their speed is their derivative). Speeds: first-order variables that are not
    /// coordinates. Where MOTIONVARIABLES declared some, only those are speeds or second-order
    /// coordinates (a file's other VARIABLES X' are quantities whose rates it may give later).
    fn choose_state(&mut self, span: &Span) -> IResult<()> {
        let ruled: Vec<SymbolId> = self.kinematic.iter().map(|(q, _)| *q).collect();
        let motion = self.motion_variables.clone();
        let mut coords = Vec::new();
        let mut speeds = Vec::new();
        for (s, order) in self.declared_variables() {
            if ruled.contains(&s) {
                coords.push(s);
            } else if !motion.is_empty() && !motion.contains(&s) {
                continue;
            } else if order >= 2 {
                coords.push(s);
                let d = self.model.ar.derivative_symbol(s).at(span)?;
                speeds.push(d);
                let (q, qd) = (self.model.ar.symbol_expr(s), self.model.ar.symbol_expr(d));
                self.model.set_kinematics(q, qd).at(span)?;
            } else if order == 1 {
                speeds.push(s);
            }
        }
        // Speeds that are kinematic right-hand sides come first in declaration order already.
        let q: Vec<ExprId> = coords.iter().map(|s| self.model.ar.symbol_expr(*s)).collect();
        let u: Vec<ExprId> = speeds.iter().map(|s| self.model.ar.symbol_expr(*s)).collect();
        self.model.set_coordinates(&q).at(span)?;
        self.model.set_speeds(&u).at(span)
    }

    /// The declared time-dependent variables with their declared derivative orders, sorted.
    fn declared_variables(&self) -> Vec<(SymbolId, u8)> {
        let mut v: Vec<(SymbolId, u8)> = self
            .bindings
            .values()
            .filter_map(|b| match b {
                Binding::Symbol(e, order) => self.model.ar.as_symbol(*e).map(|s| (s, *order)),
                _ => None,
            })
            .filter(|(s, _)| matches!(self.model.ar.symbol_info(*s).kind, SymbolKind::Variable { order: 0 }))
            .collect();
        v.sort();
        v
    }
}
