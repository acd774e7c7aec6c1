//! Failures named: in comes a bound model at the state where an integration starts, where a
//! failed one went wrong (found by [`probe`](fn@probe)) or last succeeded; out goes what is wrong there (motion constraints that lose rank, a singular or
//! indefinite mass matrix, rates that are not finite or overflow, a singularity approached),
//! with the configuration and the operation that made it, or nothing.
//!
//! The mass matrix of the speeds is read off the model's kinetic-energy output (generated from
//! the same lowered program as the right-hand side): `T = u^T M u / 2 + b^T u + c`, so
//! `M_ij = (T(e_i + e_j) - T(e_i - e_j) - T(-e_i + e_j) + T(-e_i - e_j)) / 4`.

mod probe;

pub(crate) use probe::probe;

use kane_model::lang::units::size::shown_per_internal;
use kane_model::mechanics::{reciprocal_condition, CONSTRAINT_RCOND_LIMIT};
use kane_model::program::ProgramModel;
use kane_model::runtime::{ModelInfo, OutputKind};

use super::bound::{kinetic_energy_output, output_of_kind, BoundModel};
use crate::problem::Problem;
use crate::problem::SolveError;

/// A pivot this small against the largest diagonal entry makes the mass matrix singular.
const SINGULAR_PIVOT: f64 = 1e-10;
/// Where the step size collapsed, a pivot this small against the mass matrix's largest diagonal
/// entry at the start names it as the cause.
const COLLAPSED_PIVOT: f64 = 1e-6;

/// The coordinates the equations read, `Q1 = 0 deg, Q2 = 90 deg` (angles integrated in radians
/// shown in degrees): cyclic ones cannot matter to a configuration and, when no output needs
/// them, are not integrated (their start value would be a wrong one).
pub(crate) fn configuration(info: &ModelInfo, y: &[f64]) -> String {
    let read: Vec<usize> = (0..info.n_coordinates).filter(|i| !info.cyclic.contains(i)).collect();
    named_values(info, y, read)
}

/// Every state, as [`configuration`] writes the coordinates.
pub(crate) fn state_text(info: &ModelInfo, y: &[f64]) -> String {
    named_values(info, y, 0..info.state_names.len().min(y.len()))
}

fn named_values(info: &ModelInfo, y: &[f64], states: impl IntoIterator<Item = usize>) -> String {
    let text = |i: usize| match info.state_units[i] {
        u if u.eq_ignore_ascii_case("DEG") => format!("{} = {} deg", info.state_names[i], y[i].to_degrees()),
        "" => format!("{} = {}", info.state_names[i], y[i]),
        u => format!("{} = {} {u}", info.state_names[i], y[i] * shown_per_internal(u)),
    };
    states.into_iter().map(text).collect::<Vec<_>>().join(", ")
}

/// The mass matrix of the speeds at `(t, y)` (row-major), when the model has a kinetic-energy
/// output that reads no rates.
fn mass_matrix<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<Vec<f64>> {
    let info = sys.info();
    let k = kinetic_energy_output(info)?;
    let (nq, n) = (info.n_coordinates, info.state_names.len() - info.n_coordinates);
    let mut probe = y.to_vec();
    let mut energy = |a: (usize, f64), b: (usize, f64)| {
        probe[nq..].fill(0.0);
        probe[nq + a.0] += a.1;
        probe[nq + b.0] += b.1;
        let mut out = [0.0];
        sys.output(k, t, &probe, &[], &mut out);
        out[0]
    };
    let mut m = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..=i {
            let v = (energy((i, 1.0), (j, 1.0)) - energy((i, 1.0), (j, -1.0)) - energy((i, -1.0), (j, 1.0))
                + energy((i, -1.0), (j, -1.0)))
                / 4.0;
            m[i * n + j] = v;
            m[j * n + i] = v;
        }
    }
    Some(m)
}

/// The first pivot of `M = L D L^T` that is not clearly positive: its index and value (only
/// the lower triangle is read).
fn bad_pivot(m: Vec<f64>, n: usize) -> Option<(usize, f64)> {
    bad_pivot_against(m, n, 0.0, SINGULAR_PIVOT)
}

