//! Integration: in comes a [`Problem`]; out goes a [`Trajectory`]. The generic driver
//! [`solve_model`] is public, so a user's crate can integrate its own generated models; outputs
//! are computed only at output times (and the figures' plot times) and only those asked for.

use std::ops::ControlFlow;
use std::time::Instant;

use kane_model::runtime::{GeneratedModel, ModelInfo, OutputKind};
use thiserror::Error;

use crate::diagnose;
use crate::events::watch::Watch;
use crate::events::EventLog;
use crate::ode::{self, Method, OdeError, Stats, System, TaylorWork};
use crate::problem::{Pick, Problem};
use crate::refine::refine;
use crate::registry::Registry;
use crate::rows::Rows;
use crate::trajectory::{Column, Conditioning, Constraints, Trajectory};
use crate::unit_norm::{normalise, NormDrift, UnitNorm};
use kane_model::assembly::Assembly;

/// Why an integration failed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SolveError {
    /// The problem names a model the registry does not have.
    #[error("unknown model `{0}`")]
    UnknownModel(String),
    /// A state became NaN or infinite.
    #[error("integration failed: state {name} is not finite ({value}) at t = {time}; the last good state, at t = {last_time}: {last_state}")]
    NonFiniteState {
        /// The state.
        name: String,
        /// When.
        time: f64,
        /// Its value.
        value: f64,
        /// The time of the last state written (or the start).
        last_time: f64,
        /// That state, `NAME = value unit, ...`.
        last_state: String,
    },
    /// The motion constraints' matrix of dependent speeds is (nearly) singular.
    #[error("integration failed: the motion constraints lose rank at t = {time}, {configuration}: their matrix of dependent speeds has reciprocal condition number {rcond:e}, so the dependent speeds are not determined there\n  help: choose other dependent speeds in CONSTRAIN, or keep the motion away from this configuration")]
    ConstraintRankLoss {
        /// When.
        time: f64,
        /// The coordinates, `Q1 = 0 deg, ...`.
        configuration: String,
        /// `A_d`'s smallest over largest singular value (NaN when an entry is not finite).
        rcond: f64,
    },
    /// The mass matrix of the speeds is singular or indefinite (a zero or negative mass or
    /// inertia, or bodies that lose a degree of freedom in this configuration).
    #[error("integration failed: mass matrix {} at t = {time}, {configuration}: its pivot for {speed} is {pivot:e}, not positive\n  help: check for zero or negative masses and inertias (parameters), or start away from this configuration (a gimbal at lock with massless gimbals)", if *pivot < 0.0 { "indefinite" } else { "singular" })]
    SingularMassMatrix {
        /// When.
        time: f64,
        /// The coordinates, `Q1 = 0 deg, ...`.
        configuration: String,
        /// The speed whose pivot is not positive.
        speed: String,
        /// The pivot (zero, negative or not finite).
        pivot: f64,
    },
    /// A rate is NaN or infinite (an overflow when infinite) at a finite state.
    #[error("integration failed: the rate of {name} is {value} at t = {time}: {} at the state {state}\n  help: check the parameters and initial values for extreme magnitudes, and the model's expressions where they divide, take roots or logarithms", operation.as_deref().unwrap_or("an operation outside its domain (a division by zero, a root or logarithm of a negative number) or an overflow in the equations"))]
    RateNotFinite {
        /// The state whose rate it is.
        name: String,
        /// When.
        time: f64,
        /// The rate.
        value: f64,
        /// The state, `NAME = value unit, ...`.
        state: String,
        /// The operation that made it, when the model's program is known.
        operation: Option<String>,
    },
    /// The step size collapsed where the equations approach a singularity.
    #[error("integration failed: the equations approach a singularity at t = {time}: {operation}; the step size collapsed there, at the state {state}\n  help: keep the motion away from where this divisor vanishes (parameters, initial values), or stop the run before it with an event")]
    NearSingularity {
        /// When.
        time: f64,
        /// The state, `NAME = value unit, ...`.
        state: String,
        /// The quotient whose divisor nearly vanishes.
        operation: String,
    },
    /// A state or rate so large that the next steps overflow.
    #[error("integration failed: overflow: {name} is {value:e} at t = {time}, beyond what double precision can step (about 1e150)\n  help: scale the model's units or lower the initial values")]
    Overflow {
        /// The state, or the state whose rate it is (`W1'`).
        name: String,
        /// When.
        time: f64,
        /// Its value.
        value: f64,
    },
    /// Writing a row as it was produced failed.
    #[error("integration stopped: writing a row failed: {0}")]
    Rows(String),
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
    /// The initial state cannot be brought onto the configuration constraints.
    #[error("cannot start: {0}")]
    Assembly(#[from] kane_model::assembly::AssemblyError),
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

/// One integration's cost, rows and full state at the final time.
pub(crate) struct Integration {
    pub(crate) stats: Stats,
    pub(crate) rows: Vec<Vec<f64>>,
    pub(crate) plot_rows: Vec<Vec<f64>>,
    pub(crate) y_end: Vec<f64>,
    pub(crate) norm_drift: Option<NormDrift>,
    pub(crate) events: EventLog,
    /// The largest constraint residuals at the output times.
    pub(crate) largest_residual: Residuals,
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
    let assembled = assembled(problem, full_sys)?;
    let (problem, assembly) = match &assembled {
        Some((p, a)) => (p, Some(a.clone())),
        None => (problem, None),
    };
    let keep = integrated_states(problem);
    let sys = Reduced::new(full_sys, keep.clone());
    let columns = columns(problem);
    let start_error = diagnose::constraint_rank_error(full_sys, 0.0, &problem.initial)
        .or_else(|| diagnose::mass_matrix_error(full_sys, 0.0, &problem.initial));
    if let Some(e) = start_error {
        return Err(e);
    }
    let integrate_at = |method: Method| integrate(problem, &sys, &keep, &columns, method);
    let start = Instant::now();
    let (Integration { stats, rows, plot_rows, y_end, norm_drift, events, largest_residual }, accuracy) =
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
        events,
        constraints: largest_residual.report(assembly),
    })
}

