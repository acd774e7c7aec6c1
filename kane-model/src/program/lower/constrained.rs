//! The right-hand side of a constrained model lowered: in come Kane's equations over all speeds
//! (`M`, `f`) with their constraint block; out go `param_constants` and `rhs`. At each
//! evaluation `rhs` factors `A_d` (Householder, [`super::householder`]), solves the dependent
//! speeds `A_d u_d = -(A_i u_i + b)`, then `C_d = -A_d^-1 A_i` and `g_d = -A_d^-1 bias`, and
//! solves the reduced `(C^T M C) u_i' = C^T (f - M g)` with `C = [I; C_d]`, `g = [0; g_d]`: no
//! symbolic inverse, so nothing divides by an entry that vanishes at a symmetric state.
// Matrix code reads clearest with indices.
#![allow(clippy::needless_range_loop)]

use crate::expr::{Arena, Compiler, ExprId, SymbolId};
use crate::mechanics::{KaneEquations, SolvedLoads, SpeedConstraints};

use super::super::ir::{Input, Op, Section, SectionBuilder};
use super::super::LowerError;
use super::hoist::Hoisted;
use super::householder::{self, sum, Factored};
use super::inverse::{self, LoadValues};
use super::solve;

/// The `param_constants` and `rhs` sections of the constrained `eqs`.
pub fn lower(
    ar: &mut Arena,
    eqs: &KaneEquations,
    c: &SpeedConstraints,
    params: &[SymbolId],
) -> Result<(Section, Section), LowerError> {
    let n = eqs.speeds.len() + c.dependent.len();
    let mut roots: Vec<ExprId> = block_roots(c);
    let first = roots.len();
    roots.extend(solve::upper_triangle(&eqs.mass_matrix));
    roots.extend(&eqs.forcing);
    roots.extend(&c.bias);
    roots.extend(&eqs.kinematics);
    let loads = eqs.loads.as_ref().map(inverse::load_roots).unwrap_or_default();
    roots.extend(&loads);
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = Hoisted::default();
    let roots = roots.iter().map(|r| hoisted.rewrite(ar, *r, &is_param)).collect::<Result<Vec<_>, _>>()?;
    let states: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
    let (symbols, param_constants) = hoisted.reading(ar, &states, params);
    let dependent: Vec<ExprId> = c.dependent.iter().map(|s| ar.symbol_expr(*s)).collect();
    let mut lowering = Compiler::new(ar, |s| symbols.get(&s).copied(), None);
    let block = Block::lower(&mut lowering, &dependent, &roots[..first], eqs.coordinates.len());
    let values = lowering.lower_all(&roots[first..]);
    let b = &mut lowering.builder;
    let m = solve::symmetric(&values, n);
    let k = n * (n + 1) / 2;
    let f = &values[k..k + n];
    let bias = &values[k + n..k + n + c.dependent.len()];
    let kinematics_end = values.len() - loads.len();
    let kinematics = values[k + n + c.dependent.len()..kinematics_end].to_vec();
    let reduced = block.reduce(b, &m, f, bias);
    let x = match &eqs.loads {
        Some(l) => {
            let loads = LoadValues::from_values(&values[kinematics_end..], n, l.loads.len());
            let mut x = inverse::solve_reduced(b, &reduced.m, &reduced.f, &reduced.cd, &reduced.g, &loads);
            x.truncate(eqs.speeds.len());
            x
        }
        None => {
            let some: Vec<Vec<Option<u32>>> =
                reduced.m.iter().map(|row| row.iter().map(|v| Some(*v)).collect()).collect();
            let recips = vec![None; some.len()];
            solve::lower(b, &solve::System { m: &some, f: &reduced.f, recips: &recips, dets: &[] })
        }
    };
    let mut results = kinematics;
    results.extend(x);
    Ok((param_constants, lowering.builder.finish(results)))
}

/// `A_d`, `A_i` and `b`, row by row, in one list.
pub fn block_roots(c: &SpeedConstraints) -> Vec<ExprId> {
    let mut roots: Vec<ExprId> = c.a_dependent.iter().flatten().copied().collect();
    roots.extend(c.a_independent.iter().flatten());
    roots.extend(&c.b);
    roots
}

/// The constraint block in a section: `A_d` factored, `A_i`, and the dependent speeds solved.
pub struct Block {
    factored: Factored,
    a_independent: Vec<Vec<u32>>,
}

impl Block {
    /// Lowers `A_d`, `A_i` and `b` (`roots`, as [`block_roots`] lists them, hoisted or not),
    /// factors `A_d`, solves the dependent speeds from the state (speeds after `nq`
    /// coordinates) and makes the section read them wherever their symbols (`dependent`, as
    /// expressions) appear.
    pub fn lower(lowering: &mut Compiler<Input>, dependent: &[ExprId], roots: &[ExprId], nq: usize) -> Block {
        let md = dependent.len();
        let ni = (roots.len() - md * md - md) / md;
        let values = lowering.lower_all(roots);
        let rows = |start: usize, cols: usize| -> Vec<Vec<u32>> {
            (0..md).map(|i| values[start + i * cols..start + (i + 1) * cols].to_vec()).collect()
        };
        let (a_dependent, a_independent) = (rows(0, md), rows(md * md, ni));
        let b_values = &values[md * md + md * ni..];
        let b = &mut lowering.builder;
        let factored = householder::factor(b, a_dependent);
        let zero = b.constant(0.0);
        let speeds: Vec<u32> = (0..ni).map(|r| b.input(Input::State(nq + r))).collect();
        let rhs: Vec<u32> = (0..md)
            .map(|k| {
                let terms: Vec<u32> = (0..ni).map(|r| b.mul(a_independent[k][r], speeds[r])).collect();
                let s = sum(b, &terms, zero);
                let t = b.add(s, b_values[k]);
                b.push(Op::Neg(t))
            })
            .collect();
        let solved = factored.solve(b, &rhs);
        for (e, v) in dependent.iter().zip(solved) {
            lowering.bind(*e, v);
        }
        Block { factored, a_independent }
    }

