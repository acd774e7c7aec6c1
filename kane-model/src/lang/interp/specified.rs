//! Formulas for SPECIFIED quantities: `T = -K*Q` anywhere in a file (after KANE() too, as
//! Autolev writes the formulas its CODE evaluates before the equations) replaces `T` (and its
//! derivatives `T'`, `T''`) in the equations and the outputs.
//!
//! In: the bindings at the end of a file. Out: the substitution of each specified symbol by
//! its formula.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolKind};
use crate::mechanics::Model;

use super::value::Value;
use super::Binding;

/// `S -> formula`, `S' -> d/dt formula`, ... for every SPECIFIED `S` the bindings give a
/// scalar formula.
pub(crate) fn specified_formulas(
    model: &mut Model,
    bindings: &FxHashMap<String, Binding>,
) -> crate::mechanics::Result<FxHashMap<ExprId, ExprId>> {
    let mut map = FxHashMap::default();
    let mut names: Vec<(&String, ExprId)> = bindings
        .iter()
        .filter_map(|(name, b)| match b {
            Binding::Value(Value::Scalar(f)) => Some((name, *f)),
            _ => None,
        })
        .collect();
    names.sort();
    for (name, formula) in names {
        let Some(s) = model.ar.lookup(name) else { continue };
        if !matches!(model.ar.symbol_info(s).kind, SymbolKind::Specified { order: 0 }) {
            continue;
        }
        map.insert(model.ar.symbol_expr(s), formula);
        let mut rate = formula;
        for primes in 1..=2 {
            let Some(d) = model.ar.lookup(&format!("{name}{}", "'".repeat(primes))) else { break };
            rate = model.dt(rate)?;
            map.insert(model.ar.symbol_expr(d), rate);
        }
    }
    Ok(map)
}
