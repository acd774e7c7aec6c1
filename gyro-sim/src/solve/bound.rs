//! Models bound to their parameters: in come a generated model's type (or a user's own
//! [`BoundModel`]) and parameter values; out go the ODE system the steppers integrate, its
//! outputs, and the same system without the cyclic coordinates nothing reads ([`Reduced`]).

use kane_model::runtime::{GeneratedModel, ModelInfo, OutputKind};

use crate::ode::{System, TaylorWork};

/// A generated model with parameters, as an ODE system.
pub struct ModelSystem<M: GeneratedModel> {
    params: M::Params,
    constants: M::ParamConstants,
}

impl<M: GeneratedModel> ModelSystem<M> {
    /// The system for these parameters.
    pub fn new(params: M::Params) -> Self {
        let constants = M::param_constants(&params);
        ModelSystem { params, constants }
    }

    /// The parameters.
    pub fn params(&self) -> &M::Params {
        &self.params
    }
}

/// A model with its parameters bound: the system the solver integrates, its metadata and its
/// outputs.
pub trait BoundModel: System {
    /// The model's metadata.
    fn info(&self) -> &'static ModelInfo;
    /// Output `k` at `(t, y)` (full state) into `out`; `rates` are `u'` when it needs them.
    fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], out: &mut [f64]);
    /// Output `k` at `(t, y)` into `out` and its time derivative along `y' = dy` into `rate`
    /// (for an output that reads no speed rates).
    fn output_rate(&self, k: usize, t: f64, y: &[f64], dy: &[f64], out: &mut [f64], rate: &mut [f64]);
}

impl<M: GeneratedModel> BoundModel for ModelSystem<M> {
    fn info(&self) -> &'static ModelInfo {
        &M::INFO
    }
    fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], out: &mut [f64]) {
        M::output(k, t, y, rates, &self.params, out)
    }
    fn output_rate(&self, k: usize, t: f64, y: &[f64], dy: &[f64], out: &mut [f64], rate: &mut [f64]) {
        M::output_rate(k, t, y, dy, &self.params, out, rate)
    }
}

impl<M: GeneratedModel> System for ModelSystem<M> {
    const FIXED_DIM: usize = M::INFO.state_names.len();
    const REDUCED_DIM: usize = M::INFO.state_names.len() - M::INFO.cyclic.len();
    fn dim(&self) -> usize {
        M::INFO.state_names.len()
    }
    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        M::rhs_with_constants(t, y, &self.params, &self.constants, dy)
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        M::taylor(t, y, &self.params, &self.constants, order, out, work)
    }
    fn taylor_straight_line(&self) -> &[usize] {
        M::INFO.taylor_straight_line
    }
}

/// A system without some of its states (cyclic coordinates nothing asked for depends on): they
/// are held at zero, which no equation reads, and never integrated.
pub struct Reduced<'a, S: System> {
    inner: &'a S,
    keep: Vec<usize>,
    /// Every state is kept, in order: calls go straight through.
    all: bool,
    full: std::cell::RefCell<(Vec<f64>, Vec<f64>)>,
}

impl<'a, S: System> Reduced<'a, S> {
    /// `inner` restricted to the states `keep`.
    pub fn new(inner: &'a S, keep: Vec<usize>) -> Self {
        let n = inner.dim();
        let all = keep.iter().copied().eq(0..n);
        Reduced { inner, keep, all, full: std::cell::RefCell::new((vec![0.0; n], vec![0.0; n])) }
    }

    /// The full system, every state kept.
    pub fn inner(&self) -> &'a S {
        self.inner
    }

    /// The full state with the dropped coordinates at zero.
    pub fn expand(&self, y: &[f64], full: &mut [f64]) {
        full.fill(0.0);
        for (i, k) in self.keep.iter().enumerate() {
            full[*k] = y[i];
        }
    }
}

impl<S: System> System for Reduced<'_, S> {
    // The full dimension, and the one without every cyclic coordinate: a run that keeps
    // another number of states takes general steps.
    const FIXED_DIM: usize = S::FIXED_DIM;
    const REDUCED_DIM: usize = S::REDUCED_DIM;
    const UNROLL_ANY_DIM: bool = S::UNROLL_ANY_DIM;
    fn dim(&self) -> usize {
        self.keep.len()
    }
    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        if self.all {
            return self.inner.rhs(t, y, dy);
        }
        let mut full = self.full.borrow_mut();
        let (fy, fdy) = &mut *full;
        for (i, k) in self.keep.iter().enumerate() {
            fy[*k] = y[i];
        }
        self.inner.rhs(t, fy, fdy);
        for (i, k) in self.keep.iter().enumerate() {
            dy[i] = fdy[*k];
        }
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        if self.all {
            return self.inner.taylor(t, y, order, out, work);
        }
        let mut full = self.full.borrow_mut();
        let (fy, fout) = &mut *full;
        let (n, n1) = (fy.len(), order + 1);
        for (i, k) in self.keep.iter().enumerate() {
            fy[*k] = y[i];
        }
        fout.resize(n * n1, 0.0);
        let has = self.inner.taylor(t, fy, order, fout, work);
        for (i, k) in self.keep.iter().enumerate() {
            out[i * n1..(i + 1) * n1].copy_from_slice(&fout[k * n1..(k + 1) * n1]);
        }
        fout.truncate(n);
        has
    }
    fn taylor_straight_line(&self) -> &[usize] {
        self.inner.taylor_straight_line()
    }
}

/// The output of `info` of kind `kind` (kinetic energy, configuration residuals, ...), if it
/// has one: the one place an output is found by its kind.
pub(crate) fn output_of_kind(info: &ModelInfo, kind: OutputKind) -> Option<usize> {
    info.outputs.iter().position(|o| o.kind == kind)
}

/// The kinetic-energy output of a model, if it has one that reads no rates.
pub(crate) fn kinetic_energy_output(info: &ModelInfo) -> Option<usize> {
    output_of_kind(info, OutputKind::KineticEnergy)
        .filter(|k| !info.outputs[*k].needs_rates && info.outputs[*k].columns.len() == 1)
}
