//! One native function compiled in process: in come its parameter types and a body emitter;
//! out goes [`NativeCode`], the function's address and the memory that holds it.

use cranelift_codegen::ir::{types, AbiParam, Type, UserFuncName};
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{default_libcall_names, Linkage, Module};

use super::math;
use super::JitError;

/// A parameter of a native function.
#[derive(Clone, Copy, Debug)]
pub(super) enum Param {
    /// A double.
    F64,
    /// A 64-bit integer.
    I64,
    /// An address.
    Pointer,
}

/// A compiled function and the module whose memory holds it.
pub(super) struct NativeCode {
    module: Option<JITModule>,
    address: *const u8,
}

// SAFETY: after `finalize_definitions` the module is never touched again but to free its
// memory on drop; the code it holds is immutable and reads only its arguments.
unsafe impl Send for NativeCode {}
// SAFETY: as above; calling the code mutates nothing but what its arguments point to.
unsafe impl Sync for NativeCode {}

impl Drop for NativeCode {
    fn drop(&mut self) {
        if let Some(module) = self.module.take() {
            // SAFETY: `address` points into this module's memory and is dropped with it; no
            // call can be running, since a call borrows the owner of `self`.
            unsafe { module.free_memory() }
        }
    }
}

impl NativeCode {
    /// Compiles a function of `params` (no results) whose body `emit` writes (ending in a
    /// return); `emit`'s own result is handed back beside the code.
    pub(super) fn compile<R>(
        params: &[Param],
        emit: impl FnOnce(&mut JITModule, &mut FunctionBuilder<'_>) -> Result<R, JitError>,
    ) -> Result<(NativeCode, R), JitError> {
        let mut module = new_module()?;
        let pointer = module.target_config().pointer_type();
        let mut ctx = module.make_context();
        for &p in params {
            let ty: Type = match p {
                Param::F64 => types::F64,
                Param::I64 => types::I64,
                Param::Pointer => pointer,
            };
            ctx.func.signature.params.push(AbiParam::new(ty));
        }
        let id = module
            .declare_function("native", Linkage::Local, &ctx.func.signature)
            .map_err(|e| JitError::Compile(e.to_string()))?;
        ctx.func.name = UserFuncName::user(0, id.as_u32());
        let mut fctx = FunctionBuilderContext::new();
        let emitted = {
            let mut b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
            let emitted = emit(&mut module, &mut b)?;
            b.finalize(module.target_config());
            emitted
        };
        module.define_function(id, &mut ctx).map_err(|e| JitError::Compile(format!("{e:?}")))?;
        module.clear_context(&mut ctx);
        module.finalize_definitions().map_err(|e| JitError::Compile(e.to_string()))?;
        let address = module.get_finalized_function(id);
        Ok((NativeCode { module: Some(module), address }, emitted))
    }

    /// The function's entry point.
    pub(super) fn address(&self) -> *const u8 {
        self.address
    }
}

/// A module for this machine, the math callees in its symbol table.
fn new_module() -> Result<JITModule, JitError> {
    let mut flags = settings::builder();
    let set = |flags: &mut settings::Builder, name: &str, value: &str| {
        flags.set(name, value).map_err(|e| JitError::Compile(e.to_string()))
    };
    set(&mut flags, "use_colocated_libcalls", "false")?;
    set(&mut flags, "is_pic", "false")?;
    set(&mut flags, "opt_level", "speed")?;
    let isa = cranelift_native::builder()
        .map_err(|e| JitError::UnsupportedHost(e.to_string()))?
        .finish(settings::Flags::new(flags))
        .map_err(|e| JitError::UnsupportedHost(e.to_string()))?;
    let mut builder = JITBuilder::with_isa(isa, default_libcall_names());
    for callee in math::all() {
        builder.symbol(callee.name, callee.address);
    }
    Ok(JITModule::new(builder))
}
