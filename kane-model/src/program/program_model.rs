//! The lowered program run as it is, without compiling Rust (the instant path): in comes a
//! spec; out goes a [`ProgramModel`] that evaluates `param_constants`, `rhs` and each output from
//! the same SSA sections the printer spells, so both paths compute the same operations.

use crate::assembly::{Assembly, AssemblyError};
use crate::runtime::dual::Dual;
use crate::runtime::taylor::Row;
use crate::runtime::{quaternion_from_dcm, ModelInfo, TaylorWork};
use crate::spec::ModelSpec;

use super::fault::{first_fault, near_division_by_zero, text, Fault};
use super::ir::{Input, Program, Section};
use super::meta::Meta;
use super::taylor::{TaylorError, TaylorProgram};
use super::{lower, LowerError};

/// A model evaluated from its lowered program. Each evaluation takes a scratch buffer `regs`
/// (one per thread; reused, it saves allocating).
#[derive(Clone, Debug)]
pub struct ProgramModel {
    info: &'static ModelInfo,
    program: Program,
    defaults: Vec<f64>,
    initial: Vec<f64>,
    quaternion: Vec<bool>,
    taylor: Result<TaylorProgram, TaylorError>,
}

impl ProgramModel {
    /// Lowers `spec` (its metadata leaked for the process's lifetime: see [`Meta::leak`]).
    pub fn new(spec: &mut ModelSpec) -> Result<ProgramModel, LowerError> {
        let lowered = lower(spec)?;
        let meta = Meta::of(spec, &lowered);
        let default = |name: &String| spec.default_of(name).filter(|v| v.is_finite()).unwrap_or(f64::NAN);
        Ok(ProgramModel {
            info: meta.leak(),
            defaults: meta.params.iter().map(default).collect(),
            initial: meta.states.iter().map(default).collect(),
            quaternion: spec.outputs.iter().map(|o| o.kind.is_quaternion()).collect(),
            taylor: TaylorProgram::new(&lowered.program.rhs, lowered.states.len()),
            program: lowered.program,
        })
    }

    /// The model's metadata.
    pub fn info(&self) -> &'static ModelInfo {
        self.info
    }

    /// Whether output `k` is an orientation written as a quaternion (its section gives the
    /// direction cosine matrix).
    pub fn is_quaternion(&self, k: usize) -> bool {
        self.quaternion[k]
    }

    /// The lowered program it evaluates.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// `y` with its dependent coordinates solved so the configuration constraints hold (see
    /// [`crate::assembly`]); None for a model without configuration constraints.
    pub fn assemble(&self, params: &[f64], y: &mut [f64]) -> Option<Result<Assembly, AssemblyError>> {
        let k = crate::assembly::residual_output(self.info)?;
        Some(crate::assembly::assemble(self.info, y, |y, dy, r, dr| {
            self.output_rate(k, 0.0, y, dy, params, r, dr)
        }))
    }

    /// The parameter defaults from INPUT, in `info().param_names` order (NaN where none).
    pub fn default_params(&self) -> Vec<f64> {
        self.defaults.clone()
    }

    /// The initial state from INPUT, in radians (NaN where none).
    pub fn initial_state(&self) -> Vec<f64> {
        self.initial.clone()
    }

    /// The parameter-only quantities for `params`.
    pub fn param_constants(&self, params: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.program.param_constants.results.len()];
        let read = |input: Input| match input {
            Input::Param(i) => params[i],
            _ => f64::NAN,
        };
        self.program.param_constants.eval(read, &mut out);
        out
    }

    /// `dy = f(t, y)` with `constants = param_constants(params)`.
    pub fn rhs(
        &self,
        t: f64,
        y: &[f64],
        params: &[f64],
        constants: &[f64],
        dy: &mut [f64],
        regs: &mut Vec<f64>,
    ) {
        let at = At { t, y, rates: &[], params, constants };
        at.run(&self.program.rhs, regs, dy)
    }

    /// The Taylor program of `rhs`, or why there is none.
    pub fn taylor_program(&self) -> Result<&TaylorProgram, TaylorError> {
        self.taylor.as_ref().map_err(Clone::clone)
    }

    /// The normalised Taylor coefficients of the solution through `(t, y)` up to `order` into
    /// `out` (state-major, `order + 1` per state; see [`TaylorProgram::coefficients`]); false
    /// for an order above [`crate::runtime::TAYLOR_MAX_ORDER`].
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
    ) -> Result<bool, TaylorError> {
        let program = self.taylor.as_ref().map_err(Clone::clone)?;
        let passes = |w: &mut [Row<f64>], order| (1..order).for_each(|k| program.pass(w, k));
        Ok(self.taylor_by(t, y, params, constants, order, out, work, passes))
    }

    /// [`Self::taylor`] with the passes `1..order` run by `passes` (see
    /// [`TaylorProgram::coefficients_by`]); false without a Taylor program.
    #[allow(clippy::too_many_arguments)]
    pub fn taylor_by(
        &self,
        t: f64,
        y: &[f64],
        params: &[f64],
        constants: &[f64],
        order: usize,
        out: &mut [f64],
        work: &mut TaylorWork,
        passes: impl FnOnce(&mut [Row<f64>], usize),
    ) -> bool {
        let Ok(program) = self.taylor.as_ref() else { return false };
        let at = At { t, y, rates: &[], params, constants };
        program.coefficients_by(t, y, |input| at.read(input), order, out, work, passes)
    }

    /// Output `k` at `(t, y)` into `out` (its columns); `rates` are `u'` when it needs them.
    #[allow(clippy::too_many_arguments)]
    pub fn output(
        &self,
        k: usize,
        t: f64,
        y: &[f64],
        rates: &[f64],
        params: &[f64],
        out: &mut [f64],
        regs: &mut Vec<f64>,
    ) {
        let section = &self.program.outputs[k].section;
        let at = At { t, y, rates, params, constants: &[] };
        if self.quaternion[k] {
            let mut dcm = [0.0; 9];
            at.run(section, regs, &mut dcm);
            out[..4].copy_from_slice(&quaternion_from_dcm(&dcm));
        } else {
            at.run(section, regs, out);
        }
    }
}

