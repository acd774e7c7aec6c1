//! Failures named: in comes a bound model at the state where an integration starts or last
//! succeeded; out goes what is wrong there (motion constraints that lose rank, a singular or
//! indefinite mass matrix, rates that are not finite or overflow), with the configuration, or
//! nothing.
//!
//! The mass matrix of the speeds is read off the model's kinetic-energy output (generated from
//! the same lowered program as the right-hand side): `T = u^T M u / 2 + b^T u + c`, so
//! `M_ij = (T(e_i + e_j) - T(e_i - e_j) - T(-e_i + e_j) + T(-e_i - e_j)) / 4`.

use kane_model::mechanics::{reciprocal_condition, CONSTRAINT_RCOND_LIMIT};
use kane_model::runtime::ModelInfo;

use crate::solve::{kinetic_energy_output, BoundModel, SolveError};

/// A pivot this small against the largest diagonal entry makes the mass matrix singular.
const SINGULAR_PIVOT: f64 = 1e-10;

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
        u => format!("{} = {} {u}", info.state_names[i], y[i]),
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
fn bad_pivot(mut m: Vec<f64>, n: usize) -> Option<(usize, f64)> {
    let scale = (0..n).map(|i| m[i * n + i].abs()).fold(0.0, f64::max);
    for k in 0..n {
        let d = m[k * n + k];
        if !d.is_finite() || d <= SINGULAR_PIVOT * scale || scale == 0.0 {
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
    let (k, pivot) = bad_pivot(mass_matrix(sys, t, y)?, n)?;
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
    let k = sys.info().outputs.iter().position(|o| o.kind == "constraint_matrix")?;
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

/// `error` explained at the last good state `(t, y)` when a cause is found there: a singular
/// mass matrix, rates that are not finite, values about to overflow; otherwise `error` itself.
pub(crate) fn explain<B: BoundModel>(sys: &B, error: SolveError, t: f64, y: &[f64]) -> SolveError {
    let explainable = matches!(
        error,
        SolveError::NonFiniteState { .. }
            | SolveError::NonFiniteOutput { .. }
            | SolveError::Ode(crate::ode::OdeError::StepSizeUnderflow { .. })
    );
    if !explainable {
        return error;
    }
    constraint_rank_error(sys, t, y)
        .or_else(|| mass_matrix_error(sys, t, y))
        .or_else(|| rates_error(sys, t, y))
        .or_else(|| overflow_error(sys, t, y))
        .unwrap_or(error)
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
