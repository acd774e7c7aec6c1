//! The right-hand side lowered: in come Kane's equations (simplified) and the parameters; out go
//! two sections, `param_constants` (parameter-only quantities, once per parameter set) and `rhs`
//! (`q'` then `u'`, the entries of `M` and `f` with `M u' = f` solved in the same program).
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use rustc_hash::FxHashMap;

use crate::expr::{Arena, Compiler, ExprId, SymbolId};
use crate::mechanics::KaneEquations;

use super::super::ir::Section;
use super::super::LowerError;
use super::hoist::Hoisted;
use super::solve;

/// The roots of `rhs` after hoisting: `M`'s upper triangle, `f`, the kinematics, then the
/// determinants of 2x2 blocks; and the reciprocals of constant pivots.
struct Roots {
    roots: Vec<ExprId>,
    dets: Vec<((usize, usize), usize)>,
    recips: Vec<Option<ExprId>>,
    hoisted: Hoisted,
}

/// The `param_constants` and `rhs` sections of `eqs`; `params` are the constants the code reads.
pub fn lower(
    ar: &mut Arena,
    eqs: &KaneEquations,
    params: &[SymbolId],
) -> Result<(Section, Section), LowerError> {
    let r = hoisted_roots(ar, eqs, params)?;
    let n = eqs.speeds.len();
    let states: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
    let (symbols, param_constants) = r.hoisted.reading(ar, &states, params);
    // Speeds arrive last in an integrator's stage (they come from the previous stage's u'):
    // products multiply the factors without speeds first.
    let memo = std::cell::RefCell::new(FxHashMap::<ExprId, bool>::default());
    let ar_ref: &Arena = ar;
    let is_late = |e: ExprId| -> bool {
        *memo
            .borrow_mut()
            .entry(e)
            .or_insert_with(|| ar_ref.free_symbols(&[e]).iter().any(|s| eqs.speeds.contains(s)))
    };
    let mut lowering = Compiler::new(ar_ref, |s| symbols.get(&s).copied(), Some(&is_late));
    let values = lowering.lower_all(&r.roots);
    let mut k = 0;
    let mut m: Vec<Vec<Option<u32>>> = vec![vec![None; n]; n];
    for i in 0..n {
        for j in i..n {
            if !ar_ref.is_zero(r.roots[k]) {
                m[i][j] = Some(values[k]);
                m[j][i] = Some(values[k]);
            }
            k += 1;
        }
    }
    let f = &values[k..k + n];
    let kinematics = &values[k + n..k + n + eqs.coordinates.len()];
    let recips: Vec<Option<u32>> = r.recips.iter().map(|e| e.map(|e| lowering.value(e))).collect();
    let dets: Vec<((usize, usize), u32)> = r.dets.iter().map(|(ac, i)| (*ac, values[*i])).collect();
    let x = solve::lower(&mut lowering.builder, &solve::System { m: &m, f, recips: &recips, dets: &dets });
    let mut results = kinematics.to_vec();
    results.extend(x);
    Ok((param_constants, lowering.builder.finish(results)))
}

/// Parameter-only parts (whole subexpressions, the parameter terms of sums and factors of
/// products, reciprocals of constant pivots) replaced by constants computed once per parameter
/// set; the determinant of each 2x2 block of `M`, collected by state monomial, appended so that
/// its parameter parts are constants too (the gimbal's is `A + B cos^2 q2`).
fn hoisted_roots(ar: &mut Arena, eqs: &KaneEquations, params: &[SymbolId]) -> Result<Roots, LowerError> {
    let n = eqs.speeds.len();
    let mm = &eqs.mass_matrix;
    let mut rhs_roots: Vec<ExprId> = Vec::new();
    for i in 0..n {
        rhs_roots.extend(&mm[i][i..]);
    }
    rhs_roots.extend(&eqs.forcing);
    rhs_roots.extend(&eqs.kinematics);
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = Hoisted::default();
    let mut roots = Vec::with_capacity(rhs_roots.len());
    for &r in &rhs_roots {
        roots.push(hoisted.rewrite(ar, r, &is_param)?);
    }
    let pairs: Vec<(usize, usize)> = solve::blocks(n, |i, j| !ar.is_zero(mm[i][j]))
        .into_iter()
        .filter_map(|b| if let [a, c] = b[..] { Some((a, c)) } else { None })
        .collect();
    let mut dets = Vec::new();
    for &(a, c) in &pairs {
        let diag = ar.mul(&[mm[a][a], mm[c][c]])?;
        let off = ar.powi(mm[a][c], 2)?;
        let det = ar.sub(diag, off)?;
        let det = if ar.expansion_bounds(&[det])[0] <= crate::mechanics::COLLECT_TERMS_BUDGET as u64 {
            ar.collect_state(det, is_param)?
        } else {
            det
        };
        roots.push(hoisted.rewrite(ar, det, &is_param)?);
        dets.push(((a, c), roots.len() - 1));
    }
    // A pivot without fill-in is M's diagonal entry itself: a constant one is inverted once
    // (2x2 blocks use their determinant instead).
    let mut recips: Vec<Option<ExprId>> = vec![None; n];
    for j in (0..n).filter(|j| !pairs.iter().any(|(a, c)| a == j || c == j)) {
        let row_empty = (0..j).all(|k| ar.is_zero(mm[k][j]));
        let mjj = mm[j][j];
        if row_empty && !ar.is_zero(mjj) && ar.free_symbols(&[mjj]).iter().all(|s| is_param(*s)) {
            let minus_one = ar.minus_one();
            let recip = ar.pow(mjj, minus_one)?;
            recips[j] = Some(hoisted.constant(ar, recip)?);
        }
    }
    Ok(Roots { roots, dets, recips, hoisted })
}
