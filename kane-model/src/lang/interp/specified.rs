//! Formulas for SPECIFIED quantities: `T = -K*Q` anywhere in a file (after KANE() too, as
//! Autolev writes the formulas its CODE evaluates before the equations) replaces `T` (and its
//! derivatives `T'`, `T''`, by their own formulas where the file gives them, else the rates of
//! the formula) in the equations and the outputs.
//!
//! In: the formulas at the end of a file, by upper-cased name with primes. Out: the
//! substitution of each specified symbol by its formula.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolKind};
use crate::mechanics::Model;

/// `S -> formula`, `S' -> formula of S'` (or `d/dt` of `S`'s), ... for every SPECIFIED `S`
/// the file gave a formula, or a formula of a derivative.
pub(crate) fn specified_formulas(
    model: &mut Model,
    formulas: &FxHashMap<String, ExprId>,
) -> crate::mechanics::Result<FxHashMap<ExprId, ExprId>> {
    let mut map = FxHashMap::default();
    let mut bases: Vec<&str> = formulas.keys().map(|k| k.trim_end_matches('\'')).collect();
    bases.sort_unstable();
    bases.dedup();
    for name in bases {
        let Some(s) = model.ar.lookup(name) else { continue };
        if !matches!(model.ar.symbol_info(s).kind, SymbolKind::Specified { order: 0 }) {
            continue;
        }
        let mut rate = formulas.get(name).copied();
        if let Some(f) = rate {
            map.insert(model.ar.symbol_expr(s), f);
        }
        for primes in 1..=2 {
            let primed = format!("{name}{}", "'".repeat(primes));
            let Some(d) = model.ar.lookup(&primed) else { break };
            rate = match (formulas.get(&primed), rate) {
                (Some(own), _) => Some(*own),
                (None, Some(f)) => Some(model.dt(f)?),
                (None, None) => None,
            };
            if let Some(f) = rate {
                map.insert(model.ar.symbol_expr(d), f);
            }
        }
    }
    Ok(map)
}
