//! The outputs lowered: in come a spec's outputs; out go one section per output (its own shared
//! subexpressions), the states each reads and whether it needs the speed rates.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId, TIME};
use crate::spec::ModelSpec;

use super::super::ir::{Input, OutputCode};
use super::super::CodegenError;
use super::exprs::ExprLowering;

/// One [`OutputCode`] per output of `spec`; `params` are the constants the code reads.
pub fn lower(spec: &mut ModelSpec, params: &[SymbolId]) -> Result<Vec<OutputCode>, CodegenError> {
    let states = spec.states();
    let rates = spec.equations.speed_derivatives.clone();
    let mut symbols: FxHashMap<SymbolId, Input> = FxHashMap::default();
    symbols.insert(TIME, Input::Time);
    for (i, s) in states.iter().enumerate() {
        symbols.insert(*s, Input::State(i));
    }
    for (i, s) in params.iter().enumerate() {
        symbols.insert(*s, Input::Param(i));
    }
    for (i, s) in rates.iter().enumerate() {
        symbols.insert(*s, Input::Rate(i));
    }
    let mut out = Vec::with_capacity(spec.outputs.len());
    for k in 0..spec.outputs.len() {
        let components = spec.outputs[k].components.clone();
        let reads = reads(spec, &components, &states)?;
        let ar = &spec.model.ar;
        let needs_rates = ar.free_symbols(&components).iter().any(|s| rates.contains(s));
        let mut lowering = ExprLowering::new(ar, &symbols, None);
        let values = lowering.lower_all(&components);
        out.push(OutputCode { section: lowering.builder.finish(values), reads, needs_rates });
    }
    Ok(out)
}

/// The states `components` depend on, read from their collected form, where coordinates that
/// cancel (|a_P| does not depend on the gimbal's q1) are gone; the code evaluates the original
/// form, which is better conditioned (the expanded one cancels large terms when the gimbals
/// spin fast). A component too large to collect (a long chain's kinetic energy) reads the
/// states of its original form.
fn reads(
    spec: &mut ModelSpec,
    components: &[ExprId],
    states: &[SymbolId],
) -> Result<Vec<usize>, CodegenError> {
    let mut read = vec![false; states.len()];
    for &e in components {
        let c = match spec.model.collected_form(e) {
            Err(crate::mechanics::MechanicsError::Expr(crate::expr::ExprError::TooLarge(_))) => e,
            c => c?,
        };
        let ar = &spec.model.ar;
        let form = if ar.free_symbols(&[c]).len() < ar.free_symbols(&[e]).len() { c } else { e };
        let free = ar.free_symbols(&[form]);
        for (i, s) in states.iter().enumerate() {
            read[i] |= free.contains(s);
        }
    }
    Ok((0..states.len()).filter(|i| read[*i]).collect())
}
