//! The instant path: in comes a model's lowered program ([`ProgramModel`]); out goes a registry
//! entry that integrates it by evaluating the program's sections directly, no Rust compiled.
//! Slower per step than a compiled model, but ready at once: for checking and short runs.

use std::cell::RefCell;
use std::sync::Arc;

use kane_model::codegen::ProgramModel;
use kane_model::runtime::ModelInfo;

use super::model_file::ModelFile;
use crate::ode::{System, TaylorWork};
use crate::problem::{Engine, ModelEntry, ProgramSource};
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

/// The registry entry running the model file `file` on the instant path, its mechanics known.
pub fn file_entry(file: &ModelFile) -> ModelEntry {
    file.dress(instant_entry(file.program.clone()))
}

/// The registry entry running `model` on the instant path.
pub fn instant_entry(model: Arc<ProgramModel>) -> ModelEntry {
    let (a, b, c, d) = (model.clone(), model.clone(), model.clone(), model.clone());
    ModelEntry {
        info: model.info(),
        initial_state: Arc::new(move || a.initial_state()),
        default_params: Arc::new(move || b.default_params()),
        solve: Arc::new(move |problem, rows_to| {
            solve_bound(problem, &InstantSystem::new(&c, problem.params.clone()), rows_to)
        }),
        engine: Engine::Instant,
        program: Some(ProgramSource(Arc::new(move || Some(d.clone())))),
        source: None,
        mechanics: None,
        drawing: None,
    }
}