/// The problem with its initial state assembled onto the model's configuration constraints,
/// or None for a model without them.
fn assembled<B: BoundModel>(problem: &Problem, model: &B) -> Result<Option<(Problem, Assembly)>, SolveError> {
    let info = model.info();
    let Some(k) = kane_model::assembly::residual_output(info) else { return Ok(None) };
    let mut initial = problem.initial.clone();
    let assembly = kane_model::assembly::assemble(info, &mut initial, |y, dy, r, dr| {
        model.output_rate(k, 0.0, y, dy, r, dr)
    })?;
    Ok(Some((Problem { initial, ..problem.clone() }, assembly)))
}

/// The largest constraint residuals at the output times so far, by kind (configuration,
/// motion), and the worst conditioning of the dependent speeds' matrix, for a model that has
/// them.
#[derive(Clone, Debug, Default)]
pub(crate) struct Residuals {
    /// The configuration and motion residual outputs, found once.
    outputs: [Option<usize>; 2],
    configuration: Option<f64>,
    motion: Option<f64>,
    /// The constraint-matrix output, found once.
    matrix: Option<usize>,
    /// The worst conditioning so far, when the model has a constraint-matrix output.
    conditioning: Option<Conditioning>,
    scratch: Vec<f64>,
}

impl Residuals {
    /// Tracking for `info`'s residual outputs (none: nothing is computed).
    fn of(info: &ModelInfo) -> Residuals {
        let find = |kind: OutputKind| info.outputs.iter().position(|o| o.kind == kind);
        Residuals {
            outputs: [find(OutputKind::ConfigurationResiduals), find(OutputKind::MotionResiduals)],
            matrix: find(OutputKind::ConstraintMatrix),
            ..Default::default()
        }
    }

    /// Updated with the residuals and the conditioning at `(t, y)`.
    fn track<B: BoundModel>(&mut self, model: &B, t: f64, y: &[f64]) {
        for (k, slot) in self.outputs.iter().zip([&mut self.configuration, &mut self.motion]) {
            let Some(k) = *k else { continue };
            self.scratch.resize(model.info().outputs[k].columns.len(), 0.0);
            model.output(k, t, y, &[], &mut self.scratch);
            *slot = Some(kane_model::assembly::largest_magnitude(slot.unwrap_or(0.0), &self.scratch));
        }
        let Some(k) = self.matrix else { return };
        let rcond = diagnose::matrix_rcond(model, k, t, y, &mut self.scratch);
        let worse = match &self.conditioning {
            Some(c) => rcond.is_nan() || rcond < c.rcond,
            None => true,
        };
        if worse {
            let configuration = diagnose::configuration(model.info(), y);
            self.conditioning = Some(Conditioning { rcond, time: t, configuration });
        }
    }

    /// The run's report, when the model has constraints.
    fn report(self, assembly: Option<Assembly>) -> Option<Constraints> {
        let any = assembly.is_some() || self.configuration.is_some() || self.motion.is_some();
        any.then_some(Constraints {
            assembly,
            configuration: self.configuration,
            motion: self.motion,
            conditioning: self.conditioning,
        })
    }
}

