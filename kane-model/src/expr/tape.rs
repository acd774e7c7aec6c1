//! Compilation to a flat instruction tape for fast interpreted evaluation.

use num_traits::Float;
use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::eval::number_as;
use super::node::{ExprId, Func, Node, SymbolId};
use super::number::Number;

/// One tape instruction; operands are indices of earlier instructions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// Input slot `k`.
    Input(u32),
    /// A constant.
    Const(f64),
    /// `a + b`.
    Add(u32, u32),
    /// `a - b`.
    Sub(u32, u32),
    /// `a * b`.
    Mul(u32, u32),
    /// `a / b`.
    Div(u32, u32),
    /// `-a`.
    Neg(u32),
    /// `a ^ k` for an integer `k`.
    Powi(u32, i32),
    /// `sqrt(a)`.
    Sqrt(u32),
    /// `a ^ b`.
    Powf(u32, u32),
    /// `f(a)`.
    Func(Func, u32),
    /// `atan2(a, b)`.
    Atan2(u32, u32),
}

/// A straight-line program computing several expressions from an input vector.
#[derive(Clone, Debug)]
pub struct Tape {
    ops: Vec<Op>,
    outputs: Vec<u32>,
    n_inputs: usize,
}

struct Compiler<'a> {
    ar: &'a Arena,
    ops: Vec<Op>,
    reg: FxHashMap<(ExprId, bool), u32>,
    consts: FxHashMap<u64, u32>,
    /// Value numbering: an instruction already emitted is reused, so products and sums that
    /// share a prefix share its instructions.
    emitted: FxHashMap<OpKey, u32>,
}

/// An instruction as a hashable key (constants by bits, commutative operands ordered).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
struct OpKey(u8, u32, u64);

fn key_of(op: Op) -> OpKey {
    let ordered = |a: u32, b: u32| u64::from(a.max(b));
    match op {
        Op::Input(k) => OpKey(0, k, 0),
        Op::Const(c) => OpKey(1, 0, c.to_bits()),
        Op::Add(a, b) => OpKey(2, a.min(b), ordered(a, b)),
        Op::Sub(a, b) => OpKey(3, a, u64::from(b)),
        Op::Mul(a, b) => OpKey(4, a.min(b), ordered(a, b)),
        Op::Div(a, b) => OpKey(5, a, u64::from(b)),
        Op::Neg(a) => OpKey(6, a, 0),
        Op::Powi(a, k) => OpKey(7, a, k as u32 as u64),
        Op::Sqrt(a) => OpKey(8, a, 0),
        Op::Powf(a, b) => OpKey(9, a, u64::from(b)),
        Op::Func(f, a) => OpKey(10 + f as u8, a, 0),
        Op::Atan2(a, b) => OpKey(30, a, u64::from(b)),
    }
}