impl ProgramModel {
    /// The first operation of `rhs` (or of `param_constants`) at `(t, y)` whose operands are finite
    /// and whose result is not, named (see [`super::fault`]).
    pub fn rhs_fault(&self, t: f64, y: &[f64], params: &[f64]) -> Option<Fault> {
        let constants = self.param_constants(params);
        let at = At { t, y, rates: &[], params, constants: &constants };
        first_fault(&self.program.param_constants, |i| at.read(i), &|i| self.input_name(i))
            .or_else(|| first_fault(&self.program.rhs, |i| at.read(i), &|i| self.input_name(i)))
    }

    /// The quotient of `rhs` at `(t, y)` whose divisor cancels most nearly to zero (a
    /// singularity approached), named; see [`super::fault::near_division_by_zero`].
    pub fn rhs_near_fault(&self, t: f64, y: &[f64], params: &[f64]) -> Option<Fault> {
        let constants = self.param_constants(params);
        let at = At { t, y, rates: &[], params, constants: &constants };
        near_division_by_zero(&self.program.rhs, |i| at.read(i), &|i| self.input_name(i))
    }

    /// The first faulty operation of output `k` at `(t, y)` (`rates` are `u'`), named.
    pub fn output_fault(&self, k: usize, t: f64, y: &[f64], rates: &[f64], params: &[f64]) -> Option<Fault> {
        let at = At { t, y, rates, params, constants: &[] };
        first_fault(&self.program.outputs[k].section, |i| at.read(i), &|i| self.input_name(i))
    }

    /// An input as the model file names it (a parameter-only quantity written out).
    fn input_name(&self, input: Input) -> String {
        let info = self.info;
        let state = |i: usize| info.state_names.get(i).copied().unwrap_or("?");
        match input {
            Input::Time => "T".to_string(),
            Input::State(i) => state(i).to_string(),
            Input::Param(i) => info.param_names.get(i).copied().unwrap_or("?").to_string(),
            Input::Rate(i) => format!("{}'", state(info.n_coordinates + i)),
            Input::ParamConstant(i) => match self.program.param_constants.results.get(i) {
                Some(&v) => {
                    format!("({})", text(&self.program.param_constants, v, &|i| self.input_name(i), 3))
                }
                None => "?".to_string(),
            },
            Input::Slot(i) => format!("slot {i}"),
        }
    }

    /// Output `k` at `(t, y)` into `out` and its time derivative along `y' = dy` into `rate`
    /// (the section run in dual numbers); meaningful only for an output that reads no speed
    /// rates.
    #[allow(clippy::too_many_arguments)]
    pub fn output_rate(
        &self,
        k: usize,
        t: f64,
        y: &[f64],
        dy: &[f64],
        params: &[f64],
        out: &mut [f64],
        rate: &mut [f64],
    ) {
        let section = &self.program.outputs[k].section;
        let read = |input: Input| match input {
            Input::Time => Dual::new(t, 1.0),
            Input::State(i) => Dual::new(y[i], dy[i]),
            Input::Param(i) => Dual::constant(params[i]),
            Input::ParamConstant(_) | Input::Rate(_) | Input::Slot(_) => Dual::constant(f64::NAN),
        };
        let mut values = vec![Dual::constant(0.0); section.results.len()];
        section.eval(read, &mut values);
        if self.quaternion[k] {
            let dcm: [Dual<f64>; 9] = std::array::from_fn(|i| values[i]);
            values = quaternion_from_dcm(&dcm).to_vec();
        }
        for ((o, r), v) in out.iter_mut().zip(rate.iter_mut()).zip(&values) {
            *o = v.re;
            *r = v.eps;
        }
    }
}

/// Where a section is evaluated: the values its inputs read.
struct At<'a> {
    t: f64,
    y: &'a [f64],
    rates: &'a [f64],
    params: &'a [f64],
    constants: &'a [f64],
}

impl At<'_> {
    fn read(&self, input: Input) -> f64 {
        match input {
            Input::Time => self.t,
            Input::State(i) => self.y[i],
            Input::Param(i) => self.params[i],
            Input::ParamConstant(i) => self.constants[i],
            Input::Rate(i) => self.rates[i],
            // Model sections read no slots (only event sections do).
            Input::Slot(_) => f64::NAN,
        }
    }

    fn run(&self, s: &Section, regs: &mut Vec<f64>, out: &mut [f64]) {
        s.eval_in(|input| self.read(input), regs, out)
    }
}
