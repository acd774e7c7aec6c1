//! One integration: in come the problem, the reduced system and a method; out go the rows at
//! the output times (streamed to the row sink when there is one), the plot rows, the full state
//! at the final time, the events found and the constraints kept, or the failure explained
//! where the run went wrong.

use std::ops::ControlFlow;

use super::bound::{BoundModel, Reduced};
use super::diagnose;
use super::events::Watch;
use super::residuals::Residuals;
use crate::ode::{self, normalise, Method, NormDrift, OdeError, Stats, UnitNorm};
use crate::problem::{Column, EventLog, Pick, Problem, RowStream, Rows, SolveError};

/// One integration's cost, rows and full state at the final time.
pub(crate) struct Integration {
    /// What it cost.
    pub(crate) stats: Stats,
    /// The rows at the output times (a thinned set when they were streamed).
    pub(crate) rows: Vec<Vec<f64>>,
    /// The rows at the output and plot times, for the figures (empty without plot times).
    pub(crate) plot_rows: Vec<Vec<f64>>,
    /// The full state at the final time (or where an event stopped the run).
    pub(crate) y_end: Vec<f64>,
    /// How far the unit-norm groups drifted, when there are any.
    pub(crate) norm_drift: Option<NormDrift>,
    /// The events found.
    pub(crate) events: EventLog,
    /// The largest constraint residuals at the output times.
    pub(crate) largest_residual: Residuals,
}

/// One integration at `method`: the rows written and the full state at the final time.
pub(crate) fn integrate<B: BoundModel>(
    problem: &Problem,
    sys: &Reduced<'_, B>,
    keep: &[usize],
    columns: &[Column],
    method: Method,
    rows_to: Option<&RowStream>,
) -> Result<Integration, SolveError> {
    let info = sys.inner().info();
    let n = info.state_names.len();
    let mut full_y = vec![0.0; n];
    let mut y_end = problem.initial.clone();
    let mut t_good = 0.0;
    let mut rows = Rows::streamed(rows_to.cloned());
    let mut dy = vec![0.0; n];
    let mut bad: Option<SolveError> = None;
    let y_start: Vec<f64> = keep.iter().map(|k| problem.initial[*k]).collect();
    let all_times = merged(&problem.times, &problem.plot_times);
    let mut plot_rows = Rows::thinned(rows_to.is_some());
    let mut next_output = 0;
    let groups = reduced_groups(&problem.unit_norms, keep);
    let held = UnitNorm::new(sys, &groups, norm_threshold(method));
    let mut largest_residual = Residuals::of(info);
    let on_output = |t: f64, y_red: &[f64]| {
        sys.expand(y_red, &mut full_y);
        normalise(&problem.unit_norms, &mut full_y);
        largest_residual.track(sys.inner(), t, &full_y);
        y_end.copy_from_slice(&full_y);
        t_good = t;
        let row = match row_at(problem, sys.inner(), columns, t, &full_y, &mut dy) {
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
    let integration = ode::Integration::new(&held, 0.0, &y_start, method).max_steps(problem.max_steps);
    let result = if problem.events.is_empty() {
        integration.run(&all_times, on_output)
    } else {
        let mut watch = Watch::new(problem, sys, sys.inner());
        let row = |t: f64, y: &[f64]| row_at(problem, sys.inner(), columns, t, y, &mut vec![0.0; n]);
        let run = integration.watch(|s| watch.observe(s, &row)).run(&all_times, on_output);
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
        run
    };
    let outcome = match (result.map(|run| run.stats), bad) {
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
    diagnose::explain(sys.inner(), problem, error, t_good, y_good, probed.flatten())
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
