//! Integration: in come a [`Problem`] (which carries its model's entry, found when the scene
//! was resolved: nothing is looked up here) and where its rows go; out goes a [`Trajectory`].
//! The generic driver [`solve_model`] is what each registry entry of a generated model calls
//! (`Registry::with` instantiates it for a user's crate too); outputs are computed only at output
//! times (and the figures' plot times) and only those asked for.
//!
//! Files: `bound` a model with its parameters bound, as the system the steppers take;
//! `integration` one integration at one method; `refine` an asked accuracy reached by
//! tightening the tolerances; `residuals` the constraints kept along a run; `diagnose` a
//! failure named where it happened; `events` events watched after each step.

mod bound;
mod diagnose;
mod events;
mod integration;
mod refine;
mod residuals;

use std::time::Instant;

use kane_model::assembly::Assembly;
use kane_model::runtime::{GeneratedModel, OutputKind};

use bound::{kinetic_energy_output, output_of_kind};
pub use bound::{BoundModel, ModelSystem, Reduced};
use integration::{integrate, Integration};
pub(crate) use refine::largest_difference;
use refine::refine;

use crate::ode::Method;
use crate::problem::{Column, Pick, Problem, RowStream, SolveError, Trajectory};

/// Integrates `problem` with the solver of the model it carries (found when it was resolved);
/// with `rows_to` each row goes there as it is produced and only a bounded, thinned set stays in
/// memory (none: every row is kept; give none when an accuracy is asked, since refinement
/// compares whole runs).
pub fn solve(problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
    problem.model.solve(problem, rows_to)
}

/// Integrates `problem` with the generated model `M` (rows to `rows_to` as in [`solve`]).
pub fn solve_model<M: GeneratedModel>(
    problem: &Problem,
    rows_to: Option<&RowStream>,
) -> Result<Trajectory, SolveError> {
    let mut params = M::Params::default();
    for (name, v) in M::INFO.param_names.iter().zip(&problem.params) {
        M::set_param(&mut params, name, *v);
    }
    solve_bound(problem, &ModelSystem::<M>::new(params), rows_to)
}

/// Integrates `problem` with `full_sys` (a model with its parameters already bound; rows to
/// `rows_to` as in `solve`).
pub fn solve_bound<B: BoundModel>(
    problem: &Problem,
    full_sys: &B,
    rows_to: Option<&RowStream>,
) -> Result<Trajectory, SolveError> {
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
    let integrate_at = |method: Method| integrate(problem, &sys, &keep, &columns, method, rows_to);
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
    // An energy output at the start and the end: kinetic, and gravity's potential when known.
    let start_and_end = |k: usize| {
        let at = |t: f64, y: &[f64]| {
            let mut out = [0.0];
            full_sys.output(k, t, y, &[], &mut out);
            out[0]
        };
        (at(0.0, &problem.initial), at(t_end, &y_end))
    };
    let kinetic_energy = kinetic_energy_output(info).map(start_and_end);
    let potential = output_of_kind(info, OutputKind::PotentialEnergy)
        .filter(|k| !info.outputs[*k].needs_rates && info.outputs[*k].columns.len() == 1);
    let potential_energy = kinetic_energy.and(potential).map(start_and_end);
    Ok(Trajectory {
        title: problem.title.clone(),
        columns,
        rows,
        plot_rows,
        stats,
        wall,
        integrated: keep.iter().map(|k| info.state_names[*k]).collect(),
        kinetic_energy,
        potential_energy,
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

/// The states to integrate: all but the cyclic coordinates that no column reads.
fn integrated_states(problem: &Problem) -> Vec<usize> {
    let info = problem.model.info();
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
    let info = problem.model.info();
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
