//! The lowered program: in come the equations and outputs of a spec (through
//! [`super::lower`]); out goes a [`Program`], straight-line SSA sections of elementary operations
//! ([`Op`], the tape's instruction set) that every consumer reads: the Rust printer, operation
//! counts, and later events and Taylor coefficients.

use rustc_hash::FxHashMap;

pub use crate::expr::Op;

/// A value a section reads from outside.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Input {
    /// Time.
    Time,
    /// State `i` (coordinates, then speeds).
    State(usize),
    /// Parameter `i`.
    Param(usize),
    /// Parameter-only quantity `i`, computed by the `derive` section.
    Derived(usize),
    /// The speed rate `u'_i`, computed by the `rhs` section.
    Rate(usize),
    /// Positional value `i` the caller gives (an event expression's names: see
    /// [`super::event`]); model sections never read one.
    Slot(usize),
}

/// One straight-line section: instruction `k` defines value `k`; operands are earlier values.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Section {
    /// What `Op::Input(k)` reads.
    pub inputs: Vec<Input>,
    /// The instructions, in order.
    pub ops: Vec<Op>,
    /// The values the section returns, in order.
    pub results: Vec<u32>,
}

impl Section {
    /// Runs the section: `read` gives each input's value, `out` receives the results.
    pub fn eval<T: num_traits::Float>(&self, read: impl Fn(Input) -> T, out: &mut [T]) {
        self.eval_in(read, &mut Vec::with_capacity(self.ops.len()), out)
    }

    /// [`Section::eval`] with the values kept in `regs` (cleared first, so one buffer serves
    /// many calls without allocating).
    pub fn eval_in<T: num_traits::Float>(&self, read: impl Fn(Input) -> T, regs: &mut Vec<T>, out: &mut [T]) {
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
    pub(crate) fn apply<T: num_traits::Float>(&self, op: &Op, regs: &[T], read: &impl Fn(Input) -> T) -> T {
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

    /// Arithmetic operations (instructions other than inputs and constants).
    pub fn op_count(&self) -> usize {
        self.ops.iter().filter(|o| !matches!(o, Op::Input(_) | Op::Const(_))).count()
    }
}

/// Builds a section, numbering values so that an instruction already emitted is reused.
#[derive(Default)]
pub struct SectionBuilder {
    section: Section,
    inputs: FxHashMap<Input, u32>,
    emitted: FxHashMap<(u8, u32, u64), u32>,
}

impl SectionBuilder {
    /// The value of an input.
    pub fn input(&mut self, input: Input) -> u32 {
        if let Some(&v) = self.inputs.get(&input) {
            return v;
        }
        self.section.inputs.push(input);
        let v = self.push(Op::Input((self.section.inputs.len() - 1) as u32));
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
        self.section.ops.push(op);
        let v = (self.section.ops.len() - 1) as u32;
        self.emitted.insert(key, v);
        v
    }

    /// `a + b`, `a - b`, `a * b`, `a / b`.
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

    /// Declares the section's results and returns it.
    pub fn finish(mut self, results: Vec<u32>) -> Section {
        self.section.results = results;
        self.section
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

/// One output's section and what the driver needs to know about it.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputCode {
    /// Its instructions; results are its components.
    pub section: Section,
    /// The states its value depends on (coordinates that cancel are left out).
    pub reads: Vec<usize>,
    /// Whether it reads the speed rates `u'` (then the driver evaluates `rhs` first).
    pub needs_rates: bool,
}

/// The lowered program of one model.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Parameter-only quantities, in `f64`, once per parameter set; inputs are parameters.
    pub derive: Section,
    /// `y' = f(t, y)`: results are `q'` then `u'`.
    pub rhs: Section,
    /// One section per output.
    pub outputs: Vec<OutputCode>,
    /// Coordinates no equation reads (cyclic).
    pub cyclic: Vec<usize>,
    /// Number of coordinates.
    pub n_coordinates: usize,
}

impl Program {
    /// Operations per `rhs` call and per evaluation of all outputs.
    pub fn op_counts(&self) -> (usize, usize) {
        (self.rhs.op_count(), self.outputs.iter().map(|o| o.section.op_count()).sum())
    }
}
