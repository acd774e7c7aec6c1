//! The math functions machine code calls: each the Rust function the evaluator uses, behind the
//! C calling convention, so both engines compute the same values; and the calls to them.

use std::collections::HashMap;

use cranelift_codegen::ir::{self, types, AbiParam, InstBuilder, Value};
use cranelift_frontend::FunctionBuilder;
use cranelift_jit::JITModule;
use cranelift_module::{Linkage, Module};

use super::JitError;
use crate::expr::Func;

extern "C" fn sin(x: f64) -> f64 {
    x.sin()
}
extern "C" fn cos(x: f64) -> f64 {
    x.cos()
}
extern "C" fn tan(x: f64) -> f64 {
    x.tan()
}
extern "C" fn asin(x: f64) -> f64 {
    x.asin()
}
extern "C" fn acos(x: f64) -> f64 {
    x.acos()
}
extern "C" fn atan(x: f64) -> f64 {
    x.atan()
}
extern "C" fn exp(x: f64) -> f64 {
    x.exp()
}
extern "C" fn ln(x: f64) -> f64 {
    x.ln()
}
extern "C" fn sign(x: f64) -> f64 {
    crate::runtime::sign(x)
}
extern "C" fn sinh(x: f64) -> f64 {
    x.sinh()
}
extern "C" fn cosh(x: f64) -> f64 {
    x.cosh()
}
extern "C" fn tanh(x: f64) -> f64 {
    x.tanh()
}
/// `sin(x)` and `cos(x)`, returned in two registers.
#[repr(C)]
pub(super) struct SinCos {
    sin: f64,
    cos: f64,
}

extern "C" fn sin_cos(x: f64) -> SinCos {
    let (sin, cos) = x.sin_cos();
    SinCos { sin, cos }
}

extern "C" fn powf(x: f64, y: f64) -> f64 {
    x.powf(y)
}
extern "C" fn atan2(y: f64, x: f64) -> f64 {
    y.atan2(x)
}

/// A function of one or two `f64`s that machine code calls by address.
#[derive(Clone, Copy, Debug)]
pub(super) struct Callee {
    /// Its symbol in the compiled module.
    pub name: &'static str,
    /// Its address.
    pub address: *const u8,
    /// How many `f64` arguments it takes.
    pub arity: usize,
    /// How many `f64` results it returns.
    pub results: usize,
}

/// The callee computing `f`; None for a function compiled inline (`abs`).
pub(super) fn unary(f: Func) -> Option<Callee> {
    let (name, function): (&'static str, extern "C" fn(f64) -> f64) = match f {
        Func::Sin => ("kane_sin", sin),
        Func::Cos => ("kane_cos", cos),
        Func::Tan => ("kane_tan", tan),
        Func::Asin => ("kane_asin", asin),
        Func::Acos => ("kane_acos", acos),
        Func::Atan => ("kane_atan", atan),
        Func::Exp => ("kane_exp", exp),
        Func::Ln => ("kane_ln", ln),
        Func::Sign => ("kane_sign", sign),
        Func::Sinh => ("kane_sinh", sinh),
        Func::Cosh => ("kane_cosh", cosh),
        Func::Tanh => ("kane_tanh", tanh),
        Func::Abs => return None,
    };
    Some(Callee { name, address: function as *const u8, arity: 1, results: 1 })
}

/// `x ^ y`.
pub(super) fn powf_callee() -> Callee {
    Callee {
        name: "kane_powf",
        address: powf as extern "C" fn(f64, f64) -> f64 as *const u8,
        arity: 2,
        results: 1,
    }
}

/// `atan2(y, x)`.
pub(super) fn atan2_callee() -> Callee {
    Callee {
        name: "kane_atan2",
        address: atan2 as extern "C" fn(f64, f64) -> f64 as *const u8,
        arity: 2,
        results: 1,
    }
}

/// `sin(x)` and `cos(x)` in one call (two results, `sin` first).
pub(super) fn sin_cos_callee() -> Callee {
    Callee {
        name: "kane_sin_cos",
        address: sin_cos as extern "C" fn(f64) -> SinCos as *const u8,
        arity: 1,
        results: 2,
    }
}

/// Every callee, for the module's symbol table.
pub(super) fn all() -> Vec<Callee> {
    let binary = [powf_callee(), atan2_callee(), sin_cos_callee()];
    Func::ALL.iter().filter_map(|&f| unary(f)).chain(binary).collect()
}

/// The callees one function being emitted has declared so far.
#[derive(Default)]
pub(super) struct Callees {
    declared: HashMap<&'static str, ir::FuncRef>,
}

impl Callees {
    /// A call of `callee` on `args`: its results.
    pub(super) fn call(
        &mut self,
        module: &mut JITModule,
        b: &mut FunctionBuilder<'_>,
        callee: Callee,
        args: &[Value],
    ) -> Result<Vec<Value>, JitError> {
        let func = match self.declared.get(callee.name) {
            Some(&f) => f,
            None => {
                let mut signature = module.make_signature();
                signature.params.extend((0..callee.arity).map(|_| AbiParam::new(types::F64)));
                signature.returns.extend((0..callee.results).map(|_| AbiParam::new(types::F64)));
                let id = module
                    .declare_function(callee.name, Linkage::Import, &signature)
                    .map_err(|e| JitError::Compile(e.to_string()))?;
                let f = module.declare_func_in_func(id, b.func);
                self.declared.insert(callee.name, f);
                f
            }
        };
        let call = b.ins().call(func, args);
        Ok(b.inst_results(call).to_vec())
    }
}
