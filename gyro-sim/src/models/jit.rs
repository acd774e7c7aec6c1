//! The JIT engine: in comes a model's lowered program ([`ProgramModel`]); out goes a registry
//! entry that integrates it as machine code compiled in process ([`JitModel`]), ready in
//! milliseconds and with no Rust toolchain needed.

use std::sync::Arc;

use kane_model::codegen::jit::{JitError, JitModel};
use kane_model::codegen::ProgramModel;
use kane_model::runtime::ModelInfo;

use super::model_file::ModelFile;
use crate::ode::{System, TaylorWork};
use crate::problem::{Engine, ModelEntry, ProgramSource};
use crate::solve::{solve_bound, BoundModel};

/// A JIT-compiled model with its parameters bound.
pub struct JitSystem<'a> {
    model: &'a JitModel,
    params: Vec<f64>,
    constants: Vec<f64>,
}

impl<'a> JitSystem<'a> {
    /// `model` at the parameter values `params` (in `info().param_names` order).
    pub fn new(model: &'a JitModel, params: Vec<f64>) -> Self {
        let constants = model.param_constants(&params);
        JitSystem { model, params, constants }
    }
}

impl System for JitSystem<'_> {
    const UNROLL_ANY_DIM: bool = true;
    fn dim(&self) -> usize {
        self.model.info().state_names.len()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.model.rhs(t, y, &self.params, &self.constants, dy)
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        let evaluator = self.model.evaluator();
        evaluator.taylor(t, y, &self.params, &self.constants, order, out, work) == Ok(true)
    }
}

impl BoundModel for JitSystem<'_> {
    fn info(&self) -> &'static ModelInfo {
        self.model.info()
    }
    fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], out: &mut [f64]) {
        self.model.output(k, t, y, rates, &self.params, out)
    }
    fn output_rate(&self, k: usize, t: f64, y: &[f64], dy: &[f64], out: &mut [f64], rate: &mut [f64]) {
        self.model.evaluator().output_rate(k, t, y, dy, &self.params, out, rate)
    }
}

/// The registry entry running the model file `file` on the JIT engine, its mechanics known.
pub fn jit_file_entry(file: &ModelFile) -> Result<ModelEntry, JitError> {
    Ok(file.dress(jit_entry(file.program.clone())?))
}

/// The registry entry running `program` on the JIT engine (its `rhs` compiled now).
pub fn jit_entry(program: Arc<ProgramModel>) -> Result<ModelEntry, JitError> {
    let model = Arc::new(JitModel::new(program.clone())?);
    let (a, b) = (program.clone(), program.clone());
    Ok(ModelEntry {
        info: program.info(),
        initial_state: Arc::new(move || a.initial_state()),
        default_params: Arc::new(move || b.default_params()),
        solve: Arc::new(move |problem, rows_to| {
            for pick in &problem.picks {
                if let crate::problem::Pick::Output(k) = *pick {
                    let _ = model.prepare_output(k);
                }
            }
            solve_bound(problem, &JitSystem::new(&model, problem.params.clone()), rows_to)
        }),
        engine: Engine::Jit,
        program: Some(ProgramSource(Arc::new(move || Some(program.clone())))),
        source: None,
        mechanics: None,
        drawing: None,
    })
}
