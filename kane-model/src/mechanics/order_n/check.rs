//! A numerical check of explicit speed rates against Kane's `M u' = f` at a pseudo-random state
//! and parameter set: the order-n form replaces the mass-matrix form only where they agree.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, SymbolId, SymbolKind};
use crate::mechanics::KaneEquations;

/// True when `rates` solve `M u' = f` of `eqs` at two pseudo-random points: each row's residual
/// within 1e-9 of the size of its terms (a backward error, blind to `M`'s conditioning, which
/// grows with a chain's length).
pub(crate) fn agrees(ar: &Arena, eqs: &KaneEquations, rates: &[ExprId]) -> bool {
    (0..2u64).all(|seed| agrees_at(ar, eqs, rates, seed).unwrap_or(false))
}

fn agrees_at(ar: &Arena, eqs: &KaneEquations, rates: &[ExprId], seed: u64) -> Option<bool> {
    let n = eqs.speeds.len();
    let mut state = 0x9E37_79B9_7F4A_7C15u64 ^ seed.wrapping_mul(0xD1B5_4A32_D192_ED03);
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut values: FxHashMap<SymbolId, f64> = FxHashMap::default();
    for (s, info) in ar.symbols() {
        if info.kind == SymbolKind::Constant {
            values.insert(s, 0.5 + next());
        }
    }
    for s in eqs.coordinates.iter().chain(&eqs.speeds) {
        values.insert(*s, 2.0 * next() - 1.0);
    }
    let mut roots: Vec<ExprId> = eqs.mass_matrix.iter().flatten().copied().collect();
    roots.extend(&eqs.forcing);
    roots.extend(rates);
    let v = ar.eval::<f64>(&roots, |s| values.get(&s).copied()).ok()?;
    let (m, rest) = v.split_at(n * n);
    let (f, x) = rest.split_at(n);
    Some(m.chunks(n).zip(f).all(|(row, fi)| {
        let r: f64 = row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>() - fi;
        let size: f64 = row.iter().zip(x).map(|(a, b)| (a * b).abs()).sum::<f64>() + fi.abs();
        r.abs() <= 1e-9 * size
    }))
}
