//! The instant path: in comes a model's lowered program ([`ProgramModel`]); out goes a model
//! that integrates it by evaluating the program's sections directly, no Rust compiled.
//! Slower per step than a compiled model, but ready at once: for checking and short runs.

use std::cell::RefCell;
use std::sync::Arc;

use kane_model::program::ProgramModel;
use kane_model::runtime::ModelInfo;

use super::model_file::ModelFile;
use crate::ode::{System, TaylorWork};
use crate::problem::{Engine, Problem, RowStream, SharedModel, SimModel, SolveError, Trajectory};
use crate::solve::{solve_bound, BoundModel};

/// A program model with its parameters bound.
pub struct InstantSystem<'a> {
    model: &'a ProgramModel,
    params: Vec<f64>,
    constants: Vec<f64>,
    regs: RefCell<Vec<f64>>,
}

impl<'a> InstantSystem<'a> {
    /// `model` at the parameter values `params` (in `info().param_names` order).
    pub fn new(model: &'a ProgramModel, params: Vec<f64>) -> Self {
        let constants = model.param_constants(&params);
        InstantSystem { model, params, constants, regs: RefCell::new(Vec::new()) }
    }
}

impl System for InstantSystem<'_> {
    fn dim(&self) -> usize {
        self.model.info().state_names.len()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.model.rhs(t, y, &self.params, &self.constants, dy, &mut self.regs.borrow_mut())
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        self.model.taylor(t, y, &self.params, &self.constants, order, out, work) == Ok(true)
    }
}

impl BoundModel for InstantSystem<'_> {
    fn info(&self) -> &'static ModelInfo {
        self.model.info()
    }
    fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], out: &mut [f64]) {
        self.model.output(k, t, y, rates, &self.params, out, &mut self.regs.borrow_mut())
    }
    fn output_rate(&self, k: usize, t: f64, y: &[f64], dy: &[f64], out: &mut [f64], rate: &mut [f64]) {
        self.model.output_rate(k, t, y, dy, &self.params, out, rate)
    }
}

/// The lowered program on the instant engine.
struct InstantModel {
    program: Arc<ProgramModel>,
}

impl SimModel for InstantModel {
    fn info(&self) -> &'static ModelInfo {
        self.program.info()
    }
    fn engine(&self) -> Engine {
        Engine::Instant
    }
    fn initial_state(&self) -> Vec<f64> {
        self.program.initial_state()
    }
    fn default_params(&self) -> Vec<f64> {
        self.program.default_params()
    }
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
        solve_bound(problem, &InstantSystem::new(&self.program, problem.params.clone()), rows_to)
    }
    fn program(&self) -> Option<Arc<ProgramModel>> {
        Some(self.program.clone())
    }
}

/// The model file `file` on the instant engine, its mechanics and drawing known.
pub fn instant_file_model(file: &ModelFile) -> SharedModel {
    file.dress(instant_model(file.program.clone()))
}

/// `program` on the instant engine.
pub fn instant_model(program: Arc<ProgramModel>) -> SharedModel {
    Arc::new(InstantModel { program })
}