/// The kinetic-energy output of a model, if it has one that reads no rates.
pub(crate) fn kinetic_energy_output(info: &ModelInfo) -> Option<usize> {
    info.outputs
        .iter()
        .position(|o| o.kind == OutputKind::KineticEnergy && !o.needs_rates && o.columns.len() == 1)
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
    problem.events.iter().flat_map(|e| &e.reads).for_each(|i| needed[*i] = true);
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
    let mut t_good = 0.0;
    let mut rows = Rows::streamed(problem.rows_to.clone());
    let mut dy = vec![0.0; n];
    let mut bad: Option<SolveError> = None;
    let y_start: Vec<f64> = keep.iter().map(|k| problem.initial[*k]).collect();
    let all_times = merged(&problem.times, &problem.plot_times);
    let mut plot_rows = Rows::thinned(problem.rows_to.is_some());
    let mut next_output = 0;
    let groups = reduced_groups(&problem.unit_norms, keep);
    let held = UnitNorm::new(sys, &groups, norm_threshold(method));
    let mut largest_residual = Residuals::of(info);
    let on_output = |t: f64, y_red: &[f64]| {
        sys.expand(y_red, &mut full_y);
        normalise(&problem.unit_norms, &mut full_y);
        largest_residual.track(sys.inner, t, &full_y);
        y_end.copy_from_slice(&full_y);
        t_good = t;
        let row = match row_at(problem, sys.inner, columns, t, &full_y, &mut dy) {
            Ok(row) => row,
            Err(e) => {
                bad = Some(e);
                return ControlFlow::Break(());
            }
        };
        if !problem.plot_times.is_empty() {
            let _ = plot_rows.push(row.clone());
        }
        if problem.times.get(next_output) == Some(&t) {
            next_output += 1;
            if let Err(e) = rows.push(row) {
                bad = Some(SolveError::Rows(e));
                return ControlFlow::Break(());
            }
        }
        ControlFlow::Continue(())
    };
    let mut events = EventLog::default();
    let result = if problem.events.is_empty() {
        ode::integrate_limited(&held, 0.0, &y_start, &all_times, method, problem.max_steps, on_output)
    } else {
        let mut watch = Watch::new(problem, sys, sys.inner);
        let row = |t: f64, y: &[f64]| row_at(problem, sys.inner, columns, t, y, &mut vec![0.0; n]);
        let run = ode::integrate_watched(
            &held,
            0.0,
            &y_start,
            &all_times,
            method,
            problem.max_steps,
            |s| watch.observe(s, &row),
            on_output,
        );
        if let Some(e) = watch.error.take() {
            return Err(e);
        }
        if let (Some(row), Some(state)) = (watch.stop_row.take(), watch.stop_state.take()) {
            if !problem.plot_times.is_empty() {
                let _ = plot_rows.push(row.clone());
            }
            rows.push(row).map_err(SolveError::Rows)?;
            y_end = state;
        }
        events = watch.log;
        run.map(|w| w.stats)
    };
    let outcome = match (result, bad) {
        (Ok(stats), None) => Ok(stats),
        (Ok(_), Some(e)) => Err(e),
        (Err(OdeError::NonFinite { time, index, value }), _) => Err(SolveError::NonFiniteState {
            name: info.state_names[keep[index]].to_string(),
            time,
            value,
            last_time: t_good,
            last_state: diagnose::state_text(info, &y_end),
        }),
        (Err(other), _) => Err(SolveError::Ode(other)),
    };
    let stats = outcome.map_err(|e| explained(problem, sys, &held, keep, method, e, (t_good, &y_end)))?;
    let norm_drift = (!groups.is_empty()).then(|| held.drift());
    let (rows, plot_rows) = (rows.into_rows(), plot_rows.into_rows());
    Ok(Integration { stats, rows, plot_rows, y_end, norm_drift, events, largest_residual })
}

/// `error` explained where the run went wrong: the failed stretch integrated again (`held`, at
/// `method`) from the last good output `good` (time, full state), see [`diagnose::probe`].
fn explained<B: BoundModel, S: ode::System + ?Sized>(
    problem: &Problem,
    sys: &Reduced<'_, B>,
    held: &S,
    keep: &[usize],
    method: Method,
    error: SolveError,
    good: (f64, &[f64]),
) -> SolveError {
    let (t_good, y_good) = good;
    let probed = diagnose::explainable(&error).then(|| {
        let from: Vec<f64> = keep.iter().map(|k| y_good[*k]).collect();
        let t_end = problem.times.last().copied().unwrap_or(t_good);
        let (t, y_red) = diagnose::probe(held, t_good, &from, t_end, method, problem.max_steps)?;
        let mut full = vec![0.0; y_good.len()];
        sys.expand(&y_red, &mut full);
        normalise(&problem.unit_norms, &mut full);
        Some((t, full))
    });
    diagnose::explain(sys.inner, problem, error, t_good, y_good, probed.flatten())
}

/// The row at `(t, full_y)`: `t`, then the picks' columns (`dy` the scratch for the speed rates
/// outputs may read); an error for a value that is not finite.
fn row_at<B: BoundModel>(
    problem: &Problem,
    model: &B,
    columns: &[Column],
    t: f64,
    full_y: &[f64],
    dy: &mut [f64],
) -> Result<Vec<f64>, SolveError> {
    let info = model.info();
    let needs_rates =
        problem.picks.iter().any(|p| matches!(p, Pick::Output(k) if info.outputs[*k].needs_rates));
    if needs_rates {
        model.rhs(t, full_y, dy);
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
                model.output(k, t, full_y, &dy[info.n_coordinates..], &mut row[at..]);
            }
        }
    }
    match row.iter().position(|v| !v.is_finite()) {
        Some(j) => {
            Err(SolveError::NonFiniteOutput { name: columns[j - 1].name.clone(), time: t, value: row[j] })
        }
        None => Ok(row),
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
