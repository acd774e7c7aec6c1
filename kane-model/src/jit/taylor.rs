//! Taylor coefficients in machine code, one pass for any order: in comes a [`TaylorProgram`];
//! out goes a [`CompiledTaylor`], native code for pass `k >= 1` (the states' coefficient `k`,
//! then every varying value's), its sums as loops in the runtime's order of operations (so its
//! coefficients equal the evaluator's). Order 0 and the states' last coefficient stay with
//! [`TaylorProgram`]; the orders written out whole are [`super::CompiledExpansion`]'s.

use cranelift_codegen::ir::InstBuilder;
use cranelift_module::Module;

use super::native::{NativeCode, Param};
use super::recurrence::{Order, Pass};
use super::JitError;
use crate::program::taylor::TaylorProgram;
use crate::runtime::taylor::{Row, MAX_ORDER};

type PassFn = unsafe extern "C" fn(*mut f64, i64);

/// One Taylor pass of any order compiled to machine code, callable from any thread.
pub struct CompiledTaylor {
    code: NativeCode,
    rows: usize,
}

impl std::fmt::Debug for CompiledTaylor {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CompiledTaylor").field("rows", &self.rows).finish_non_exhaustive()
    }
}

impl CompiledTaylor {
    /// Compiles one pass of `program` for any `k`.
    pub fn new(program: &TaylorProgram) -> Result<CompiledTaylor, JitError> {
        let params = [Param::Pointer, Param::I64];
        let (code, ()) = NativeCode::compile(&params, |module, b| {
            let pointer = module.target_config().pointer_type();
            let entry = b.create_block();
            b.append_block_params_for_function_params(entry);
            b.switch_to_block(entry);
            b.seal_block(entry);
            let (w, k) = (b.block_params(entry)[0], b.block_params(entry)[1]);
            let k_bytes = b.ins().ishl_imm_u(k, 3);
            let pk = b.ins().iadd(w, k_bytes);
            let mut pass = Pass::new(b, pointer, program, Order::Any { w, k, pk });
            pass.one_pass(program)?;
            pass.b.ins().return_(&[]);
            Ok(())
        })?;
        Ok(CompiledTaylor { code, rows: program.ops.len() })
    }

    /// Passes `1..order` on the rows `w`, whose coefficients of order 0 are known.
    ///
    /// # Panics
    /// When `w` has fewer rows than the program's values or `order` is past the largest.
    pub fn passes(&self, w: &mut [Row<f64>], order: usize) {
        (1..order).for_each(|k| self.pass(w, k))
    }

    /// Pass `k` on the rows `w`, whose coefficients below `k` are known.
    ///
    /// # Panics
    /// When `w` has fewer rows than the program's values or `k` is not in `1..=MAX_ORDER`.
    pub fn pass(&self, w: &mut [Row<f64>], k: usize) {
        assert!((1..=MAX_ORDER).contains(&k), "a Taylor pass of order {k}");
        assert!(w.len() >= self.rows, "a Taylor pass needs {} rows, given {}", self.rows, w.len());
        // SAFETY: the code was compiled from a signature of exactly these parameters.
        let function = unsafe { std::mem::transmute::<*const u8, PassFn>(self.code.address()) };
        // SAFETY: the code reads and writes coefficients `0..=k` of rows below `self.rows`
        // (`k` checked above), all inside `w` by the check above (rows are contiguous arrays of
        // `MAX_ORDER + 1`).
        unsafe { function(w.as_mut_ptr().cast::<f64>(), k as i64) }
    }
}