impl Compiler<'_> {
    fn push(&mut self, op: Op) -> u32 {
        let key = key_of(op);
        if let Some(&r) = self.emitted.get(&key) {
            return r;
        }
        self.ops.push(op);
        let r = (self.ops.len() - 1) as u32;
        self.emitted.insert(key, r);
        r
    }

    fn constant(&mut self, x: f64) -> u32 {
        if let Some(&r) = self.consts.get(&x.to_bits()) {
            return r;
        }
        let r = self.push(Op::Const(x));
        self.consts.insert(x.to_bits(), r);
        r
    }

    /// Register holding `e` (or `-e` when `negate`); children are already compiled.
    fn get(&mut self, e: ExprId, negate: bool) -> u32 {
        if let Some(&r) = self.reg.get(&(e, negate)) {
            return r;
        }
        let r = if negate {
            if let Node::Product(f) = self.ar.node(e) {
                self.product(f, true)
            } else {
                let a = self.get(e, false);
                self.push(Op::Neg(a))
            }
        } else {
            self.reg[&(e, false)]
        };
        self.reg.insert((e, negate), r);
        r
    }

    fn product(&mut self, f: &[ExprId], negate: bool) -> u32 {
        let mut coeff = Number::ONE;
        let mut num: Vec<u32> = Vec::new();
        let mut den: Vec<u32> = Vec::new();
        for &x in f {
            if let Some(n) = self.ar.as_number(x) {
                coeff = n;
                continue;
            }
            if let Node::Pow([b, e]) = *self.ar.node(x) {
                if let Some(k) = self.ar.as_rational(e).and_then(|r| r.as_i64()).filter(|k| *k < 0) {
                    let b = self.get(b, false);
                    den.push(if k == -1 { b } else { self.powi(b, -k) });
                    continue;
                }
            }
            num.push(self.get(x, false));
        }
        if negate {
            coeff = coeff.checked_neg().unwrap_or(coeff);
        }
        let c = coeff.to_f64();
        let mut acc = num.into_iter().reduce(|a, b| self.push(Op::Mul(a, b)));
        if c != 1.0 && c != -1.0 {
            let k = self.constant(c.abs());
            acc = Some(match acc {
                Some(a) => self.push(Op::Mul(k, a)),
                None => k,
            });
        }
        let d = den.into_iter().reduce(|a, b| self.push(Op::Mul(a, b)));
        let mut r = match (acc, d) {
            (Some(a), Some(d)) => self.push(Op::Div(a, d)),
            (Some(a), None) => a,
            (None, Some(d)) => {
                let one = self.constant(1.0);
                self.push(Op::Div(one, d))
            }
            (None, None) => self.constant(1.0),
        };
        if c < 0.0 {
            r = self.push(Op::Neg(r));
        }
        r
    }

    fn powi(&mut self, b: u32, k: i64) -> u32 {
        match k {
            1 => b,
            2 => self.push(Op::Mul(b, b)),
            _ => self.push(Op::Powi(b, i32::try_from(k).unwrap_or(i32::MAX))),
        }
    }

    fn node(&mut self, e: ExprId, inputs: &FxHashMap<SymbolId, u32>) -> Result<u32, ExprError> {
        let ar = self.ar;
        Ok(match ar.node(e) {
            Node::Rational(_) | Node::Float(_) => self.constant(ar.as_number(e).map_or(0.0, Number::to_f64)),
            Node::Symbol(s) => match inputs.get(s) {
                Some(&k) => self.push(Op::Input(k)),
                None => return Err(ExprError::MissingBinding(ar.symbol_info(*s).name.clone())),
            },
            Node::Sum(terms) => {
                let mut acc: Option<u32> = None;
                for &t in terms.iter() {
                    let neg = ar.is_negated(t) && ar.as_number(t).is_none();
                    let r = self.get(t, neg);
                    acc = Some(match (acc, neg) {
                        (None, true) => self.push(Op::Neg(r)),
                        (None, false) => r,
                        (Some(a), true) => self.push(Op::Sub(a, r)),
                        (Some(a), false) => self.push(Op::Add(a, r)),
                    });
                }
                acc.unwrap_or_else(|| self.constant(0.0))
            }
            Node::Product(f) => self.product(f, false),
            Node::Pow([b, x]) => {
                let rb = self.get(*b, false);
                match ar.as_rational(*x) {
                    Some(r) if r.is_integer() && r.as_i64().is_some_and(|k| k > 0) => {
                        self.powi(rb, r.as_i64().unwrap_or(1))
                    }
                    Some(r) if r.numer() == 1 && r.denom() == 2 => self.push(Op::Sqrt(rb)),
                    Some(r) if r.is_integer() => {
                        let p = self.powi(rb, -r.as_i64().unwrap_or(-1));
                        let one = self.constant(1.0);
                        self.push(Op::Div(one, p))
                    }
                    _ => {
                        let rx = self.get(*x, false);
                        self.push(Op::Powf(rb, rx))
                    }
                }
            }
            Node::Func(f, x) => {
                let a = self.get(*x, false);
                self.push(Op::Func(*f, a))
            }
            Node::Atan2([y, x]) => {
                let a = self.get(*y, false);
                let b = self.get(*x, false);
                self.push(Op::Atan2(a, b))
            }
        })
    }
}