/// The first pivot not above `tolerance` times the largest diagonal entry of `m` or
/// `reference`, whichever is larger.
fn bad_pivot_against(mut m: Vec<f64>, n: usize, reference: f64, tolerance: f64) -> Option<(usize, f64)> {
    let scale = (0..n).map(|i| m[i * n + i].abs()).fold(reference, f64::max);
    for k in 0..n {
        let d = m[k * n + k];
        if !d.is_finite() || d <= tolerance * scale || scale == 0.0 {
            return Some((k, d));
        }
        for i in k + 1..n {
            let l = m[i * n + k] / d;
            for j in k + 1..=i {
                m[i * n + j] -= l * m[j * n + k];
            }
        }
    }
    None
}

/// A singular or indefinite mass matrix at `(t, y)`, named with the configuration.
pub(crate) fn mass_matrix_error<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<SolveError> {
    let info = sys.info();
    let n = info.state_names.len() - info.n_coordinates;
    let found = bad_pivot(mass_matrix(sys, t, y)?, n);
    singular_mass_matrix(sys, t, y, found)
}

/// Where the step size collapsed at `(t, y)`: a mass matrix whose pivot fell below
/// [`COLLAPSED_PIVOT`] of its size at the start `y0`, named with the configuration.
fn collapsed_mass_matrix<B: BoundModel>(sys: &B, t: f64, y: &[f64], y0: &[f64]) -> Option<SolveError> {
    let info = sys.info();
    let n = info.state_names.len() - info.n_coordinates;
    let start = mass_matrix(sys, 0.0, y0)?;
    let reference = (0..n).map(|i| start[i * n + i].abs()).fold(0.0, f64::max);
    let found = bad_pivot_against(mass_matrix(sys, t, y)?, n, reference, COLLAPSED_PIVOT);
    singular_mass_matrix(sys, t, y, found)
}

/// The error for the pivot `found` (its index and value) of the mass matrix at `(t, y)`.
fn singular_mass_matrix<B: BoundModel>(
    sys: &B,
    t: f64,
    y: &[f64],
    found: Option<(usize, f64)>,
) -> Option<SolveError> {
    let info = sys.info();
    let (k, pivot) = found?;
    Some(SolveError::SingularMassMatrix {
        time: t,
        configuration: configuration(info, y),
        speed: info.state_names[info.n_coordinates + k].to_string(),
        pivot,
    })
}

/// The smallest over the largest singular value of the motion constraints' matrix of
/// dependent speeds at `(t, y)`, when the model has that matrix as an output.
pub(crate) fn constraint_rcond<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<f64> {
    let k = output_of_kind(sys.info(), OutputKind::ConstraintMatrix)?;
    Some(matrix_rcond(sys, k, t, y, &mut Vec::new()))
}

/// The reciprocal condition number of the constraint-matrix output `k` at `(t, y)`, its
/// entries written into `scratch`.
pub(crate) fn matrix_rcond<B: BoundModel>(
    sys: &B,
    k: usize,
    t: f64,
    y: &[f64],
    scratch: &mut Vec<f64>,
) -> f64 {
    let size = sys.info().outputs[k].columns.len();
    scratch.resize(size, 0.0);
    sys.output(k, t, y, &[], scratch);
    reciprocal_condition(size.isqrt(), scratch)
}

/// Motion constraints that lose rank at `(t, y)` (reciprocal condition number below
/// [`CONSTRAINT_RCOND_LIMIT`], or not finite), named with the configuration.
pub(crate) fn constraint_rank_error<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<SolveError> {
    let rcond = constraint_rcond(sys, t, y)?;
    (rcond.is_nan() || rcond < CONSTRAINT_RCOND_LIMIT).then(|| SolveError::ConstraintRankLoss {
        time: t,
        configuration: configuration(sys.info(), y),
        rcond,
    })
}

/// Rates that are not finite at `(t, y)` (or overflow), named with the state.
pub(crate) fn rates_error<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<SolveError> {
    let info = sys.info();
    let mut dy = vec![0.0; y.len()];
    sys.rhs(t, y, &mut dy);
    let i = dy.iter().position(|v| !v.is_finite())?;
    Some(SolveError::RateNotFinite {
        name: info.state_names[i].to_string(),
        time: t,
        value: dy[i],
        state: state_text(info, y),
        operation: None,
    })
}

/// A state or rate whose magnitude leaves no room for a step's arithmetic.
const OVERFLOW_RISK: f64 = 1e150;

