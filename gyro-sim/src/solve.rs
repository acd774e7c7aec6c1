//! Integration: in comes a [`Problem`]; out goes a [`Trajectory`]. The generic driver
//! [`solve_model`] is public, so a user's crate can integrate its own generated models; outputs
//! are computed only at output times (and the figures' plot times) and only those asked for.

use std::ops::ControlFlow;
use std::time::Instant;

use kane_model::runtime::{GeneratedModel, ModelInfo};
use thiserror::Error;

use crate::ode::{self, Method, OdeError, Stats, System, TaylorWork};
use crate::problem::{Pick, Problem};
use crate::refine::refine;
use crate::registry::Registry;
use crate::trajectory::{Column, Trajectory};
use crate::unit_norm::{normalise, NormDrift, UnitNorm};

/// Why an integration failed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SolveError {
    /// The problem names a model the registry does not have.
    #[error("unknown model `{0}`")]
    UnknownModel(String),
    /// A state became NaN or infinite.
    #[error("integration failed: state {name} is not finite ({value}) at t = {time}")]
    NonFiniteState {
        /// The state.
        name: String,
        /// When.
        time: f64,
        /// Its value.
        value: f64,
    },
    /// An output became NaN or infinite.
    #[error("integration failed: {name} is not finite ({value}) at t = {time}")]
    NonFiniteOutput {
        /// The output column.
        name: String,
        /// When.
        time: f64,
        /// Its value.
        value: f64,
    },
    /// The integrator stopped.
    #[error("integration failed: {0}")]
    Ode(#[from] OdeError),
    /// Refining the tolerances could not reach the asked accuracy.
    #[error("integration failed: accuracy {goal:e} not reached: runs at rtol {rtol:e} and below still differ by more; ask a looser accuracy")]
    AccuracyNotReached {
        /// Asked.
        goal: f64,
        /// The finest relative tolerance tried.
        rtol: f64,
    },
}

/// Integrates `problem` with the model the registry has under its name.
pub fn solve(problem: &Problem, registry: &Registry) -> Result<Trajectory, SolveError> {
    let entry = registry
        .find(&problem.model_key)
        .ok_or_else(|| SolveError::UnknownModel(problem.model_key.clone()))?;
    (entry.solve)(problem)
}

/// A generated model with parameters, as an ODE system.
pub struct ModelSystem<M: GeneratedModel> {
    params: M::Params,
    derived: M::Derived,
}

impl<M: GeneratedModel> ModelSystem<M> {
    /// The system for these parameters.
    pub fn new(params: M::Params) -> Self {
        let derived = M::derive(&params);
        ModelSystem { params, derived }
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
}

impl<M: GeneratedModel> BoundModel for ModelSystem<M> {
    fn info(&self) -> &'static ModelInfo {
        &M::INFO
    }
    fn output(&self, k: usize, t: f64, y: &[f64], rates: &[f64], out: &mut [f64]) {
        M::output(k, t, y, rates, &self.params, out)
    }
}

impl<M: GeneratedModel> System for ModelSystem<M> {
    fn dim(&self) -> usize {
        M::INFO.state_names.len()
    }
    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        M::rhs_derived(t, y, &self.params, &self.derived, dy)
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        M::taylor(t, y, &self.params, &self.derived, order, out, work)
    }
}

/// A system without some of its states (cyclic coordinates nothing asked for depends on): they
/// are held at zero, which no equation reads, and never integrated.
pub struct Reduced<'a, S: System> {
    inner: &'a S,
    keep: Vec<usize>,
    full: std::cell::RefCell<(Vec<f64>, Vec<f64>)>,
}