impl Tape {
    /// Compiles `roots` with `inputs[k]` read from input slot `k`.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::{Arena, Tape};
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let e = ar.sin(x).unwrap();
    /// let tape = Tape::compile(&ar, &[e], &[ar.as_symbol(x).unwrap()]).unwrap();
    /// let mut out = [0.0];
    /// tape.eval(&[0.5], &mut Vec::new(), &mut out);
    /// assert_eq!(out[0], 0.5f64.sin());
    /// ```
    pub fn compile(ar: &Arena, roots: &[ExprId], inputs: &[SymbolId]) -> Result<Tape, ExprError> {
        let slots: FxHashMap<SymbolId, u32> =
            inputs.iter().enumerate().map(|(k, s)| (*s, k as u32)).collect();
        let mut c = Compiler {
            ar,
            ops: Vec::new(),
            reg: FxHashMap::default(),
            consts: FxHashMap::default(),
            emitted: FxHashMap::default(),
        };
        for id in ar.bottom_up(roots, |_| false) {
            let r = c.node(id, &slots)?;
            c.reg.insert((id, false), r);
        }
        let outputs = roots.iter().map(|r| c.reg[&(*r, false)]).collect();
        Ok(Tape { ops: c.ops, outputs, n_inputs: inputs.len() })
    }

    /// The instructions.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// Number of arithmetic operations (instructions other than inputs and constants).
    pub fn op_count(&self) -> usize {
        self.ops.iter().filter(|o| !matches!(o, Op::Input(_) | Op::Const(_))).count()
    }

    /// Number of input slots.
    pub fn n_inputs(&self) -> usize {
        self.n_inputs
    }

    /// Number of outputs.
    pub fn n_outputs(&self) -> usize {
        self.outputs.len()
    }

    /// Runs the tape: `regs` is scratch space reused between calls, `out` receives the outputs.
    pub fn eval<T: Float>(&self, inputs: &[T], regs: &mut Vec<T>, out: &mut [T]) {
        regs.resize(self.ops.len(), T::zero());
        let regs = &mut regs[..self.ops.len()];
        for (i, op) in self.ops.iter().enumerate() {
            let v = match *op {
                Op::Input(k) => inputs[k as usize],
                Op::Const(c) => number_as(Number::Float(c)),
                Op::Add(a, b) => regs[a as usize] + regs[b as usize],
                Op::Sub(a, b) => regs[a as usize] - regs[b as usize],
                Op::Mul(a, b) => regs[a as usize] * regs[b as usize],
                Op::Div(a, b) => regs[a as usize] / regs[b as usize],
                Op::Neg(a) => -regs[a as usize],
                Op::Powi(a, k) => regs[a as usize].powi(k),
                Op::Sqrt(a) => regs[a as usize].sqrt(),
                Op::Powf(a, b) => regs[a as usize].powf(regs[b as usize]),
                Op::Func(f, a) => f.apply(regs[a as usize]),
                Op::Atan2(a, b) => regs[a as usize].atan2(regs[b as usize]),
            };
            regs[i] = v;
        }
        for (o, &k) in out.iter_mut().zip(&self.outputs) {
            *o = regs[k as usize];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tape_matches_interpreter() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let s = ar.add(&[x, y]).unwrap();
        let c = ar.cos(s).unwrap();
        let d = ar.div(c, y).unwrap();
        let three = ar.integer(-3);
        let t = ar.mul(&[three, x, d]).unwrap();
        let e = ar.sub(t, c).unwrap();
        let syms = [ar.as_symbol(x).unwrap(), ar.as_symbol(y).unwrap()];
        let tape = Tape::compile(&ar, &[e, d], &syms).unwrap();
        let mut out = [0.0; 2];
        tape.eval(&[0.3, -1.7], &mut Vec::new(), &mut out);
        let want = ar.eval(&[e, d], |s| Some(if s == syms[0] { 0.3 } else { -1.7 })).unwrap();
        assert!((out[0] - want[0]).abs() < 1e-14 && (out[1] - want[1]).abs() < 1e-14);
    }

    #[test]
    fn missing_input_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        assert_eq!(Tape::compile(&ar, &[x], &[]).unwrap_err(), ExprError::MissingBinding("x".into()));
    }
}
