//! A section rewritten into Taylor operations: in comes an SSA [`Section`]; out goes a
//! [`TaylorProgram`] whose every operation has a recurrence. Integer powers become products,
//! real powers `exp(b ln a)`, `tan` and `tanh` quotients, and the inverse functions integrals of
//! quotients; `sin`/`cos` (and `sinh`/`cosh`) of one operand come in pairs. Values that read no
//! state nor time are constants, computed at order 0 only.

use rustc_hash::FxHashMap;

use crate::expr::Func;
use crate::runtime::taylor::Inverse;

use super::super::ir::{Input, Op, Section};
use super::{TKind, TaylorError, TaylorOp, TaylorProgram};

/// Builds the Taylor operations of one section.
struct Builder {
    ops: Vec<TaylorOp>,
    /// `sin`/`cos` (or `sinh`/`cosh`) pairs by operand and hyperbolic flag.
    pairs: FxHashMap<(u32, bool), (u32, u32)>,
    /// Constants by their bits.
    consts: FxHashMap<u64, u32>,
}

impl Builder {
    fn push(&mut self, kind: TKind, operands: &[u32]) -> u32 {
        let series = matches!(kind, TKind::Time | TKind::State(_))
            || operands.iter().any(|v| self.ops[*v as usize].series);
        self.ops.push(TaylorOp { kind, series });
        (self.ops.len() - 1) as u32
    }

    fn constant(&mut self, c: f64) -> u32 {
        if let Some(&v) = self.consts.get(&c.to_bits()) {
            return v;
        }
        let v = self.push(TKind::Const(c), &[]);
        self.consts.insert(c.to_bits(), v);
        v
    }

    fn series(&self, v: u32) -> bool {
        self.ops[v as usize].series
    }

    fn mul(&mut self, a: u32, b: u32) -> u32 {
        match (self.series(a), self.series(b)) {
            _ if a == b => self.push(TKind::Sqr(a), &[a]),
            (true, false) => self.push(TKind::Scale(a, b), &[a, b]),
            (false, true) => self.push(TKind::Scale(b, a), &[a, b]),
            _ => self.push(TKind::Mul(a, b), &[a, b]),
        }
    }

    fn div(&mut self, a: u32, b: u32) -> u32 {
        if self.series(a) && !self.series(b) {
            self.push(TKind::DivConst(a, b), &[a, b])
        } else {
            self.push(TKind::Div(a, b), &[a, b])
        }
    }

    /// `a^n` by repeated squaring; `1 / a^-n` for negative `n`.
    fn powi(&mut self, a: u32, n: i32) -> u32 {
        if n < 0 {
            let one = self.constant(1.0);
            let p = self.powi(a, n.saturating_neg());
            return self.div(one, p);
        }
        match n {
            0 => self.constant(1.0),
            1 => a,
            _ => {
                let half = self.powi(a, n / 2);
                let sq = self.mul(half, half);
                if n % 2 == 1 {
                    self.mul(sq, a)
                } else {
                    sq
                }
            }
        }
    }

    /// The `(sin, cos)` (or `(sinh, cosh)`) pair of `a`, made on first use.
    fn pair(&mut self, a: u32, hyperbolic: bool) -> (u32, u32) {
        if let Some(&p) = self.pairs.get(&(a, hyperbolic)) {
            return p;
        }
        let s = self.ops.len() as u32;
        let (ks, kc) = if hyperbolic {
            (TKind::Sinh(a, s + 1), TKind::Cosh(a, s))
        } else {
            (TKind::Sin(a, s + 1), TKind::Cos(a, s))
        };
        self.push(ks, &[a]);
        self.push(kc, &[a]);
        self.pairs.insert((a, hyperbolic), (s, s + 1));
        (s, s + 1)
    }

    /// `sqrt(1 - a^2)`.
    fn cosine_of_arcsine(&mut self, a: u32) -> u32 {
        let one = self.constant(1.0);
        let sq = self.mul(a, a);
        let diff = self.push(TKind::Sub(one, sq), &[one, sq]);
        self.push(TKind::Sqrt(diff), &[diff])
    }

