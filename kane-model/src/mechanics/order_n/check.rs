//! A numerical check of explicit speed rates against Kane's `M u' = f` at a pseudo-random state
//! and parameter set: the order-n form replaces the mass-matrix form only where they agree.
// Matrix code reads clearest with indices (a[i][j] beside a[j][i]).
#![allow(clippy::needless_range_loop)]

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, SymbolId, SymbolKind};
use crate::mechanics::KaneEquations;

/// True when `rates` solve `M u' = f` of `eqs` to a relative 1e-9 at two pseudo-random points.
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
    let mut m: Vec<Vec<f64>> = v[..n * n].chunks(n).map(<[f64]>::to_vec).collect();
    let mut f = v[n * n..n * n + n].to_vec();
    let x = solve(&mut m, &mut f)?;
    let scale = x.iter().fold(1.0f64, |a, b| a.max(b.abs()));
    Some(x.iter().zip(&v[n * n + n..]).all(|(a, b)| (a - b).abs() <= 1e-9 * scale))
}

/// Gaussian elimination with partial pivoting; `None` for a singular matrix.
fn solve(m: &mut [Vec<f64>], f: &mut [f64]) -> Option<Vec<f64>> {
    let n = f.len();
    for c in 0..n {
        let p = (c..n).max_by(|a, b| m[*a][c].abs().total_cmp(&m[*b][c].abs()))?;
        if m[p][c] == 0.0 {
            return None;
        }
        m.swap(c, p);
        f.swap(c, p);
        for r in c + 1..n {
            let k = m[r][c] / m[c][c];
            for j in c..n {
                m[r][j] -= k * m[c][j];
            }
            f[r] -= k * f[c];
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|j| m[r][j] * x[j]).sum();
        x[r] = (f[r] - s) / m[r][r];
    }
    Some(x)
}
