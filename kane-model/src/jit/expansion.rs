//! The Taylor coefficients of one order in machine code, the whole expansion written out: in
//! comes a [`TaylorProgram`] and an order `p`; out goes a [`CompiledExpansion`], native code that
//! computes the states' coefficients `0..=p` through `(t, y)` straight into the output, as the
//! generated Rust's `taylor_order_p` does: order 0 by the evaluator's functions, then every pass
//! with its sums written out and summed as the generated Rust sums them (fused multiply-adds, in
//! chains: its numbers to rounding), every coefficient kept in a register.

use std::collections::HashMap;

use cranelift_codegen::ir::condcodes::FloatCC;
use cranelift_codegen::ir::{types, InstBuilder, MemFlagsData, Value};
use cranelift_frontend::FunctionBuilder;
use cranelift_jit::JITModule;
use cranelift_module::Module;

use super::math::{self, Callees};
use super::native::{NativeCode, Param};
use super::recurrence::{Order, Pass};
use super::section::offset;
use super::JitError;
use crate::expr::Func;
use crate::program::ir::Input;
use crate::program::taylor::{TKind, TaylorProgram};
use crate::runtime::taylor::{Inverse, MAX_ORDER};

type ExpansionFn = unsafe extern "C" fn(f64, *const f64, *const f64, *const f64, *mut f64);

/// The arrays the code reads: the state, parameters and parameter-only quantities.
const ARRAYS: usize = 3;

/// A Taylor expansion of one order compiled to machine code, callable from any thread.
pub struct CompiledExpansion {
    code: NativeCode,
    order: usize,
    states: usize,
    /// The least length of each array the code reads (one past the largest index).
    lengths: [usize; ARRAYS],
}

impl std::fmt::Debug for CompiledExpansion {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CompiledExpansion").field("order", &self.order).finish_non_exhaustive()
    }
}

impl CompiledExpansion {
    /// Compiles the expansion of `program` to `order`, written out.
    pub fn new(program: &TaylorProgram, order: usize) -> Result<CompiledExpansion, JitError> {
        if !(1..=MAX_ORDER).contains(&order) {
            return Err(JitError::Compile(format!("a Taylor order of {order}, past {MAX_ORDER}")));
        }
        let params = [Param::F64, Param::Pointer, Param::Pointer, Param::Pointer, Param::Pointer];
        let (code, lengths) = NativeCode::compile(&params, |module, b| emit(module, b, program, order))?;
        Ok(CompiledExpansion { code, order, states: program.results.len(), lengths })
    }

    /// The normalised Taylor coefficients through `(t, y)`, orders `0..=order`, into `out`
    /// (state-major, as [`TaylorProgram::coefficients`] writes them).
    ///
    /// # Panics
    /// When an array is shorter than the code reads or `out` shorter than the coefficients.
    pub fn run(&self, t: f64, y: &[f64], params: &[f64], constants: &[f64], out: &mut [f64]) {
        for (array, &least) in [y, params, constants].iter().zip(&self.lengths) {
            assert!(
                array.len() >= least,
                "a Taylor expansion reads {least} values of an array of {}",
                array.len()
            );
        }
        let coefficients = self.states * (self.order + 1);
        assert!(out.len() >= coefficients, "a Taylor expansion writes {coefficients} coefficients");
        // SAFETY: the code was compiled from a signature of exactly these parameters.
        let function = unsafe { std::mem::transmute::<*const u8, ExpansionFn>(self.code.address()) };
        // SAFETY: every index the code reads is below the lengths checked above, and it writes
        // `out[..coefficients]` only.
        unsafe { function(t, y.as_ptr(), params.as_ptr(), constants.as_ptr(), out.as_mut_ptr()) }
    }
}