/// A state or rate at `(t, y)` so large that steps overflow, named.
fn overflow_error<B: BoundModel>(sys: &B, t: f64, y: &[f64]) -> Option<SolveError> {
    let names = sys.info().state_names;
    let mut dy = vec![0.0; y.len()];
    sys.rhs(t, y, &mut dy);
    let big = |v: &f64| v.abs() > OVERFLOW_RISK;
    let found = match y.iter().position(big) {
        Some(i) => Some((names[i].to_string(), y[i])),
        None => dy.iter().position(big).map(|i| (format!("{}'", names[i]), dy[i])),
    };
    found.map(|(name, value)| SolveError::Overflow { name, time: t, value })
}

/// Whether a failure may have a cause that [`explain`] can name.
pub(crate) fn explainable(error: &SolveError) -> bool {
    matches!(
        error,
        SolveError::NonFiniteState { .. }
            | SolveError::NonFiniteOutput { .. }
            | SolveError::Ode(crate::ode::OdeError::StepSizeUnderflow { .. })
    )
}

/// `error` explained: first where the probe found the failure (`probed`: a full state whose
/// rates are not finite, or the last step's end), then at the last good output `(t, y)`. A
/// cause found there (constraints losing rank, a singular mass matrix, rates that are not
/// finite, values about to overflow, a singularity approached) replaces it, with the operation
/// that made it named when the model's program is known.
pub(crate) fn explain<B: BoundModel>(
    sys: &B,
    problem: &Problem,
    error: SolveError,
    t: f64,
    y: &[f64],
    probed: Option<(f64, Vec<f64>)>,
) -> SolveError {
    if !explainable(&error) {
        return error;
    }
    let program = problem.model.program().filter(|p| {
        let (a, b) = (p.info(), sys.info());
        a.param_names == b.param_names && a.state_names == b.state_names
    });
    let params = &problem.params;
    let cause_at = |t: f64, y: &[f64]| {
        constraint_rank_error(sys, t, y)
            .or_else(|| mass_matrix_error(sys, t, y))
            .or_else(|| rates_error(sys, t, y).map(|e| named_operation(e, program.as_deref(), params, t, y)))
            .or_else(|| overflow_error(sys, t, y))
    };
    if let Some((tp, yp)) = &probed {
        if let Some(e) = cause_at(*tp, yp) {
            return e;
        }
        if let Some(e) = collapsed_mass_matrix(sys, *tp, yp, &problem.initial) {
            return e;
        }
        let near = program.as_deref().and_then(|p| p.rhs_near_fault(*tp, yp, params));
        if let Some(fault) = near {
            let state = state_text(sys.info(), yp);
            return SolveError::NearSingularity { time: *tp, state, operation: fault.to_string() };
        }
    }
    cause_at(t, y).unwrap_or(error)
}

/// `error` (rates that are not finite at `(t, y)`) with the operation that made them named.
fn named_operation(
    error: SolveError,
    program: Option<&ProgramModel>,
    params: &[f64],
    t: f64,
    y: &[f64],
) -> SolveError {
    match (error, program.and_then(|p| p.rhs_fault(t, y, params))) {
        (SolveError::RateNotFinite { name, time, value, state, .. }, Some(fault)) => {
            SolveError::RateNotFinite { name, time, value, state, operation: Some(fault.to_string()) }
        }
        (error, _) => error,
    }
}

#[cfg(test)]
mod tests {
    use super::bad_pivot;

    #[test]
    fn pivots_name_singular_and_indefinite_matrices() {
        assert_eq!(bad_pivot(vec![2.0, 1.0, 1.0, 2.0], 2), None);
        assert_eq!(bad_pivot(vec![1.0, 1.0, 1.0, 1.0], 2).map(|p| p.0), Some(1));
        assert!(bad_pivot(vec![1.0, 2.0, 2.0, 1.0], 2).is_some_and(|p| p.1 < 0.0));
        assert_eq!(bad_pivot(vec![0.0; 4], 2).map(|p| p.0), Some(0));
        let spd = vec![4.0, 2.0, 0.0, 2.0, 5.0, 1.0, 0.0, 1.0, 3.0];
        assert_eq!(bad_pivot(spd, 3), None);
    }
}
