//! One section in machine code: in comes a [`Section`]; out goes a [`CompiledSection`], a
//! native function compiled in process by Cranelift that performs the section's operations in
//! the evaluator's order (no reassociation, no fused multiply-add), so its results equal the
//! evaluator's.

use std::collections::{HashMap, HashSet};

use cranelift_codegen::ir::{types, InstBuilder, MemFlagsData, Value};
use cranelift_frontend::FunctionBuilder;
use cranelift_jit::JITModule;

use super::math::{self, Callee, Callees};
use super::native::{NativeCode, Param};
use super::JitError;
use crate::expr::Func;
use crate::program::ir::{Input, Op, Section};

/// What a compiled section reads: time and five arrays.
#[derive(Clone, Copy, Debug)]
pub struct Reads<'a> {
    /// Time.
    pub t: f64,
    /// The state.
    pub y: &'a [f64],
    /// Parameters.
    pub params: &'a [f64],
    /// Parameter-only quantities.
    pub constants: &'a [f64],
    /// Speed rates `u'`.
    pub rates: &'a [f64],
    /// Positional values (event sections' names).
    pub slots: &'a [f64],
}

/// The arrays a section reads, in the order of the native function's pointer arguments.
const ARRAYS: usize = 5;

type NativeFn =
    unsafe extern "C" fn(f64, *const f64, *const f64, *const f64, *const f64, *const f64, *mut f64);

/// A section compiled to machine code, callable from any thread.
pub struct CompiledSection {
    code: NativeCode,
    /// The least length of each array the code reads (one past the largest index).
    lengths: [usize; ARRAYS],
    results: usize,
}

impl std::fmt::Debug for CompiledSection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CompiledSection").field("results", &self.results).finish_non_exhaustive()
    }
}

impl CompiledSection {
    /// Compiles `section` for this machine.
    pub fn new(section: &Section) -> Result<CompiledSection, JitError> {
        let mut params = vec![Param::F64];
        params.extend([Param::Pointer; ARRAYS + 1]);
        let (code, lengths) = NativeCode::compile(&params, |module, b| Body::new(module, b).emit(section))?;
        Ok(CompiledSection { code, lengths, results: section.results.len() })
    }

    /// Number of results.
    pub fn results(&self) -> usize {
        self.results
    }

    /// Runs the section on `reads`, its results into `out`.
    ///
    /// # Panics
    /// When an array is shorter than the section reads or `out` shorter than its results.
    pub fn run(&self, reads: &Reads<'_>, out: &mut [f64]) {
        let arrays = [reads.y, reads.params, reads.constants, reads.rates, reads.slots];
        for (array, &least) in arrays.iter().zip(&self.lengths) {
            assert!(
                array.len() >= least,
                "a compiled section reads {least} values of an array of {}",
                array.len()
            );
        }
        assert!(out.len() >= self.results, "a compiled section writes {} results", self.results);
        let [y, params, constants, rates, slots] = arrays.map(<[f64]>::as_ptr);
        // SAFETY: the code was compiled from a signature of exactly these parameters.
        let function = unsafe { std::mem::transmute::<*const u8, NativeFn>(self.code.address()) };
        // SAFETY: every index the code reads is below the lengths checked above, and it writes
        // `out[..results]` only.
        unsafe { function(reads.t, y, params, constants, rates, slots, out.as_mut_ptr()) }
    }
}

/// The function body being emitted: its block's parameters and the callees declared so far.
struct Body<'m, 'b, 'f> {
    module: &'m mut JITModule,
    b: &'b mut FunctionBuilder<'f>,
    callees: Callees,
    /// The operands whose sine and cosine are both taken.
    paired: HashSet<u32>,
    /// `(sin, cos)` of a paired operand, once computed.
    sin_cos: HashMap<u32, (Value, Value)>,
}

impl<'m, 'b, 'f> Body<'m, 'b, 'f> {
    fn new(module: &'m mut JITModule, b: &'b mut FunctionBuilder<'f>) -> Self {
        Body { module, b, callees: Callees::default(), paired: HashSet::new(), sin_cos: HashMap::new() }
    }

    /// Emits `section` as the whole function; returns the least length of each array it reads.
    fn emit(&mut self, section: &Section) -> Result<[usize; ARRAYS], JitError> {
        let block = self.b.create_block();
        self.b.append_block_params_for_function_params(block);
        self.b.switch_to_block(block);
        self.b.seal_block(block);
        let params = self.b.block_params(block).to_vec();
        let (t, arrays, out) = (params[0], &params[1..=ARRAYS], params[ARRAYS + 1]);
        self.paired = paired_operands(section);
        let mut lengths = [0; ARRAYS];
        let mut load_input = |body: &mut Self, k: u32| -> Result<Value, JitError> {
            match array_of(section.inputs[k as usize]) {
                None => Ok(t),
                Some((array, index)) => {
                    lengths[array] = lengths[array].max(index + 1);
                    body.load(arrays[array], index)
                }
            }
        };
        let mut values: Vec<Value> = Vec::with_capacity(section.ops.len());
        for op in &section.ops {
            let value = match *op {
                Op::Input(k) => load_input(self, k)?,
                ref op => self.operation(op, &section.ops, &values)?,
            };
            values.push(value);
        }
        for (k, &v) in section.results.iter().enumerate() {
            self.b.ins().store(MemFlagsData::trusted(), values[v as usize], out, offset(k)?);
        }
        self.b.ins().return_(&[]);
        Ok(lengths)
    }