/// The whole function: order 0, the passes `1..order`, the states' coefficients into `out`;
/// returns the least length of each array it reads.
fn emit(
    module: &mut JITModule,
    b: &mut FunctionBuilder<'_>,
    program: &TaylorProgram,
    order: usize,
) -> Result<[usize; ARRAYS], JitError> {
    let entry = b.create_block();
    b.append_block_params_for_function_params(entry);
    b.switch_to_block(entry);
    b.seal_block(entry);
    let params = b.block_params(entry).to_vec();
    let (t, arrays, out) = (params[0], [params[1], params[2], params[3]], params[4]);
    let pointer = module.target_config().pointer_type();
    let mut pass = Pass::new(b, pointer, program, Order::Fixed(0));
    let mut lengths = order_zero(module, &mut pass, program, t, arrays)?;
    for k in 1..order {
        pass.set_order(k);
        pass.one_pass(program)?;
    }
    lengths[0] = lengths[0].max(program.results.len());
    finish(&mut pass, program, order, arrays[0], out)?;
    pass.b.ins().return_(&[]);
    Ok(lengths)
}

/// Coefficient 0 of every value; returns the least length of each array read.
fn order_zero(
    module: &mut JITModule,
    pass: &mut Pass<'_, '_>,
    program: &TaylorProgram,
    t: Value,
    arrays: [Value; ARRAYS],
) -> Result<[usize; ARRAYS], JitError> {
    let mut lengths = [0; ARRAYS];
    let mut read = |pass: &mut Pass<'_, '_>, array: usize, index: usize| -> Result<Value, JitError> {
        lengths[array] = lengths[array].max(index + 1);
        let flags = MemFlagsData::trusted().with_readonly();
        Ok(pass.b.ins().load(types::F64, flags, arrays[array], offset(index)?))
    };
    let mut calls = Calls { module, callees: Callees::default(), sin_cos: HashMap::new() };
    for (v, op) in program.ops.iter().enumerate() {
        let value = match op.kind {
            TKind::Time => t,
            TKind::State(i) => read(pass, 0, i as usize)?,
            TKind::Const(c) => pass.b.ins().f64const(c),
            TKind::Input(k) => match program.inputs[k as usize] {
                Input::Time => t,
                Input::State(i) => read(pass, 0, i)?,
                Input::Param(i) => read(pass, 1, i)?,
                Input::ParamConstant(i) => read(pass, 2, i)?,
                input => return Err(JitError::Compile(format!("a Taylor program reading {input:?}"))),
            },
            kind => calls.value_at_zero(pass, kind)?,
        };
        pass.set_known(v, 0, value);
    }
    Ok(lengths)
}

/// The math calls of order 0: the callees declared and the `(sin, cos)` of each angle.
struct Calls<'m> {
    module: &'m mut JITModule,
    callees: Callees,
    sin_cos: HashMap<u32, (Value, Value)>,
}

