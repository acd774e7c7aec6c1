//! Lowering: in comes a [`ModelSpec`]; out goes a [`Program`] (straight-line sections for
//! `param_constants`, `rhs` and each output) with the parameters it reads. Nothing here knows
//! Rust.

mod choose;
mod constrained;
mod explicit;
mod hoist;
mod householder;
mod inverse;
mod ldlt;
mod outputs;
mod rhs;
mod solve;

use crate::expr::{ExprId, SymbolId, SymbolKind};
use crate::spec::ModelSpec;

use super::ir::Program;
use super::LowerError;

/// A lowered program and the symbols it reads.
#[derive(Clone, Debug)]
pub struct Lowered {
    /// The program.
    pub program: Program,
    /// The parameters, in the order `Input::Param` indexes them.
    pub params: Vec<SymbolId>,
    /// The states, coordinates then speeds.
    pub states: Vec<SymbolId>,
    /// True when `rhs` is the order-n form (explicit `u'`), false for the mass-matrix form.
    pub order_n: bool,
}

/// Lowers `spec`: the mass-matrix form (the equations simplified, collected by state monomial,
/// parameter-only parts hoisted into `param_constants`, the solve of `M u' = f` and every output
/// lowered) or, for a tree of simple rotations where it takes fewer operations, the order-n form.
pub fn lower(spec: &mut ModelSpec) -> Result<Lowered, LowerError> {
    choose::lower(spec)
}

/// The mass-matrix form of `spec` lowered.
fn mass_matrix(spec: &mut ModelSpec) -> Result<Lowered, LowerError> {
    spec.model.form_equations(&mut spec.equations)?;
    let mut eqs = spec.equations.clone();
    // Generated code runs many times: the collected form is worth its derivation cost.
    spec.model.simplify_equations(&mut eqs)?;
    let states = spec.states();
    let mut all: Vec<ExprId> = eqs.mass_matrix.iter().flatten().copied().collect();
    all.extend(&eqs.forcing);
    all.extend(&eqs.kinematics);
    let mut computed = eqs.speed_derivatives.clone();
    if let Some(c) = &eqs.constraints {
        computed.extend(c.dependent.iter().chain(&c.dependent_rates));
        all.extend(c.a_dependent.iter().chain(&c.a_independent).flatten().chain(&c.b).chain(&c.bias));
    }
    if let Some(l) = &eqs.loads {
        computed.extend(&l.loads);
        all.extend(inverse::load_roots(l));
    }
    let rhs_free = spec.model.ar.free_symbols(&all);
    for o in &spec.outputs {
        all.extend(&o.components);
    }
    let params = parameters(spec, &all, &states, &computed)?;
    let (param_constants, rhs) = match (&eqs.constraints, &eqs.loads) {
        (Some(c), _) => constrained::lower(&mut spec.model.ar, &eqs, c, &params)?,
        (None, Some(l)) => inverse::lower(&mut spec.model.ar, &eqs, l, &params)?,
        (None, None) => rhs::lower(&mut spec.model.ar, &eqs, &params)?,
    };
    let outputs = outputs::lower(spec, &params)?;
    let nq = eqs.coordinates.len();
    let cyclic = (0..nq).filter(|i| !rhs_free.contains(&states[*i])).collect();
    let program = Program { param_constants, rhs, outputs, cyclic, n_coordinates: nq };
    Ok(Lowered { program, params, states, order_n: false })
}

/// The order-n form of `spec` lowered, when the model is a tree it fits.
fn order_n(spec: &mut ModelSpec) -> Result<Option<Lowered>, LowerError> {
    let Some(rates) = spec.model.order_n_rates(&spec.equations)? else { return Ok(None) };
    let eqs = &spec.equations;
    let (kinematics, speeds, rate_symbols) =
        (eqs.kinematics.clone(), eqs.speeds.clone(), eqs.speed_derivatives.clone());
    let states = spec.states();
    let mut all: Vec<ExprId> = rates.clone();
    all.extend(&kinematics);
    let rhs_free = spec.model.ar.free_symbols(&all);
    for o in &spec.outputs {
        all.extend(&o.components);
    }
    let params = parameters(spec, &all, &states, &rate_symbols)?;
    let form =
        explicit::Explicit { states: &states, speeds: &speeds, kinematics: &kinematics, rates: &rates };
    let (param_constants, rhs) = explicit::lower(&mut spec.model.ar, &form, &params)?;
    let outputs = outputs::lower(spec, &params)?;
    let nq = kinematics.len();
    let cyclic = (0..nq).filter(|i| !rhs_free.contains(&states[*i])).collect();
    let program = Program { param_constants, rhs, outputs, cyclic, n_coordinates: nq };
    Ok(Some(Lowered { program, params, states, order_n: true }))
}

/// The constants `roots` read, in order of first appearance; an error for a time-dependent
/// symbol that is neither a state nor computed by the program (`rates`: speed rates, and
/// dependent speeds with their rates).
fn parameters(
    spec: &ModelSpec,
    roots: &[ExprId],
    states: &[SymbolId],
    rates: &[SymbolId],
) -> Result<Vec<SymbolId>, LowerError> {
    let ar = &spec.model.ar;
    let mut params = Vec::new();
    for s in ar.free_symbols(roots) {
        match ar.symbol_info(s).kind {
            SymbolKind::Constant => params.push(s),
            SymbolKind::Time => {}
            _ if states.contains(&s) || rates.contains(&s) => {}
            _ if spec.inputs.contains(&s) => params.push(s),
            _ => return Err(LowerError::UnsupportedSymbol(ar.symbol_info(s).name.clone())),
        }
    }
    Ok(params)
}
