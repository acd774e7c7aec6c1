//! The JIT engine: in comes a model's lowered program ([`ProgramModel`]); out goes a model
//! that integrates it as machine code compiled in process ([`JitModel`]), ready in
//! milliseconds and with no Rust toolchain needed.

use std::sync::Arc;

use kane_model::jit::{JitError, JitModel};
use kane_model::program::ProgramModel;
use kane_model::runtime::ModelInfo;

use super::model_file::ModelFile;
use crate::ode::{Method, System, TaylorWork};
use crate::problem::{Engine, Pick, Problem, RowStream, SharedModel, SimModel, SolveError, Trajectory};
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
        self.model.taylor(t, y, &self.params, &self.constants, order, out, work)
    }
    fn taylor_straight_line(&self) -> &[usize] {
        self.model.taylor_straight_line()
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

/// The lowered program on the JIT engine.
struct JitEngineModel {
    jit: JitModel,
    program: Arc<ProgramModel>,
}

impl SimModel for JitEngineModel {
    fn info(&self) -> &'static ModelInfo {
        self.program.info()
    }
    fn engine(&self) -> Engine {
        Engine::Jit
    }
    fn initial_state(&self) -> Vec<f64> {
        self.program.initial_state()
    }
    fn default_params(&self) -> Vec<f64> {
        self.program.default_params()
    }
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
        for pick in &problem.picks {
            if let Pick::Output(k) = *pick {
                // An output the JIT refuses is evaluated instead.
                let _ = self.jit.prepare_output(k);
            }
        }
        if matches!(problem.method, Method::Taylor(_)) {
            // Coefficients the JIT refuses are evaluated instead.
            let _ = self.jit.prepare_taylor();
        }
        solve_bound(problem, &JitSystem::new(&self.jit, problem.params.clone()), rows_to)
    }
    fn program(&self) -> Option<Arc<ProgramModel>> {
        Some(self.program.clone())
    }
}

/// The model file `file` on the JIT engine, its mechanics and drawing known.
pub fn jit_file_model(file: &ModelFile) -> Result<SharedModel, JitError> {
    Ok(file.dress(jit_model(file.program.clone())?))
}

/// `program` on the JIT engine (its `rhs` compiled now).
pub fn jit_model(program: Arc<ProgramModel>) -> Result<SharedModel, JitError> {
    Ok(Arc::new(JitEngineModel { jit: JitModel::new(program.clone())?, program }))
}
