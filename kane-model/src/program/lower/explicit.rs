//! The right-hand side from explicit speed rates (the order-n form): in come `q' = kinematics`
//! and `u' = rates` as expressions; out go the `param_constants` section (their parameter-only
//! parts, once per parameter set) and the `rhs` section (`q'` then `u'`, shared subexpressions
//! once).

use rustc_hash::FxHashMap;

use crate::expr::{Arena, Compiler, ExprId, SymbolId};

use super::super::ir::Section;
use super::super::LowerError;
use super::hoist::Hoisted;

/// What the explicit form reads and returns.
pub struct Explicit<'a> {
    /// The coordinates, then the speeds: the states in order.
    pub states: &'a [SymbolId],
    /// The speeds (read last in products).
    pub speeds: &'a [SymbolId],
    /// `q'`, one per coordinate.
    pub kinematics: &'a [ExprId],
    /// `u'`, one per speed.
    pub rates: &'a [ExprId],
}

/// The `param_constants` and `rhs` sections of `form`; `params` are the constants the code reads.
pub fn lower(
    ar: &mut Arena,
    form: &Explicit<'_>,
    params: &[SymbolId],
) -> Result<(Section, Section), LowerError> {
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = Hoisted::default();
    let mut roots = Vec::with_capacity(form.kinematics.len() + form.rates.len());
    for &r in form.kinematics.iter().chain(form.rates) {
        roots.push(hoisted.rewrite(ar, r, &is_param)?);
    }
    let (symbols, param_constants) = hoisted.reading(ar, form.states, params);
    let late = late_speeds(ar, form.speeds);
    let mut lowering = Compiler::new(ar, |s| symbols.get(&s).copied(), Some(&late));
    let values = lowering.lower_all(&roots);
    Ok((param_constants, lowering.builder.finish(values)))
}

/// Marks the expressions that read a speed, memoised over the graph (speeds arrive last in an
/// integrator's stage, so products multiply the other factors first).
fn late_speeds<'a>(ar: &'a Arena, speeds: &'a [SymbolId]) -> impl Fn(ExprId) -> bool + 'a {
    let memo = std::cell::RefCell::new(FxHashMap::<ExprId, bool>::default());
    move |e: ExprId| -> bool { reads_speed(ar, e, speeds, &mut memo.borrow_mut()) }
}

fn reads_speed(ar: &Arena, e: ExprId, speeds: &[SymbolId], memo: &mut FxHashMap<ExprId, bool>) -> bool {
    if let Some(&b) = memo.get(&e) {
        return b;
    }
    let b = match ar.as_symbol(e) {
        Some(s) => speeds.contains(&s),
        None => ar.node(e).children().iter().any(|c| reads_speed(ar, *c, speeds, memo)),
    };
    memo.insert(e, b);
    b
}