    /// `array[index]`.
    fn load(&mut self, array: Value, index: usize) -> Result<Value, JitError> {
        Ok(self.b.ins().load(types::F64, MemFlagsData::trusted().with_readonly(), array, offset(index)?))
    }

    /// The value of an arithmetic instruction of `ops`, its operands among `values`.
    fn operation(&mut self, op: &Op, ops: &[Op], values: &[Value]) -> Result<Value, JitError> {
        let v = |i: u32| values[i as usize];
        Ok(match *op {
            Op::Input(_) => unreachable!("inputs are loaded by `emit`"),
            Op::Const(c) => self.b.ins().f64const(c),
            Op::Add(a, b) => self.b.ins().fadd(v(a), v(b)),
            Op::Sub(a, b) => self.b.ins().fsub(v(a), v(b)),
            Op::Mul(a, b) => self.b.ins().fmul(v(a), v(b)),
            Op::Div(a, b) => match exact_reciprocal(ops[b as usize]) {
                Some(r) => {
                    let r = self.b.ins().f64const(r);
                    self.b.ins().fmul(v(a), r)
                }
                None => self.b.ins().fdiv(v(a), v(b)),
            },
            Op::Neg(a) => self.b.ins().fneg(v(a)),
            Op::Sqrt(a) => self.b.ins().sqrt(v(a)),
            Op::Powi(a, k) => self.powi(v(a), k),
            Op::Powf(a, b) => self.call(math::powf_callee(), &[v(a), v(b)])?,
            Op::Atan2(a, b) => self.call(math::atan2_callee(), &[v(a), v(b)])?,
            Op::Func(f @ (Func::Sin | Func::Cos), a) if self.paired.contains(&a) => {
                let (sin, cos) = self.sin_cos(a, v(a))?;
                if f == Func::Sin {
                    sin
                } else {
                    cos
                }
            }
            Op::Func(f, a) => match math::unary(f) {
                Some(callee) => self.call(callee, &[v(a)])?,
                None => self.b.ins().fabs(v(a)),
            },
        })
    }

    /// `x ^ k` by the multiplications of the runtime's `powi` (binary powering, then one
    /// division for a negative power), so the value is the same to the last bit.
    fn powi(&mut self, x: Value, k: i32) -> Value {
        let mut result: Option<Value> = None;
        let (mut base, mut n) = (x, k.unsigned_abs());
        loop {
            if n & 1 == 1 {
                result = Some(match result {
                    None => base,
                    Some(r) => self.b.ins().fmul(r, base),
                });
            }
            n /= 2;
            if n == 0 {
                break;
            }
            base = self.b.ins().fmul(base, base);
        }
        let value = result.unwrap_or_else(|| self.b.ins().f64const(1.0));
        if k < 0 {
            let one = self.b.ins().f64const(1.0);
            self.b.ins().fdiv(one, value)
        } else {
            value
        }
    }

    /// `(sin, cos)` of operand `a` (value `x`), by one call the first time.
    fn sin_cos(&mut self, a: u32, x: Value) -> Result<(Value, Value), JitError> {
        if let Some(&pair) = self.sin_cos.get(&a) {
            return Ok(pair);
        }
        let results = self.call_all(math::sin_cos_callee(), &[x])?;
        let pair = (results[0], results[1]);
        self.sin_cos.insert(a, pair);
        Ok(pair)
    }

    /// A call of `callee` on `args`: its first result.
    fn call(&mut self, callee: Callee, args: &[Value]) -> Result<Value, JitError> {
        Ok(self.call_all(callee, args)?[0])
    }

    /// A call of `callee` on `args`: its results.
    fn call_all(&mut self, callee: Callee, args: &[Value]) -> Result<Vec<Value>, JitError> {
        self.callees.call(self.module, self.b, callee, args)
    }
}

/// `1 / c` for a constant `c` whose reciprocal is exact (a power of two, its reciprocal
/// normal), so dividing by `c` and multiplying by it give the same bits.
fn exact_reciprocal(op: Op) -> Option<f64> {
    let Op::Const(c) = op else { return None };
    let r = 1.0 / c;
    let power_of_two = c.is_normal() && c.to_bits() & ((1u64 << 52) - 1) == 0;
    (power_of_two && r.is_normal()).then_some(r)
}

/// The operands of `section` whose sine and cosine are both taken (computed by one call).
fn paired_operands(section: &Section) -> HashSet<u32> {
    let (mut sines, mut cosines) = (HashSet::new(), HashSet::new());
    for op in &section.ops {
        match *op {
            Op::Func(Func::Sin, a) => sines.insert(a),
            Op::Func(Func::Cos, a) => cosines.insert(a),
            _ => false,
        };
    }
    sines.intersection(&cosines).copied().collect()
}

/// Which array an input is read from and at what index; None for time.
fn array_of(input: Input) -> Option<(usize, usize)> {
    match input {
        Input::Time => None,
        Input::State(i) => Some((0, i)),
        Input::Param(i) => Some((1, i)),
        Input::ParamConstant(i) => Some((2, i)),
        Input::Rate(i) => Some((3, i)),
        Input::Slot(i) => Some((4, i)),
    }
}

/// The byte offset of `f64` number `index`.
pub(super) fn offset(index: usize) -> Result<i32, JitError> {
    index
        .checked_mul(8)
        .and_then(|b| i32::try_from(b).ok())
        .ok_or_else(|| JitError::Compile(format!("index {index} is past what one section can address")))
}