impl<'a, S: System> Reduced<'a, S> {
    /// `inner` restricted to the states `keep`.
    pub fn new(inner: &'a S, keep: Vec<usize>) -> Self {
        let n = inner.dim();
        Reduced { inner, keep, full: std::cell::RefCell::new((vec![0.0; n], vec![0.0; n])) }
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
    fn dim(&self) -> usize {
        self.keep.len()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
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
}

/// One integration's cost, rows and full state at the final time.
pub(crate) struct Integration {
    pub(crate) stats: Stats,
    pub(crate) rows: Vec<Vec<f64>>,
    pub(crate) plot_rows: Vec<Vec<f64>>,
    pub(crate) y_end: Vec<f64>,
    pub(crate) norm_drift: Option<NormDrift>,
}

/// Integrates `problem` with the generated model `M`.
pub fn solve_model<M: GeneratedModel>(problem: &Problem) -> Result<Trajectory, SolveError> {
    let mut params = M::Params::default();
    for (name, v) in M::INFO.param_names.iter().zip(&problem.params) {
        M::set_param(&mut params, name, *v);
    }
    solve_bound(problem, &ModelSystem::<M>::new(params))
}

/// Integrates `problem` with `model` (its parameters already bound).
pub fn solve_bound<B: BoundModel>(problem: &Problem, full_sys: &B) -> Result<Trajectory, SolveError> {
    let info = full_sys.info();
    let keep = integrated_states(problem);
    let sys = Reduced::new(full_sys, keep.clone());
    let columns = columns(problem);
    let integrate_at = |method: Method| integrate(problem, &sys, &keep, &columns, method);
    let start = Instant::now();
    let (Integration { stats, rows, plot_rows, y_end, norm_drift }, accuracy) =
        match (problem.accuracy, problem.method) {
            (Some(goal), method @ (Method::Adaptive(_, tol) | Method::Taylor(tol))) => {
                // The time and the written columns: view-only columns come after them.
                let compared = 1 + columns.iter().filter(|c| !c.hidden).count();
                refine(goal, method, tol, compared, integrate_at)?
            }
            _ => (integrate_at(problem.method)?, None),
        };
    let wall = start.elapsed();
    let t_end = *problem.times.last().unwrap_or(&0.0);
    let kinetic_energy = kinetic_energy_output(info).map(|k| {
        let at = |t: f64, y: &[f64]| {
            let mut out = [0.0];
            full_sys.output(k, t, y, &[], &mut out);
            out[0]
        };
        (at(0.0, &problem.initial), at(t_end, &y_end))
    });
    Ok(Trajectory {
        title: problem.title.clone(),
        columns,
        rows,
        plot_rows,
        stats,
        wall,
        integrated: keep.iter().map(|k| info.state_names[*k]).collect(),
        kinetic_energy,
        accuracy,
        norm_drift,
    })
}

/// The kinetic-energy output of a model, if it has one that reads no rates.
fn kinetic_energy_output(info: &ModelInfo) -> Option<usize> {
    info.outputs.iter().position(|o| o.kind == "kinetic_energy" && !o.needs_rates && o.columns.len() == 1)
}

/// The states to integrate: all but the cyclic coordinates that no column reads.
fn integrated_states(problem: &Problem) -> Vec<usize> {
    let info = problem.model;
    let mut needed = vec![false; info.state_names.len()];
    for p in &problem.picks {
        match p {
            Pick::State(i) => needed[*i] = true,
            Pick::Output(k) => info.outputs[*k].reads.iter().for_each(|i| needed[*i] = true),
        }
    }
    (0..needed.len()).filter(|i| needed[*i] || !info.cyclic.contains(i)).collect()
}

/// The columns the picks write (those past `written_picks` hidden).
pub(crate) fn columns(problem: &Problem) -> Vec<Column> {
    let info = problem.model;
    let mut out = Vec::new();
    for (n, p) in problem.picks.iter().enumerate() {
        let hidden = n >= problem.written_picks;
        match *p {
            Pick::State(i) => out.push(Column {
                name: info.state_names[i].to_string(),
                unit: info.state_units[i].to_string(),
                output: false,
                hidden,
            }),
            Pick::Output(k) => {
                let o = &info.outputs[k];
                out.extend(o.columns.iter().map(|c| Column {
                    name: c.to_string(),
                    unit: o.unit.to_string(),
                    output: true,
                    hidden,
                }));
            }
        }
    }
    out
}

/// One integration at `method`: the rows written and the full state at the final time.
fn integrate<B: BoundModel>(
    problem: &Problem,
    sys: &Reduced<'_, B>,
    keep: &[usize],
    columns: &[Column],
    method: Method,
) -> Result<Integration, SolveError> {
    let info = sys.inner.info();
    let n = info.state_names.len();
    let mut full_y = vec![0.0; n];
    let mut y_end = problem.initial.clone();
    let mut rows: Vec<Vec<f64>> = Vec::with_capacity(problem.times.len());
    let mut dy = vec![0.0; n];
    let needs_rates =
        problem.picks.iter().any(|p| matches!(p, Pick::Output(k) if info.outputs[*k].needs_rates));
    let mut bad: Option<SolveError> = None;
    let y_start: Vec<f64> = keep.iter().map(|k| problem.initial[*k]).collect();
    let all_times = merged(&problem.times, &problem.plot_times);
    let mut plot_rows: Vec<Vec<f64>> = Vec::new();
    let mut next_output = 0;
    let groups = reduced_groups(&problem.unit_norms, keep);
    let held = UnitNorm::new(sys, &groups, norm_threshold(method));
    let result =
        ode::integrate_limited(&held, 0.0, &y_start, &all_times, method, problem.max_steps, |t, y_red| {
            sys.expand(y_red, &mut full_y);
            normalise(&problem.unit_norms, &mut full_y);
            y_end.copy_from_slice(&full_y);
            if needs_rates {
                sys.inner.rhs(t, &full_y, &mut dy);
            }
            let mut row = Vec::with_capacity(columns.len() + 1);
            row.push(t);
            for p in &problem.picks {
                match *p {
                    Pick::State(i) => row.push(full_y[i]),
                    Pick::Output(k) => {
                        let width = info.outputs[k].columns.len();
                        let at = row.len();
                        row.resize(at + width, 0.0);
                        sys.inner.output(k, t, &full_y, &dy[info.n_coordinates..], &mut row[at..]);
                    }
                }
            }
            if let Some(j) = row.iter().position(|v| !v.is_finite()) {
                let name = columns[j - 1].name.clone();
                bad = Some(SolveError::NonFiniteOutput { name, time: t, value: row[j] });
                return ControlFlow::Break(());
            }
            if !problem.plot_times.is_empty() {
                plot_rows.push(row.clone());
            }
            if problem.times.get(next_output) == Some(&t) {
                next_output += 1;
                rows.push(row);
            }
            ControlFlow::Continue(())
        });
    let stats = result.map_err(|e| match e {
        OdeError::NonFinite { time, index, value } => {
            SolveError::NonFiniteState { name: info.state_names[keep[index]].to_string(), time, value }
        }
        other => SolveError::Ode(other),
    })?;
    match bad {
        Some(e) => Err(e),
        None => {
            let norm_drift = (!groups.is_empty()).then(|| held.drift());
            Ok(Integration { stats, rows, plot_rows, y_end, norm_drift })
        }
    }
}

/// The unit-norm groups as indices into the integrated states `keep`.
fn reduced_groups(groups: &[Vec<usize>], keep: &[usize]) -> Vec<Vec<usize>> {
    groups.iter().map(|g| g.iter().filter_map(|i| keep.iter().position(|k| k == i)).collect()).collect()
}

/// How far a unit norm may drift before it is projected back: the method's tolerance (a
/// fixed-step method's state is held to 1e-10).
fn norm_threshold(method: Method) -> f64 {
    match method {
        Method::Adaptive(_, tol) | Method::Taylor(tol) => tol.rtol.max(tol.atol),
        Method::Fixed(..) => 1e-10,
    }
}

/// The increasing union of two increasing time lists.
fn merged(a: &[f64], b: &[f64]) -> Vec<f64> {
    let mut out: Vec<f64> = a.iter().chain(b).copied().collect();
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}