    /// Makes the section read the dependent speeds' rates (their symbols' expressions `rates`)
    /// from `A_d u_d' = -(A_i u_i' + bias)`, the independent rates read as `Input::Rate`.
    pub fn bind_rates(&self, lowering: &mut Compiler<Input>, bias: &[ExprId], rates: &[ExprId]) {
        let bias = lowering.lower_all(bias);
        let b = &mut lowering.builder;
        let zero = b.constant(0.0);
        let ni = self.a_independent.first().map_or(0, Vec::len);
        let udot: Vec<u32> = (0..ni).map(|r| b.input(Input::Rate(r))).collect();
        let rhs: Vec<u32> = (0..bias.len())
            .map(|k| {
                let terms: Vec<u32> = (0..ni).map(|r| b.mul(self.a_independent[k][r], udot[r])).collect();
                let s = sum(b, &terms, zero);
                let t = b.add(s, bias[k]);
                b.push(Op::Neg(t))
            })
            .collect();
        let solved = self.factored.solve(b, &rhs);
        for (e, v) in rates.iter().zip(solved) {
            lowering.bind(*e, v);
        }
    }

    /// `C^T M C` and `C^T (f - M g)` from `M` and `f` over all speeds and the values of `bias`.
    fn reduce(&self, b: &mut SectionBuilder, m: &[Vec<u32>], f: &[u32], bias: &[u32]) -> Reduced {
        let (md, ni) = (bias.len(), f.len() - bias.len());
        let zero = b.constant(0.0);
        // Columns of C_d = -A_d^-1 A_i and g_d = -A_d^-1 bias.
        let mut cd = vec![vec![zero; ni]; md];
        for r in 0..ni {
            let column: Vec<u32> = (0..md).map(|k| b.push(Op::Neg(self.a_independent[k][r]))).collect();
            for (k, x) in self.factored.solve(b, &column).into_iter().enumerate() {
                cd[k][r] = x;
            }
        }
        let minus_bias: Vec<u32> = bias.iter().map(|x| b.push(Op::Neg(*x))).collect();
        let g = self.factored.solve(b, &minus_bias);
        // U = (C^T M) over all columns: M[r][col] + sum_l C_d[l][r] M[ni + l][col].
        let u: Vec<Vec<u32>> = (0..ni)
            .map(|r| {
                (0..ni + md)
                    .map(|col| {
                        let terms: Vec<u32> = (0..md).map(|l| b.mul(cd[l][r], m[ni + l][col])).collect();
                        let s = sum(b, &terms, zero);
                        b.add(m[r][col], s)
                    })
                    .collect()
            })
            .collect();
        let mut reduced = vec![vec![zero; ni]; ni];
        for r in 0..ni {
            for s in r..ni {
                let terms: Vec<u32> = (0..md).map(|k| b.mul(u[r][ni + k], cd[k][s])).collect();
                let t = sum(b, &terms, zero);
                let e = b.add(u[r][s], t);
                (reduced[r][s], reduced[s][r]) = (e, e);
            }
        }
        let forcing = (0..ni)
            .map(|r| {
                let mut terms: Vec<u32> = (0..md).map(|l| b.mul(cd[l][r], f[ni + l])).collect();
                terms.extend((0..md).map(|k| {
                    let t = b.mul(u[r][ni + k], g[k]);
                    b.push(Op::Neg(t))
                }));
                let s = sum(b, &terms, zero);
                b.add(f[r], s)
            })
            .collect();
        Reduced { m: reduced, f: forcing, cd, g }
    }

    /// Makes the section read the loads (their symbols' expressions `loads`) of `eqs` with the
    /// constraints `c` and the loads `l`, this block lowered in it already.
    pub fn bind_loads(
        &self,
        lowering: &mut Compiler<Input>,
        eqs: &KaneEquations,
        c: &SpeedConstraints,
        l: &SolvedLoads,
        loads: &[ExprId],
    ) {
        let n = eqs.speeds.len() + c.dependent.len();
        let mut roots = solve::upper_triangle(&eqs.mass_matrix);
        roots.extend(&eqs.forcing);
        roots.extend(&c.bias);
        roots.extend(inverse::load_roots(l));
        let values = lowering.lower_all(&roots);
        let b = &mut lowering.builder;
        let m = solve::symmetric(&values, n);
        let at = n * (n + 1) / 2;
        let (f, bias) = (&values[at..at + n], &values[at + n..at + n + c.dependent.len()]);
        let reduced = self.reduce(b, &m, f, bias);
        let load_values = LoadValues::from_values(&values[at + n + c.dependent.len()..], n, l.loads.len());
        let x = inverse::solve_reduced(b, &reduced.m, &reduced.f, &reduced.cd, &reduced.g, &load_values);
        for (e, v) in loads.iter().zip(&x[eqs.speeds.len()..]) {
            lowering.bind(*e, *v);
        }
    }
}

/// `C^T M C`, `C^T (f - M g)`, and the reduction `C = [I; cd]`, `g = [0; g]`.
struct Reduced {
    m: Vec<Vec<u32>>,
    f: Vec<u32>,
    cd: Vec<Vec<u32>>,
    g: Vec<u32>,
}
