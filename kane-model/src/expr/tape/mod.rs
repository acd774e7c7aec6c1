//! Straight-line programs: in come expression roots (through [`Tape::compile`], or instruction
//! by instruction through a [`TapeBuilder`]); out goes a [`Tape`], one SSA list of elementary
//! operations ([`Op`]) with what each input reads, evaluated by [`Tape::eval`] and counted by
//! [`Tape::op_count`]. The same program serves interpreted evaluation (with symbols or slots as
//! inputs) and code generation (whose sections are tapes of its own inputs).

mod builder;
mod compile;

use std::hash::Hash;

use num_traits::Float;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Func, SymbolId};

pub use builder::TapeBuilder;
pub(crate) use compile::Compiler;

/// One instruction; operands are the values of earlier instructions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// Input `k` of the tape's input list.
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

/// A straight-line program: instruction `k` defines value `k`, its operands are earlier values,
/// and `Op::Input(k)` reads `inputs[k]` (a symbol, a slot, or whatever `I` names).
#[derive(Clone, Debug, PartialEq)]
pub struct Tape<I> {
    /// What `Op::Input(k)` reads.
    pub inputs: Vec<I>,
    /// The instructions, in order.
    pub ops: Vec<Op>,
    /// The values the tape returns, in order.
    pub results: Vec<u32>,
}

impl<I> Default for Tape<I> {
    fn default() -> Self {
        Tape { inputs: Vec::new(), ops: Vec::new(), results: Vec::new() }
    }
}

impl<I: Copy + Eq + Hash> Tape<I> {
    /// Compiles `roots` (shared subexpressions computed once), each symbol read as the input
    /// `input` names; an error names a symbol `input` has no input for.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::{Arena, Tape};
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let e = ar.sin(x).unwrap();
    /// let tape = Tape::compile(&ar, &[e], |s| (Some(s) == ar.as_symbol(x)).then_some(0)).unwrap();
    /// let mut out = [0.0];
    /// tape.eval(|k: usize| [0.5][k], &mut out);
    /// assert_eq!(out[0], 0.5f64.sin());
    /// assert_eq!(tape.op_count(), 1);
    /// ```
    pub fn compile(
        ar: &Arena,
        roots: &[ExprId],
        input: impl Fn(SymbolId) -> Option<I>,
    ) -> Result<Tape<I>, ExprError> {
        let mut compiler = Compiler::new(ar, input, None);
        let results = compiler.lower_all(roots);
        match compiler.missing() {
            Some(s) => Err(ExprError::MissingBinding(ar.symbol_info(s).name.clone())),
            None => Ok(compiler.builder.finish(results)),
        }
    }
}

impl<I: Copy> Tape<I> {
    /// Runs the tape: `read` gives each input's value, `out` receives the results.
    pub fn eval<T: Float>(&self, read: impl Fn(I) -> T, out: &mut [T]) {
        self.eval_in(read, &mut Vec::with_capacity(self.ops.len()), out)
    }

    /// [`Tape::eval`] with the values kept in `regs` (cleared first, so one buffer serves many
    /// calls without allocating).
    pub fn eval_in<T: Float>(&self, read: impl Fn(I) -> T, regs: &mut Vec<T>, out: &mut [T]) {
        regs.clear();
        for op in &self.ops {
            let v = self.apply(op, regs, &read);
            regs.push(v);
        }
        for (o, v) in out.iter_mut().zip(&self.results) {
            *o = regs[*v as usize];
        }
    }

    /// The value of instruction `op`, its operands read from `regs` (the earlier values).
    pub(crate) fn apply<T: Float>(&self, op: &Op, regs: &[T], read: &impl Fn(I) -> T) -> T {
        let r = |v: u32| regs[v as usize];
        match *op {
            Op::Input(k) => read(self.inputs[k as usize]),
            Op::Const(c) => T::from(c).unwrap_or_else(T::nan),
            Op::Add(a, b) => r(a) + r(b),
            Op::Sub(a, b) => r(a) - r(b),
            Op::Mul(a, b) => r(a) * r(b),
            Op::Div(a, b) => r(a) / r(b),
            Op::Neg(a) => -r(a),
            Op::Powi(a, k) => r(a).powi(k),
            Op::Sqrt(a) => r(a).sqrt(),
            Op::Powf(a, b) => r(a).powf(r(b)),
            Op::Func(f, a) => f.apply(r(a)),
            Op::Atan2(a, b) => r(a).atan2(r(b)),
        }
    }
}

impl<I> Tape<I> {
    /// Arithmetic operations: the instructions other than inputs and constants.
    pub fn op_count(&self) -> usize {
        self.ops.iter().filter(|o| !matches!(o, Op::Input(_) | Op::Const(_))).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slots(syms: &[SymbolId]) -> impl Fn(SymbolId) -> Option<usize> + '_ {
        |s| syms.iter().position(|x| *x == s)
    }

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
        let tape = Tape::compile(&ar, &[e, d], slots(&syms)).unwrap();
        let mut out = [0.0; 2];
        tape.eval(|k| [0.3, -1.7][k], &mut out);
        let want = ar.eval(&[e, d], |s| Some(if s == syms[0] { 0.3 } else { -1.7 })).unwrap();
        assert!((out[0] - want[0]).abs() < 1e-14 && (out[1] - want[1]).abs() < 1e-14);
    }

    #[test]
    fn missing_input_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let err = Tape::<usize>::compile(&ar, &[x], |_| None).unwrap_err();
        assert_eq!(err, ExprError::MissingBinding("x".into()));
    }

    #[test]
    fn a_deep_expression_compiles_without_deep_recursion() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let mut e = x;
        for k in 0..100_000 {
            let c = ar.integer(k % 7 + 2);
            e = if k % 2 == 0 { ar.add(&[e, c]).unwrap() } else { ar.mul(&[e, c]).unwrap() };
            e = ar.sin(e).unwrap();
        }
        let tape = Tape::compile(&ar, &[e], Some).unwrap();
        let mut out = [0.0];
        tape.eval(|_| 0.25, &mut out);
        let want = ar.eval(&[e], |_| Some(0.25)).unwrap()[0];
        assert!((out[0] - want).abs() < 1e-12, "{} vs {want}", out[0]);
    }
}
