//! The right-hand side of a model with loads solved for (KANE(T1, ...)) lowered: in come Kane's
//! equations over the speeds with the auxiliary rows and the load columns; out go `derive` and
//! `rhs`. At each evaluation `rhs` solves `[M, -B_s; M_a, -B_a] [u'; T] = [f; f_a]` by
//! Householder reflections ([`super::householder`]) and keeps `u'`; an output that reads a
//! load solves the same system.
// Matrix code reads clearest with indices.
#![allow(clippy::needless_range_loop)]

use crate::expr::{Arena, ExprId, SymbolId};
use crate::mechanics::{KaneEquations, SolvedLoads};

use super::super::ir::{Op, Section, SectionBuilder};
use super::super::CodegenError;
use super::exprs::ExprLowering;
use super::hoist::Hoisted;
use super::householder;

/// The `derive` and `rhs` sections of `eqs` with the loads `l`.
pub fn lower(
    ar: &mut Arena,
    eqs: &KaneEquations,
    l: &SolvedLoads,
    params: &[SymbolId],
) -> Result<(Section, Section), CodegenError> {
    let mut roots = system_roots(eqs, l);
    let first = roots.len();
    roots.extend(&eqs.kinematics);
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = Hoisted::default();
    let roots = roots.iter().map(|r| hoisted.rewrite(ar, *r, &is_param)).collect::<Result<Vec<_>, _>>()?;
    let states: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
    let (symbols, derive) = hoisted.reading(ar, &states, params);
    let mut lowering = ExprLowering::new(ar, &symbols, None);
    let values = lowering.lower_all(&roots);
    let x = solve(&mut lowering.builder, eqs.speeds.len(), l.loads.len(), &values[..first]);
    let mut results = values[first..].to_vec();
    results.extend(&x[..eqs.speeds.len()]);
    Ok((derive, lowering.builder.finish(results)))
}

/// `M`'s upper triangle, `f`, the auxiliary rows of `M`, `f_a`, then `B` row by row.
pub fn system_roots(eqs: &KaneEquations, l: &SolvedLoads) -> Vec<ExprId> {
    let n = eqs.speeds.len();
    let mut roots: Vec<ExprId> = (0..n).flat_map(|i| eqs.mass_matrix[i][i..].to_vec()).collect();
    roots.extend(&eqs.forcing);
    roots.extend(l.mass_rows.iter().flatten());
    roots.extend(&l.forcing);
    roots.extend(l.load_columns.iter().flatten());
    roots
}

/// Makes the section read the loads (their symbols' expressions `loads`) from the system,
/// lowered from [`system_roots`].
pub fn bind_loads(lowering: &mut ExprLowering, eqs: &KaneEquations, l: &SolvedLoads, loads: &[ExprId]) {
    let values = lowering.lower_all(&system_roots(eqs, l));
    let n = eqs.speeds.len();
    let x = solve(&mut lowering.builder, n, l.loads.len(), &values);
    for (e, v) in loads.iter().zip(&x[n..]) {
        lowering.bind(*e, *v);
    }
}

/// `[u'; T]` from the values of [`system_roots`] for `n` speeds and `k` loads.
fn solve(b: &mut SectionBuilder, n: usize, k: usize, values: &[u32]) -> Vec<u32> {
    let size = n + k;
    let mut e = vec![vec![0; size]; size];
    let mut at = 0;
    for i in 0..n {
        for j in i..n {
            (e[i][j], e[j][i]) = (values[at], values[at]);
            at += 1;
        }
    }
    let mut rhs: Vec<u32> = values[at..at + n].to_vec();
    at += n;
    for a in 0..k {
        e[n + a][..n].copy_from_slice(&values[at..at + n]);
        at += n;
    }
    rhs.extend(&values[at..at + k]);
    at += k;
    for i in 0..size {
        for c in 0..k {
            e[i][n + c] = b.push(Op::Neg(values[at]));
            at += 1;
        }
    }
    householder::factor(b, e).solve(b, &rhs)
}
