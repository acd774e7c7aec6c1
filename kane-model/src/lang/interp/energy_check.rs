//! `NICHECK()`: Autolev's energy check of a model's equations.
//!
//! In: no arguments, a model whose loads and masses are set. Out: the scalar `WCHECKn + KE()`,
//! where `WCHECKn` is a new variable (the first such name free, 0 at the start) whose rate is
//! minus the power of the active forces, `-sum FR_r u_r` over the independent speeds: along a
//! motion of a model with workless constraints the value stays what it was at the start.

use super::super::ast::Expr;
use super::super::diagnostic::Diagnostic;
use super::value::Value;
use super::{At, Binding, IResult, InputValue, Interpreter};

impl Interpreter {
    /// `NICHECK()`: a new variable for minus the work of the active forces, plus KE().
    pub(super) fn energy_check(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail = &e.span;
        if !args.is_empty() {
            return Err(Diagnostic::error(e.span.clone(), "NICHECK takes no arguments: NICHECK()"));
        }
        self.prepare(fail)?;
        let forces = self.model.generalized_active_forces().at(fail)?;
        let speeds = self.model.independent_speeds();
        let mut terms = Vec::with_capacity(speeds.len());
        for (&f, &u) in forces.iter().zip(&speeds) {
            let u = self.model.ar.symbol_expr(u);
            terms.push(self.model.ar.mul(&[f, u]).at(fail)?);
        }
        let power = self.model.ar.add(&terms).at(fail)?;
        let rate = self.model.ar.neg(power).at(fail)?;
        let Value::Scalar(rate) = self.in_independent_speeds(&Value::Scalar(rate), fail)? else {
            unreachable!("a scalar stays a scalar")
        };
        let name = (1..)
            .map(|n| format!("WCHECK{n}"))
            .find(|n| !self.bindings.contains_key(n) && self.model.ar.lookup(n).is_none())
            .expect("a free name");
        let work = self.model.ar.variable(&name).at(fail)?;
        self.bindings.insert(name.clone(), Binding::Symbol(work, 1));
        let s = self.model.ar.as_symbol(work).expect("a variable is a symbol");
        self.kinematic.push((s, rate));
        self.model.set_kinematics(work, rate).at(fail)?;
        self.inputs.push(InputValue { name, value: 0.0, unit: None, span: e.span.clone() });
        let ke = self.model.kinetic_energy().at(fail)?;
        Ok(Value::Scalar(self.model.ar.add(&[work, ke]).at(fail)?))
    }
}
