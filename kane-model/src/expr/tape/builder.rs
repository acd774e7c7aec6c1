//! A tape built instruction by instruction: in come inputs, constants and operations on earlier
//! values; out goes a [`Tape`], each instruction emitted once (value numbering).

use std::hash::Hash;

use rustc_hash::FxHashMap;

use super::{Op, Tape};

/// Builds a tape, numbering values so that an instruction already emitted is reused.
#[derive(Clone, Debug)]
pub struct TapeBuilder<I> {
    tape: Tape<I>,
    inputs: FxHashMap<I, u32>,
    emitted: FxHashMap<(u8, u32, u64), u32>,
}

impl<I> Default for TapeBuilder<I> {
    fn default() -> Self {
        TapeBuilder { tape: Tape::default(), inputs: FxHashMap::default(), emitted: FxHashMap::default() }
    }
}

impl<I: Copy + Eq + Hash> TapeBuilder<I> {
    /// The value of an input.
    pub fn input(&mut self, input: I) -> u32 {
        if let Some(&v) = self.inputs.get(&input) {
            return v;
        }
        self.tape.inputs.push(input);
        let v = self.push(Op::Input((self.tape.inputs.len() - 1) as u32));
        self.inputs.insert(input, v);
        v
    }

    /// The value of a constant.
    pub fn constant(&mut self, x: f64) -> u32 {
        self.push(Op::Const(x))
    }

    /// Appends an instruction (or finds the same one) and returns its value.
    pub fn push(&mut self, op: Op) -> u32 {
        let key = key_of(op);
        if let Some(&v) = self.emitted.get(&key) {
            return v;
        }
        self.tape.ops.push(op);
        let v = (self.tape.ops.len() - 1) as u32;
        self.emitted.insert(key, v);
        v
    }

    /// `a + b`.
    pub fn add(&mut self, a: u32, b: u32) -> u32 {
        self.push(Op::Add(a, b))
    }
    /// `a - b`.
    pub fn sub(&mut self, a: u32, b: u32) -> u32 {
        self.push(Op::Sub(a, b))
    }
    /// `a * b`.
    pub fn mul(&mut self, a: u32, b: u32) -> u32 {
        self.push(Op::Mul(a, b))
    }
    /// `a / b`.
    pub fn div(&mut self, a: u32, b: u32) -> u32 {
        self.push(Op::Div(a, b))
    }

    /// Declares the tape's results and returns it.
    pub fn finish(mut self, results: Vec<u32>) -> Tape<I> {
        self.tape.results = results;
        self.tape
    }
}

/// An instruction as a hashable key (constants by their bits).
fn key_of(op: Op) -> (u8, u32, u64) {
    match op {
        Op::Input(k) => (0, k, 0),
        Op::Const(c) => (1, 0, c.to_bits()),
        Op::Add(a, b) => (2, a, u64::from(b)),
        Op::Sub(a, b) => (3, a, u64::from(b)),
        Op::Mul(a, b) => (4, a, u64::from(b)),
        Op::Div(a, b) => (5, a, u64::from(b)),
        Op::Neg(a) => (6, a, 0),
        Op::Powi(a, k) => (7, a, u64::from(k as u32)),
        Op::Sqrt(a) => (8, a, 0),
        Op::Powf(a, b) => (9, a, u64::from(b)),
        Op::Func(f, a) => (10 + f as u8, a, 0),
        Op::Atan2(a, b) => (60, a, u64::from(b)),
    }
}
