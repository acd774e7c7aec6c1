//! Expressions into a tape: in come expression roots and the input each symbol reads; out go
//! SSA values in a [`TapeBuilder`]. The shape of each computation (subtraction, quotients,
//! balanced products, late factors last) is the printers' shared layout, so generated code
//! computes what a reader of the printed equations sees.

use std::hash::Hash;

use rustc_hash::{FxHashMap, FxHashSet};

use super::super::arena::Arena;
use super::super::cse::Cse;
use super::super::node::{ExprId, Func, SymbolId};
use super::super::number::Number;
use super::super::print::layout::{layout, Prec, Syntax};
use super::{Op, TapeBuilder};

/// How deep the layout of one expression may nest before a node is computed ahead, as if it
/// were shared: the layout recurses, so this bounds its stack on deep expressions (no model's
/// equations come near it).
const MAX_NESTING: usize = 200;

/// Compiles expressions into one tape.
pub(crate) struct Compiler<'a, I> {
    ar: &'a Arena,
    /// The tape being built.
    pub builder: TapeBuilder<I>,
    symbols: Box<dyn Fn(SymbolId) -> Option<I> + 'a>,
    names: FxHashMap<ExprId, u32>,
    late: Option<&'a dyn Fn(ExprId) -> bool>,
    missing: Option<SymbolId>,
}

impl<'a, I: Copy + Eq + Hash> Compiler<'a, I> {
    /// A compiler reading each symbol as the input `symbols` names; `late` marks factors to
    /// multiply last.
    pub fn new(
        ar: &'a Arena,
        symbols: impl Fn(SymbolId) -> Option<I> + 'a,
        late: Option<&'a dyn Fn(ExprId) -> bool>,
    ) -> Self {
        let (builder, symbols, names) = (TapeBuilder::default(), Box::new(symbols), FxHashMap::default());
        Compiler { ar, builder, symbols, names, late, missing: None }
    }

    /// Lowers the shared subexpressions of `roots` (children first), then each root; returns the
    /// roots' values.
    pub fn lower_all(&mut self, roots: &[ExprId]) -> Vec<u32> {
        for e in self.ahead(roots) {
            let v = layout(self.ar, e, self, true).0;
            self.names.insert(e, v);
        }
        roots.iter().map(|&e| self.value(e)).collect()
    }

    /// The nodes of `roots` computed ahead of them, children first: the shared ones, and any
    /// whose layout would nest deeper than [`MAX_NESTING`] below a node computed ahead.
    fn ahead(&self, roots: &[ExprId]) -> Vec<ExprId> {
        let shared: FxHashSet<ExprId> = Cse::new(self.ar, roots).temps.into_iter().collect();
        let mut depth: FxHashMap<ExprId, usize> = FxHashMap::default();
        let mut ahead = Vec::new();
        for id in self.ar.bottom_up(roots, |_| false) {
            let below = self.ar.node(id).children().iter().map(|c| depth.get(c).copied().unwrap_or(0)).max();
            let d = match below {
                _ if self.names.contains_key(&id) => 0,
                Some(d) => d + 1,
                None => 0,
            };
            if shared.contains(&id) || d >= MAX_NESTING {
                ahead.push(id);
                depth.insert(id, 0);
            } else {
                depth.insert(id, d);
            }
        }
        ahead
    }

    /// Makes `e` (a symbol's expression) read the value `v` computed earlier in the tape.
    pub fn bind(&mut self, e: ExprId, v: u32) {
        self.names.insert(e, v);
    }

    /// The value of `e`: its shared name, or `e` lowered.
    pub fn value(&mut self, e: ExprId) -> u32 {
        match self.names.get(&e) {
            Some(&v) => v,
            None => layout(self.ar, e, self, true).0,
        }
    }

    /// The first symbol read that has no input (its value is NaN), if any.
    pub fn missing(&self) -> Option<SymbolId> {
        self.missing
    }

    fn balanced(&mut self, factors: Vec<(u32, Prec)>) -> u32 {
        let mut level: Vec<u32> = factors.into_iter().map(|f| f.0).collect();
        while level.len() > 1 {
            let mut next = Vec::with_capacity(level.len().div_ceil(2));
            let mut it = level.into_iter();
            while let Some(a) = it.next() {
                next.push(match it.next() {
                    Some(b) => self.builder.mul(a, b),
                    None => a,
                });
            }
            level = next;
        }
        level.pop().unwrap_or_else(|| self.builder.constant(1.0))
    }
}

impl<I: Copy + Eq + Hash> Syntax for Compiler<'_, I> {
    type Out = u32;
    fn number(&mut self, n: Number) -> u32 {
        self.builder.constant(n.to_f64())
    }
    fn symbol(&mut self, s: SymbolId) -> u32 {
        match (self.symbols)(s) {
            Some(input) => self.builder.input(input),
            None => {
                self.missing = self.missing.or(Some(s));
                self.builder.constant(f64::NAN)
            }
        }
    }
    fn named(&mut self, id: ExprId) -> Option<u32> {
        self.names.get(&id).copied()
    }
    fn paren(&mut self, x: u32) -> u32 {
        x
    }
    fn sum(&mut self, terms: Vec<(bool, u32)>) -> u32 {
        let mut acc: Option<u32> = None;
        for (neg, t) in terms {
            acc = Some(match (acc, neg) {
                (None, true) => self.builder.push(Op::Neg(t)),
                (None, false) => t,
                (Some(a), true) => self.builder.sub(a, t),
                (Some(a), false) => self.builder.add(a, t),
            });
        }
        acc.unwrap_or_else(|| self.builder.constant(0.0))
    }
    fn neg(&mut self, x: (u32, Prec)) -> u32 {
        self.builder.push(Op::Neg(x.0))
    }
    fn product(&mut self, factors: Vec<(u32, Prec)>) -> u32 {
        self.balanced(factors)
    }
    fn late(&mut self, id: ExprId) -> bool {
        self.late.is_some_and(|late| late(id))
    }
    fn product_grouped(&mut self, early: Vec<(u32, Prec)>, late: Vec<(u32, Prec)>) -> u32 {
        match (early.is_empty(), late.is_empty()) {
            (true, _) => self.balanced(late),
            (_, true) => self.balanced(early),
            _ => {
                let (e, l) = (self.balanced(early), self.balanced(late));
                self.builder.mul(e, l)
            }
        }
    }
    fn quotient(&mut self, num: (u32, Prec), den: (u32, Prec)) -> u32 {
        self.builder.div(num.0, den.0)
    }
    fn pow_int(&mut self, base: (u32, Prec), k: i64) -> u32 {
        self.builder.push(Op::Powi(base.0, i32::try_from(k).unwrap_or(i32::MAX)))
    }
    fn pow(&mut self, base: (u32, Prec), exp: (u32, Prec)) -> u32 {
        self.builder.push(Op::Powf(base.0, exp.0))
    }
    fn sqrt(&mut self, x: (u32, Prec)) -> u32 {
        self.builder.push(Op::Sqrt(x.0))
    }
    fn func(&mut self, f: Func, x: (u32, Prec)) -> u32 {
        self.builder.push(Op::Func(f, x.0))
    }
    fn atan2(&mut self, y: u32, x: u32) -> u32 {
        self.builder.push(Op::Atan2(y, x))
    }
}
