//! What a standalone program computes and writes: in come a model's lowered program, its values
//! and the file's run settings; out goes a [`Plan`] (the sections, every parameter's and state's
//! value, the times and tolerances, and each written column with its header and scale), the
//! same for every language.

use crate::lang::units::{column_name, size::shown_per_internal};
use crate::lang::{FileRun, RunSettings};
use crate::program::ir::Program;
use crate::program::ProgramModel;
use crate::runtime::{ModelInfo, OutputKind};

use super::StandaloneError;

/// Where a written column's value comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// State `i`.
    State(usize),
    /// Component `j` of output `k`.
    Output(usize, usize),
}

/// One column a program writes after `t`.
#[derive(Clone, Debug, PartialEq)]
pub struct WrittenColumn {
    /// Its CSV header (name and unit: `q1_deg`), as the simulator writes it.
    pub header: String,
    /// What it reads.
    pub source: Source,
    /// Written units per internal unit (180/pi for an angle written in degrees).
    pub scale: f64,
}

/// A model's program and everything a standalone run of it needs.
#[derive(Clone)]
pub struct Plan<'a> {
    /// The model's metadata (names and units).
    pub info: &'static ModelInfo,
    /// The lowered program.
    pub program: &'a Program,
    /// Parameter values from INPUT, internal units (NaN where the file gives none).
    pub params: Vec<f64>,
    /// The initial state from INPUT, internal units, dependent coordinates solved (NaN where
    /// the file gives none).
    pub initial: Vec<f64>,
    /// Times and tolerances.
    pub settings: RunSettings,
    /// The columns after `t`.
    pub columns: Vec<WrittenColumn>,
    /// The outputs the columns read, in order of first use.
    pub outputs: Vec<usize>,
    /// Whether a written output reads the speed rates.
    pub needs_rates: bool,
    /// Whether the program evaluates the row at the INPUT values only (no integration).
    pub once: bool,
}

impl<'a> Plan<'a> {
    /// The plan of `model` with the file's run settings `run`; an error for an output no
    /// standalone program computes (a quaternion) or a configuration that cannot be assembled.
    pub fn new(model: &'a ProgramModel, run: &FileRun) -> Result<Plan<'a>, StandaloneError> {
        let info = model.info();
        if info.state_names.is_empty() {
            return Err(StandaloneError::NoDynamics);
        }
        let params = model.default_params();
        let mut initial = model.initial_state();
        if initial.iter().all(|v| v.is_finite()) && params.iter().all(|v| v.is_finite()) {
            if let Some(Err(e)) = model.assemble(&params, &mut initial) {
                return Err(StandaloneError::Assembly(e.to_string()));
            }
        }
        let mut columns = Vec::new();
        let mut outputs = Vec::new();
        for name in run.written(info) {
            if let Some(i) = info.state(name) {
                let unit = info.state_units[i];
                let header = column_name(info.state_names[i], unit);
                columns.push(WrittenColumn {
                    header,
                    source: Source::State(i),
                    scale: shown_per_internal(unit),
                });
            } else if let Some(k) = info.output(name) {
                let o = &info.outputs[k];
                if o.kind == OutputKind::Quaternion {
                    return Err(StandaloneError::Quaternion(o.name.to_string()));
                }
                let scale = shown_per_internal(o.unit);
                columns.extend(o.columns.iter().enumerate().map(|(j, c)| WrittenColumn {
                    header: column_name(c, o.unit),
                    source: Source::Output(k, j),
                    scale,
                }));
                // An output written twice (named on two OUTPUT lines) is computed once.
                if !outputs.contains(&k) {
                    outputs.push(k);
                }
            }
        }
        let needs_rates = outputs.iter().any(|k| info.outputs[*k].needs_rates);
        let settings = run.settings();
        Ok(Plan {
            info,
            program: model.program(),
            params,
            initial,
            settings,
            columns,
            outputs,
            needs_rates,
            once: false,
        })
    }

    /// The plan of a program that writes the row at the INPUT values only: a run of length 0.
    pub fn at_start(mut self) -> Plan<'a> {
        self.settings.t_final = 0.0;
        self.once = true;
        self
    }

    /// The names of the parameters and states without a value, and not open inputs.
    pub fn missing(&self) -> Vec<&'static str> {
        let info = self.info;
        let params = (0..self.params.len())
            .filter(|i| !self.params[*i].is_finite() && !info.open_inputs.contains(i))
            .map(|i| info.param_names[i]);
        let states =
            (0..self.initial.len()).filter(|i| !self.initial[*i].is_finite()).map(|i| info.state_names[i]);
        params.chain(states).collect()
    }

    /// The parameter values a program starts from: open inputs at 0, missing values NaN.
    pub fn start_params(&self) -> Vec<f64> {
        let open = self.info.open_inputs;
        (0..self.params.len()).map(|i| if open.contains(&i) { 0.0 } else { self.params[i] }).collect()
    }

    /// The CSV header line.
    pub fn header(&self) -> String {
        let mut names = vec!["t".to_string()];
        names.extend(self.columns.iter().map(|c| c.header.clone()));
        names.join(",")
    }
}