    fn func(&mut self, f: Func, a: u32) -> u32 {
        match f {
            Func::Sin => self.pair(a, false).0,
            Func::Cos => self.pair(a, false).1,
            Func::Sinh => self.pair(a, true).0,
            Func::Cosh => self.pair(a, true).1,
            Func::Tan | Func::Tanh => {
                let (s, c) = self.pair(a, f == Func::Tanh);
                self.div(s, c)
            }
            Func::Exp => self.push(TKind::Exp(a), &[a]),
            Func::Ln => self.push(TKind::Ln(a), &[a]),
            Func::Abs => self.push(TKind::Abs(a), &[a]),
            Func::Sign => self.push(TKind::Sign(a), &[a]),
            Func::Atan => {
                let one = self.constant(1.0);
                let sq = self.mul(a, a);
                let q = self.push(TKind::Add(one, sq), &[one, sq]);
                self.push(TKind::Integral(Inverse::Atan, a, q), &[a, q])
            }
            Func::Asin => {
                let q = self.cosine_of_arcsine(a);
                self.push(TKind::Integral(Inverse::Asin, a, q), &[a, q])
            }
            Func::Acos => {
                let root = self.cosine_of_arcsine(a);
                let q = self.push(TKind::Neg(root), &[root]);
                self.push(TKind::Integral(Inverse::Acos, a, q), &[a, q])
            }
        }
    }

    /// The Taylor value of one section instruction (operands already mapped).
    fn op(&mut self, section: &Section, op: Op, m: &[u32]) -> Result<u32, TaylorError> {
        let r = |v: u32| m[v as usize];
        Ok(match op {
            Op::Input(k) => match section.inputs[k as usize] {
                Input::Time => self.push(TKind::Time, &[]),
                Input::State(i) => self.push(TKind::State(i as u32), &[]),
                Input::Param(_) | Input::ParamConstant(_) | Input::Slot(_) => self.push(TKind::Input(k), &[]),
                Input::Rate(i) => return Err(TaylorError::ReadsRates(i)),
            },
            Op::Const(c) => self.constant(c),
            Op::Add(a, b) => self.push(TKind::Add(r(a), r(b)), &[r(a), r(b)]),
            Op::Sub(a, b) => self.push(TKind::Sub(r(a), r(b)), &[r(a), r(b)]),
            Op::Mul(a, b) => self.mul(r(a), r(b)),
            Op::Div(a, b) => self.div(r(a), r(b)),
            Op::Neg(a) => self.push(TKind::Neg(r(a)), &[r(a)]),
            Op::Powi(a, n) => self.powi(r(a), n),
            Op::Sqrt(a) => self.push(TKind::Sqrt(r(a)), &[r(a)]),
            Op::Powf(a, b) => {
                let ln = self.push(TKind::Ln(r(a)), &[r(a)]);
                let prod = self.mul(r(b), ln);
                self.push(TKind::Exp(prod), &[prod])
            }
            Op::Func(f, a) => self.func(f, r(a)),
            Op::Atan2(y, x) => {
                let (y, x) = (r(y), r(x));
                let (yy, xx) = (self.mul(y, y), self.mul(x, x));
                let rr = self.push(TKind::Add(xx, yy), &[xx, yy]);
                self.push(TKind::Atan2(y, x, rr), &[y, x, rr])
            }
        })
    }
}

/// The Taylor program of `section`, a right-hand side whose result `i` is `y_i'` for each of
/// the `n_states` states.
pub fn build(section: &Section, n_states: usize) -> Result<TaylorProgram, TaylorError> {
    if section.results.len() != n_states {
        return Err(TaylorError::NotARightHandSide { results: section.results.len(), states: n_states });
    }
    let mut b = Builder { ops: Vec::new(), pairs: FxHashMap::default(), consts: FxHashMap::default() };
    let mut map = Vec::with_capacity(section.ops.len());
    for op in &section.ops {
        let v = b.op(section, *op, &map)?;
        map.push(v);
    }
    let states = b
        .ops
        .iter()
        .enumerate()
        .filter_map(|(v, op)| match op.kind {
            TKind::State(i) if (i as usize) < n_states => Some((v, map_result(section, &map, i as usize))),
            _ => None,
        })
        .collect();
    if let Some(i) = b.ops.iter().find_map(|op| match op.kind {
        TKind::State(i) if i as usize >= n_states => Some(i as usize),
        _ => None,
    }) {
        return Err(TaylorError::UnknownState(i));
    }
    let results = (0..n_states).map(|i| map_result(section, &map, i)).collect();
    let constants = (0..b.ops.len()).filter(|v| !b.ops[*v].series).collect();
    let time = b.ops.iter().position(|op| op.kind == TKind::Time);
    Ok(TaylorProgram { inputs: section.inputs.clone(), ops: b.ops, results, states, constants, time })
}

/// The Taylor value holding result `i` of the section.
fn map_result(section: &Section, map: &[u32], i: usize) -> usize {
    map[section.results[i] as usize] as usize
}
