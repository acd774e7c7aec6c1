//! The JIT engine: in comes a [`ProgramModel`] (a model's lowered program); out goes a
//! [`JitModel`] whose sections run as machine code compiled in process by Cranelift, no Rust
//! toolchain needed. `param_constants` and `rhs` are compiled at once, each output and the
//! Taylor coefficients the first time they are asked for (a run pays only for what it uses);
//! everything else (output rates, faults) is the evaluator's.

mod expansion;
mod math;
mod native;
mod recurrence;
mod section;
mod taylor;

use std::sync::{Arc, OnceLock};

use thiserror::Error;

pub use expansion::CompiledExpansion;
pub use section::{CompiledSection, Reads};
pub use taylor::CompiledTaylor;

use crate::program::ProgramModel;
use crate::runtime::taylor::Row;
use crate::runtime::{quaternion_from_dcm, ModelInfo, TaylorWork, TAYLOR_UNROLLED_ORDERS};

/// Why a section could not be compiled.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum JitError {
    /// This machine's processor is not one the code generator targets.
    #[error("this machine's processor is not supported by the JIT engine ({0}): run with --engine instant")]
    UnsupportedHost(String),
    /// The code generator refused the section.
    #[error("the JIT engine could not compile a section ({0}): run with --engine instant")]
    Compile(String),
}

/// A model whose sections run as machine code; what it does not compile it asks of its
/// evaluator ([`JitModel::evaluator`]).
#[derive(Debug)]
pub struct JitModel {
    evaluator: Arc<ProgramModel>,
    param_constants: CompiledSection,
    rhs: CompiledSection,
    outputs: Vec<OnceLock<Result<CompiledSection, JitError>>>,
    taylor: OnceLock<Option<Result<CompiledTaylor, JitError>>>,
    /// The orders whose Taylor expansions are written out, and their code once compiled.
    straight_orders: Vec<usize>,
    straight: Vec<OnceLock<Result<CompiledExpansion, JitError>>>,
    quaternion: Vec<bool>,
}

impl JitModel {
    /// Compiles `evaluator`'s `param_constants` and `rhs`.
    pub fn new(evaluator: Arc<ProgramModel>) -> Result<JitModel, JitError> {
        let program = evaluator.program();
        let param_constants = CompiledSection::new(&program.param_constants)?;
        let rhs = CompiledSection::new(&program.rhs)?;
        let outputs = program.outputs.iter().map(|_| OnceLock::new()).collect();
        let quaternion = (0..program.outputs.len()).map(|k| evaluator.is_quaternion(k)).collect();
        let straight_orders = match evaluator.taylor_program() {
            Ok(taylor) => taylor.straight_line_orders(TAYLOR_UNROLLED_ORDERS),
            Err(_) => Vec::new(),
        };
        let straight = straight_orders.iter().map(|_| OnceLock::new()).collect();
        let taylor = OnceLock::new();
        Ok(JitModel {
            evaluator,
            param_constants,
            rhs,
            outputs,
            taylor,
            straight_orders,
            straight,
            quaternion,
        })
    }

    /// The model's metadata.
    pub fn info(&self) -> &'static ModelInfo {
        self.evaluator.info()
    }

    /// The evaluator of the same program (output rates, faults).
    pub fn evaluator(&self) -> &Arc<ProgramModel> {
        &self.evaluator
    }

    /// The parameter-only quantities for `params`.
    pub fn param_constants(&self, params: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.param_constants.results()];
        let reads = Reads { t: 0.0, y: &[], params, constants: &[], rates: &[], slots: &[] };
        self.param_constants.run(&reads, &mut out);
        out
    }

    /// `dy = f(t, y)` with `constants = param_constants(params)`.
    pub fn rhs(&self, t: f64, y: &[f64], params: &[f64], constants: &[f64], dy: &mut [f64]) {
        self.rhs.run(&Reads { t, y, params, constants, rates: &[], slots: &[] }, dy)
    }

    /// Compiles output `k` now if it is not yet (to keep compiling out of a timed run).
    pub fn prepare_output(&self, k: usize) -> Result<(), JitError> {
        self.output_section(k).map(|_| ())
    }

    /// Output `k` at `(t, y)` into `out` (its columns); `rates` are `u'` when it needs them.
    /// An output the code generator refuses is evaluated instead.
    pub fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], params: &[f64], out: &mut [f64]) {
        let Ok(section) = self.output_section(k) else {
            self.evaluator.output(k, t, y, rates, params, out, &mut Vec::new());
            return;
        };
        let reads = Reads { t, y, params, constants: &[], rates, slots: &[] };
        if self.quaternion[k] {
            let mut dcm = [0.0; 9];
            section.run(&reads, &mut dcm);
            out[..4].copy_from_slice(&quaternion_from_dcm(&dcm));
        } else {
            section.run(&reads, out);
        }
    }

    /// Compiles the Taylor coefficients of any order now if they are not yet; None for a model
    /// without them.
    pub fn prepare_taylor(&self) -> Option<Result<(), JitError>> {
        self.taylor_code().map(|r| r.as_ref().map(|_| ()).map_err(Clone::clone))
    }

    /// The orders whose Taylor coefficients are written out (faster than the others), each
    /// compiled the first time it is asked for.
    pub fn taylor_straight_line(&self) -> &[usize] {
        &self.straight_orders
    }

    /// The normalised Taylor coefficients through `(t, y)` up to `order` (see
    /// [`ProgramModel::taylor`]); false for a model without them or an order past the
    /// largest. Coefficients the code generator refuses are evaluated instead.
    #[allow(clippy::too_many_arguments)]
    pub fn taylor(
        &self,
        t: f64,
        y: &[f64],
        params: &[f64],
        constants: &[f64],
        order: usize,
        out: &mut [f64],
        work: &mut TaylorWork,
    ) -> bool {
        if let Some(Ok(code)) = self.straight_code(order) {
            code.run(t, y, params, constants, out);
            return true;
        }
        match self.taylor_code() {
            Some(Ok(code)) => {
                let passes = |w: &mut [Row<f64>], order| code.passes(w, order);
                self.evaluator.taylor_by(t, y, params, constants, order, out, work, passes)
            }
            _ => self.evaluator.taylor(t, y, params, constants, order, out, work) == Ok(true),
        }
    }

    fn taylor_code(&self) -> Option<&Result<CompiledTaylor, JitError>> {
        let code = self.taylor.get_or_init(|| {
            let program = self.evaluator.taylor_program().ok()?;
            Some(CompiledTaylor::new(program))
        });
        code.as_ref()
    }

    fn straight_code(&self, order: usize) -> Option<&Result<CompiledExpansion, JitError>> {
        let i = self.straight_orders.iter().position(|&o| o == order)?;
        let program = self.evaluator.taylor_program().ok()?;
        Some(self.straight[i].get_or_init(|| CompiledExpansion::new(program, order)))
    }

    fn output_section(&self, k: usize) -> Result<&CompiledSection, JitError> {
        let compiled = self.outputs[k]
            .get_or_init(|| CompiledSection::new(&self.evaluator.program().outputs[k].section));
        compiled.as_ref().map_err(Clone::clone)
    }
}
