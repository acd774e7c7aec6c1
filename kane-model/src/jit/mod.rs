//! The JIT engine: in comes a [`ProgramModel`] (a model's lowered program); out goes a
//! [`JitModel`] whose sections run as machine code compiled in process by Cranelift, no Rust
//! toolchain needed. `param_constants` and `rhs` are compiled at once, each output the first
//! time it is asked for (a run pays only for what it writes); everything else (Taylor
//! coefficients, output rates, faults) is the evaluator's.

mod math;
mod section;

use std::sync::{Arc, OnceLock};

use thiserror::Error;

pub use section::{CompiledSection, Reads};

use crate::program::ProgramModel;
use crate::runtime::{quaternion_from_dcm, ModelInfo};

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
        Ok(JitModel { evaluator, param_constants, rhs, outputs, quaternion })
    }

    /// The model's metadata.
    pub fn info(&self) -> &'static ModelInfo {
        self.evaluator.info()
    }

    /// The evaluator of the same program (Taylor coefficients, output rates, faults).
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

    fn output_section(&self, k: usize) -> Result<&CompiledSection, JitError> {
        let compiled = self.outputs[k]
            .get_or_init(|| CompiledSection::new(&self.evaluator.program().outputs[k].section));
        compiled.as_ref().map_err(Clone::clone)
    }
}
