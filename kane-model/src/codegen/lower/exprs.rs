//! Expressions into a section: in come expression roots and how each symbol is read; out go
//! SSA values. The shape of each computation (subtraction, quotients, balanced products, late
//! factors last) is the printers' shared layout, so generated code computes what a reader of
//! the printed equations sees.

use rustc_hash::FxHashMap;

use crate::expr::{layout, Arena, Cse, ExprId, Func, Number, Op, Prec, SymbolId, Syntax};

use super::super::ir::{Input, SectionBuilder};

/// Lowers expressions into one section.
pub struct ExprLowering<'a> {
    ar: &'a Arena,
    /// The section being built.
    pub builder: SectionBuilder,
    symbols: &'a FxHashMap<SymbolId, Input>,
    names: FxHashMap<ExprId, u32>,
    late: Option<&'a dyn Fn(ExprId) -> bool>,
}

impl<'a> ExprLowering<'a> {
    /// A lowering reading symbols through `symbols`; `late` marks factors to multiply last.
    pub fn new(
        ar: &'a Arena,
        symbols: &'a FxHashMap<SymbolId, Input>,
        late: Option<&'a dyn Fn(ExprId) -> bool>,
    ) -> Self {
        ExprLowering { ar, builder: SectionBuilder::default(), symbols, names: FxHashMap::default(), late }
    }

    /// Lowers the shared subexpressions of `roots` (children first), then each root; returns the
    /// roots' values.
    pub fn lower_all(&mut self, roots: &[ExprId]) -> Vec<u32> {
        let cse = Cse::new(self.ar, roots);
        for &e in &cse.temps {
            let v = layout(self.ar, e, self, true).0;
            self.names.insert(e, v);
        }
        roots.iter().map(|&e| self.value(e)).collect()
    }

    /// Makes `e` (a symbol's expression) read the value `v` computed earlier in the section.
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

impl Syntax for ExprLowering<'_> {
    type Out = u32;
    fn number(&mut self, n: Number) -> u32 {
        self.builder.constant(n.to_f64())
    }
    fn symbol(&mut self, s: SymbolId) -> u32 {
        match self.symbols.get(&s) {
            Some(&input) => self.builder.input(input),
            // Callers check the symbols first; an unknown one cannot be computed.
            None => self.builder.constant(f64::NAN),
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