impl Calls<'_> {
    /// Coefficient 0 of an arithmetic operation `kind`: the operation itself.
    fn value_at_zero(&mut self, pass: &mut Pass<'_, '_>, kind: TKind) -> Result<Value, JitError> {
        use TKind as K;
        let x = |pass: &mut Pass<'_, '_>, v: u32| pass.at_0(v as usize);
        let function =
            |f: Func| math::unary(f).ok_or_else(|| JitError::Compile(format!("no callee for {f:?}")));
        Ok(match kind {
            K::Add(a, b) => binary(pass, a, b, |b, x, y| b.ins().fadd(x, y))?,
            K::Sub(a, b) => binary(pass, a, b, |b, x, y| b.ins().fsub(x, y))?,
            K::Mul(a, b) | K::Scale(a, b) => binary(pass, a, b, |b, x, y| b.ins().fmul(x, y))?,
            K::Sqr(a) => binary(pass, a, a, |b, x, y| b.ins().fmul(x, y))?,
            K::Div(a, b) | K::DivConst(a, b) => binary(pass, a, b, |b, x, y| b.ins().fdiv(x, y))?,
            K::Neg(a) => {
                let a = x(pass, a)?;
                pass.b.ins().fneg(a)
            }
            K::Sqrt(a) => {
                let a = x(pass, a)?;
                pass.b.ins().sqrt(a)
            }
            K::Abs(a) => {
                let a = x(pass, a)?;
                let zero = pass.b.ins().f64const(0.0);
                let negative = pass.b.ins().fcmp(FloatCC::LessThan, a, zero);
                let flipped = pass.b.ins().fneg(a);
                pass.b.ins().select(negative, flipped, a)
            }
            K::Sin(a, _) | K::Cos(a, _) => {
                let (sin, cos) = self.sin_cos(pass, a)?;
                if matches!(kind, K::Sin(..)) {
                    sin
                } else {
                    cos
                }
            }
            K::Atan2(y, x_, _) => {
                let args = [x(pass, y)?, x(pass, x_)?];
                self.call(pass, math::atan2_callee(), &args)?[0]
            }
            K::Exp(a) | K::Ln(a) | K::Sinh(a, _) | K::Cosh(a, _) | K::Integral(_, a, _) | K::Sign(a) => {
                let f = match kind {
                    K::Exp(_) => Func::Exp,
                    K::Ln(_) => Func::Ln,
                    K::Sinh(..) => Func::Sinh,
                    K::Cosh(..) => Func::Cosh,
                    K::Integral(Inverse::Atan, ..) => Func::Atan,
                    K::Integral(Inverse::Asin, ..) => Func::Asin,
                    K::Integral(Inverse::Acos, ..) => Func::Acos,
                    _ => Func::Sign,
                };
                let args = [x(pass, a)?];
                self.call(pass, function(f)?, &args)?[0]
            }
            K::Time | K::State(_) | K::Const(_) | K::Input(_) => {
                return Err(JitError::Compile("an input where an operation was expected".into()))
            }
        })
    }

    /// `(sin, cos)` of value `a`'s coefficient 0, by one call the first time.
    fn sin_cos(&mut self, pass: &mut Pass<'_, '_>, a: u32) -> Result<(Value, Value), JitError> {
        if let Some(&pair) = self.sin_cos.get(&a) {
            return Ok(pair);
        }
        let x = pass.at_0(a as usize)?;
        let results = self.call(pass, math::sin_cos_callee(), &[x])?;
        let pair = (results[0], results[1]);
        self.sin_cos.insert(a, pair);
        Ok(pair)
    }

    /// A call of `callee` on `args`: its results.
    fn call(
        &mut self,
        pass: &mut Pass<'_, '_>,
        callee: math::Callee,
        args: &[Value],
    ) -> Result<Vec<Value>, JitError> {
        self.callees.call(self.module, pass.b, callee, args)
    }
}

/// `op` on coefficient 0 of values `a` and `b`.
fn binary(
    pass: &mut Pass<'_, '_>,
    a: u32,
    b: u32,
    op: impl FnOnce(&mut FunctionBuilder<'_>, Value, Value) -> Value,
) -> Result<Value, JitError> {
    let (x, y) = (pass.at_0(a as usize)?, pass.at_0(b as usize)?);
    Ok(op(pass.b, x, y))
}

/// `out`: each state's `y`, then its coefficients `f_{k-1} / k` (the runtime's `finish`).
fn finish(
    pass: &mut Pass<'_, '_>,
    program: &TaylorProgram,
    order: usize,
    y: Value,
    out: Value,
) -> Result<(), JitError> {
    let n1 = order + 1;
    let flags = MemFlagsData::trusted();
    for (i, &r) in program.results.iter().enumerate() {
        let yi = pass.b.ins().load(types::F64, flags.with_readonly(), y, offset(i)?);
        pass.b.ins().store(flags, yi, out, offset(i * n1)?);
        for k in 1..n1 {
            let previous = pass.known_at(r, k - 1)?;
            let value = if k == 1 {
                previous
            } else {
                let inverse = pass.b.ins().f64const(1.0 / k as f64);
                pass.b.ins().fmul(previous, inverse)
            };
            pass.b.ins().store(flags, value, out, offset(i * n1 + k)?);
        }
    }
    Ok(())
}
