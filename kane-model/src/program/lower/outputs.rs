//! The outputs lowered: in come a spec's outputs; out go one section per output (its own shared
//! subexpressions), the states each reads and whether it needs the speed rates.

use rustc_hash::FxHashMap;

use crate::expr::{Compiler, ExprId, SymbolId, TIME};
use crate::spec::ModelSpec;

use super::super::ir::{Input, OutputCode};
use super::super::LowerError;
use super::constrained;
use super::inverse;

/// One [`OutputCode`] per output of `spec`; `params` are the constants the code reads.
pub fn lower(spec: &mut ModelSpec, params: &[SymbolId]) -> Result<Vec<OutputCode>, LowerError> {
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
    let constraints = spec.equations.constraints.clone();
    let (dependent, dependent_rates) = match &constraints {
        Some(c) => {
            let ar = &mut spec.model.ar;
            let d: Vec<ExprId> = c.dependent.iter().map(|s| ar.symbol_expr(*s)).collect();
            (d, c.dependent_rates.iter().map(|s| ar.symbol_expr(*s)).collect())
        }
        None => (Vec::new(), Vec::new()),
    };
    let loads = spec.equations.loads.clone();
    let load_exprs: Vec<ExprId> = match &loads {
        Some(l) => l.loads.iter().map(|s| spec.model.ar.symbol_expr(*s)).collect(),
        None => Vec::new(),
    };
    let mut out = Vec::with_capacity(spec.outputs.len());
    for k in 0..spec.outputs.len() {
        let components = spec.outputs[k].components.clone();
        let ar = &spec.model.ar;
        let free = ar.free_symbols(&components);
        let solved = loads.as_ref().filter(|l| l.loads.iter().any(|s| free.contains(s)));
        let block = constraints.as_ref().filter(|c| {
            solved.is_some() || c.dependent.iter().chain(&c.dependent_rates).any(|s| free.contains(s))
        });
        let mut reads_from = components.clone();
        if let Some(c) = block {
            reads_from
                .extend(c.a_dependent.iter().chain(&c.a_independent).flatten().chain(&c.b).chain(&c.bias));
        }
        if let Some(l) = solved {
            reads_from.extend(spec.equations.mass_matrix.iter().flatten().chain(&spec.equations.forcing));
            reads_from.extend(inverse::load_roots(l));
        }
        let reads = reads(spec, &reads_from, &states)?;
        let ar = &spec.model.ar;
        let needs_rates = block.is_some_and(|c| c.dependent_rates.iter().any(|s| free.contains(s)))
            || free.iter().any(|s| rates.contains(s));
        let mut lowering = Compiler::new(ar, |s| symbols.get(&s).copied(), None);
        if let Some(c) = block {
            let roots = constrained::block_roots(c);
            let b = constrained::Block::lower(
                &mut lowering,
                &dependent,
                &roots,
                spec.equations.coordinates.len(),
            );
            if c.dependent_rates.iter().any(|s| free.contains(s)) {
                b.bind_rates(&mut lowering, &c.bias, &dependent_rates);
            }
            if let Some(l) = solved {
                b.bind_loads(&mut lowering, &spec.equations, c, l, &load_exprs);
            }
        } else if let Some(l) = solved {
            inverse::bind_loads(&mut lowering, &spec.equations, l, &load_exprs);
        }
        let values = lowering.lower_all(&components);
        out.push(OutputCode { section: lowering.builder.finish(values), reads, needs_rates });
    }
    Ok(out)
}

/// The states `components` depend on, read from their collected form, where coordinates that
/// cancel (|a_P| does not depend on the gimbal's q1) are gone; the code evaluates the original
/// form, which is better conditioned (the expanded one cancels large terms when the gimbals
/// spin fast).
fn reads(spec: &mut ModelSpec, components: &[ExprId], states: &[SymbolId]) -> Result<Vec<usize>, LowerError> {
    let mut read = vec![false; states.len()];
    for &e in components {
        let c = spec.model.collected_form_within_budget(e)?;
        let ar = &spec.model.ar;
        let form = if ar.free_symbols(&[c]).len() < ar.free_symbols(&[e]).len() { c } else { e };
        let free = ar.free_symbols(&[form]);
        for (i, s) in states.iter().enumerate() {
            read[i] |= free.contains(s);
        }
    }
    Ok((0..states.len()).filter(|i| read[*i]).collect())
}
