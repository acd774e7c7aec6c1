//! The right-hand side of a model with loads solved for (KANE(T1, ...)) lowered: in come Kane's
//! equations over the speeds with the auxiliary rows and the load columns; out go
//! `param_constants` and `rhs`. At each evaluation `rhs` solves
//! `[M, -B_s; M_a, -B_a] [u'; T] = [f; f_a]` by Householder reflections
//! ([`super::householder`]) and keeps `u'`; an output that reads a load solves the same system.
// Matrix code reads clearest with indices.
#![allow(clippy::needless_range_loop)]

use crate::expr::{Arena, Compiler, ExprId, SymbolId};
use crate::mechanics::{KaneEquations, SolvedLoads};

use super::super::ir::{Input, Op, Section, SectionBuilder};
use super::super::LowerError;
use super::hoist::Hoisted;
use super::householder::{self, sum};
use super::solve::{symmetric, upper_triangle};

/// The `param_constants` and `rhs` sections of the unconstrained `eqs` with the loads `l`.
pub fn lower(
    ar: &mut Arena,
    eqs: &KaneEquations,
    l: &SolvedLoads,
    params: &[SymbolId],
) -> Result<(Section, Section), LowerError> {
    let n = eqs.speeds.len();
    let mut roots = upper_triangle(&eqs.mass_matrix);
    roots.extend(&eqs.forcing);
    roots.extend(load_roots(l));
    let first = roots.len();
    roots.extend(&eqs.kinematics);
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = Hoisted::default();
    let roots = roots.iter().map(|r| hoisted.rewrite(ar, *r, &is_param)).collect::<Result<Vec<_>, _>>()?;
    let states: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
    let (symbols, param_constants) = hoisted.reading(ar, &states, params);
    let mut lowering = Compiler::new(ar, |s| symbols.get(&s).copied(), None);
    let values = lowering.lower_all(&roots);
    let x = solve_unconstrained(&mut lowering.builder, n, l.loads.len(), &values[..first]);
    let mut results = values[first..].to_vec();
    results.extend(&x[..n]);
    Ok((param_constants, lowering.builder.finish(results)))
}

/// The auxiliary rows of `M`, `f_a`, then `B` row by row.
pub fn load_roots(l: &SolvedLoads) -> Vec<ExprId> {
    let mut roots: Vec<ExprId> = l.mass_rows.iter().flatten().copied().collect();
    roots.extend(&l.forcing);
    roots.extend(l.load_columns.iter().flatten());
    roots
}

/// The lowered values of [`load_roots`], as rows.
pub struct LoadValues {
    /// `M_a`, a row per auxiliary speed over all speeds.
    pub mass_rows: Vec<Vec<u32>>,
    /// `f_a`.
    pub forcing: Vec<u32>,
    /// `B`, a row per speed then per auxiliary speed.
    pub columns: Vec<Vec<u32>>,
}

impl LoadValues {
    /// Split from the values of [`load_roots`] for `n` speeds (all of them) and `k` loads.
    pub fn from_values(values: &[u32], n: usize, k: usize) -> LoadValues {
        let rows = |start: usize, count: usize, width: usize| -> Vec<Vec<u32>> {
            (0..count).map(|i| values[start + i * width..start + (i + 1) * width].to_vec()).collect()
        };
        LoadValues {
            mass_rows: rows(0, k, n),
            forcing: values[k * n..k * n + k].to_vec(),
            columns: rows(k * n + k, n + k, k),
        }
    }
}

/// Makes the section of an unconstrained model read the loads (their symbols' expressions
/// `loads`) from the system.
pub fn bind_loads(lowering: &mut Compiler<Input>, eqs: &KaneEquations, l: &SolvedLoads, loads: &[ExprId]) {
    let n = eqs.speeds.len();
    let mut roots = upper_triangle(&eqs.mass_matrix);
    roots.extend(&eqs.forcing);
    roots.extend(load_roots(l));
    let values = lowering.lower_all(&roots);
    let x = solve_unconstrained(&mut lowering.builder, n, l.loads.len(), &values);
    for (e, v) in loads.iter().zip(&x[n..]) {
        lowering.bind(*e, *v);
    }
}

/// `[u'; T]` from the values of `M`'s upper triangle, `f` and [`load_roots`].
fn solve_unconstrained(b: &mut SectionBuilder, n: usize, k: usize, values: &[u32]) -> Vec<u32> {
    let m = symmetric(values, n);
    let at = n * (n + 1) / 2;
    let f = &values[at..at + n];
    let loads = LoadValues::from_values(&values[at + n..], n, k);
    solve_reduced(b, &m, f, &[], &[], &loads)
}

/// `[u_i'; T]` from `[C^T M C, -C^T B_s; M_a C, -B_a] [u_i'; T] = [C^T (f - M g); f_a - M_a g]`:
/// `reduced` and `reduced_f` are `C^T M C` and `C^T (f - M g)`, `C = [I; cd]` and `g = [0; g]`
/// (`cd` and `g` empty without constraints).
pub fn solve_reduced(
    b: &mut SectionBuilder,
    reduced: &[Vec<u32>],
    reduced_f: &[u32],
    cd: &[Vec<u32>],
    g: &[u32],
    loads: &LoadValues,
) -> Vec<u32> {
    let (ni, k) = (reduced_f.len(), loads.forcing.len());
    let n = ni + g.len();
    let zero = b.constant(0.0);
    let mut e = vec![vec![zero; ni + k]; ni + k];
    for r in 0..ni {
        e[r][..ni].copy_from_slice(&reduced[r]);
        for c in 0..k {
            let terms: Vec<u32> = (0..g.len()).map(|l| b.mul(cd[l][r], loads.columns[ni + l][c])).collect();
            let s = sum(b, &terms, zero);
            let t = b.add(loads.columns[r][c], s);
            e[r][ni + c] = b.push(Op::Neg(t));
        }
    }
    let mut rhs = reduced_f.to_vec();
    for a in 0..k {
        let row = &loads.mass_rows[a];
        for s in 0..ni {
            let terms: Vec<u32> = (0..g.len()).map(|l| b.mul(row[ni + l], cd[l][s])).collect();
            let t = sum(b, &terms, zero);
            e[ni + a][s] = b.add(row[s], t);
        }
        for c in 0..k {
            e[ni + a][ni + c] = b.push(Op::Neg(loads.columns[n + a][c]));
        }
        let terms: Vec<u32> = (0..g.len()).map(|l| b.mul(row[ni + l], g[l])).collect();
        let t = sum(b, &terms, zero);
        rhs.push(b.sub(loads.forcing[a], t));
    }
    householder::factor(b, e).solve(b, &rhs)
}
