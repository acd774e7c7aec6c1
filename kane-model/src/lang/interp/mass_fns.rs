//! Functions of the masses and loads: FR, FRSTAR, KE, MOMENTUM, MASS, CM and INERTIA.
//!
//! In: the upper-cased function name and its arguments (bodies and particles by name, or none
//! for all of them; points by name). Out: a [`Value`]; the sums over masses are the mechanics
//! layer's (`total_mass`, `center_of_mass`, `linear_momentum`, `angular_momentum`,
//! `kinetic_energy`), given the [`MassView`]s chosen here.

use crate::mechanics::{Dyadic, MassId, MassView};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::Value;
use super::{entity_key, At, Binding, IResult, Interpreter};

impl Interpreter {
    /// FR, FRSTAR, KE, MOMENTUM, MASS, CM, INERTIA.
    pub(super) fn mass_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        match upper {
            "FR" | "FRSTAR" => {
                self.prepare(&e.span)?;
                self.forces_formed = true;
                let v = if upper == "FR" {
                    self.model.generalized_active_forces()
                } else {
                    self.model.generalized_inertia_forces()
                }
                .at(fail)?;
                Ok(Value::column(v))
            }
            "KE" => {
                self.prepare(&e.span)?;
                let ke = if args.is_empty() {
                    self.model.kinetic_energy()
                } else {
                    let masses = self.mass_list(args, &e.span)?;
                    self.model.kinetic_energy_of(&masses)
                };
                Ok(Value::Scalar(ke.at(fail)?))
            }
            "MOMENTUM" => self.momentum(args, e),
            "MASS" => {
                let masses = self.mass_list(args, &e.span)?;
                Ok(Value::Scalar(self.model.total_mass(&masses).at(fail)?))
            }
            "CM" => {
                let origin = self.point_arg(
                    args.first().ok_or_else(|| Diagnostic::error(e.span.clone(), "CM needs a point"))?,
                )?;
                let masses = self.mass_list(&args[1..], &e.span)?;
                Ok(Value::Vector(self.model.center_of_mass(origin, &masses).at(fail)?))
            }
            _ => self.inertia_about(args, e),
        }
    }

    /// `MOMENTUM(LINEAR [, B, P, ...])` or `MOMENTUM(ANGULAR, O [, B, P, ...])`, in the
    /// Newtonian frame, of the masses named or of all of them.
    fn momentum(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        self.prepare(&e.span)?;
        let which = match args.first().map(|a| &a.kind) {
            Some(ExprKind::Name { name, .. }) => name.to_ascii_uppercase(),
            _ => String::new(),
        };
        let n = self.model.newtonian();
        match which.as_str() {
            "ANGULAR" if args.len() >= 2 => {
                let o = self.point_arg(&args[1])?;
                let masses = self.mass_list(&args[2..], &e.span)?;
                Ok(Value::Vector(self.model.angular_momentum_of(&masses, o, n).at(fail)?))
            }
            "LINEAR" => {
                let masses = self.mass_list(&args[1..], &e.span)?;
                Ok(Value::Vector(self.model.linear_momentum(&masses, n).at(fail)?))
            }
            _ => Err(Diagnostic::error(
                e.span.clone(),
                "MOMENTUM takes (LINEAR [, masses]) or (ANGULAR, point [, masses])",
            )),
        }
    }

    /// `INERTIA(O [, B, P, ...])`: the inertia dyadic about O of the named bodies and
    /// particles, or of all of them.
    fn inertia_about(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let origin = self.point_arg(
            args.first().ok_or_else(|| Diagnostic::error(e.span.clone(), "INERTIA needs a point"))?,
        )?;
        let names: Vec<String> = if args.len() > 1 {
            args[1..]
                .iter()
                .map(|a| match &a.kind {
                    ExprKind::Name { name, .. } => Ok(name.to_ascii_uppercase()),
                    _ => Err(Diagnostic::error(a.span.clone(), "expected a body or particle name")),
                })
                .collect::<IResult<_>>()?
        } else {
            self.masses_by_name().into_iter().map(|view| view.name).collect()
        };
        let origin_name = self.model.point_name(origin).to_string();
        let mut total = Dyadic::zero();
        for n in names {
            let key = format!("I_{n}_{origin_name}");
            let b = self.builtin(&key, 2).ok_or_else(|| {
                Diagnostic::error(e.span.clone(), format!("`{n}` is not a body or particle"))
            })?;
            let Value::Dyadic(d) = self.builtin_value(b, &e.span)? else { continue };
            total = self.model.add_dyadics(&total, &d).at(&e.span)?;
        }
        Ok(Value::Dyadic(total))
    }

    /// Every body and particle, in the order of their names (the order sums over all masses
    /// take, so that results do not depend on the order of declaration).
    fn masses_by_name(&self) -> Vec<MassView> {
        let mut all: Vec<MassView> = self.model.masses().collect();
        all.sort_by(|a, b| a.name.cmp(&b.name));
        all
    }

    /// The named bodies and particles, or all of them (by name) when none are named; each must
    /// have a mass.
    fn mass_list(&mut self, args: &[Expr], span: &Span) -> IResult<Vec<MassView>> {
        let mut out = Vec::new();
        if args.is_empty() {
            for view in self.masses_by_name() {
                out.push(with_mass(view, span)?);
            }
        }
        for (a, id) in args.iter().zip(self.mass_ids(args)?) {
            out.push(with_mass(self.model.mass_view(id), &a.span)?);
        }
        Ok(out)
    }

    /// The bodies and particles `args` name.
    pub(super) fn mass_ids(&self, args: &[Expr]) -> IResult<Vec<MassId>> {
        let mut out = Vec::with_capacity(args.len());
        for a in args {
            let ExprKind::Name { name, .. } = &a.kind else {
                return Err(Diagnostic::error(a.span.clone(), "expected a body or particle name"));
            };
            let key = name.to_ascii_uppercase();
            out.push(match self.bindings.get(&entity_key(&key)) {
                Some(Binding::Body(b)) => MassId::Body(*b),
                Some(Binding::Particle(p)) => MassId::Particle(*p),
                _ => {
                    return Err(Diagnostic::error(
                        a.span.clone(),
                        format!("`{key}` is not a body or particle"),
                    )
                    .with_help("name bodies and particles declared with BODIES or PARTICLES"))
                }
            });
        }
        Ok(out)
    }
}

/// The view, or an error at `span` when its mass has not been given.
fn with_mass(view: MassView, span: &Span) -> IResult<MassView> {
    match view.mass {
        Some(_) => Ok(view),
        None => Err(Diagnostic::error(span.clone(), format!("{} has no mass", view.name))),
    }
}
