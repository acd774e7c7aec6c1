//! Assembly: in comes a state of a model with configuration constraints (a closed loop, a
//! wheel on the ground); out goes the same state with its dependent coordinates solved by
//! Newton's method so the constraints hold, or an error that names why they cannot.

use nalgebra::{DMatrix, DVector};
use thiserror::Error;

use crate::runtime::{ModelInfo, OutputKind};

/// Newton steps before giving up.
const MAX_ITERATIONS: usize = 50;

/// What assembling a state did.
#[derive(Clone, Debug, PartialEq)]
pub struct Assembly {
    /// Newton steps taken (0 when the state already satisfied the constraints).
    pub iterations: usize,
    /// The largest residual left.
    pub residual: f64,
    /// Each dependent coordinate: its name, value before and value after.
    pub moved: Vec<(&'static str, f64, f64)>,
}

/// Why a state could not be assembled.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum AssemblyError {
    /// The constraints' Jacobian in the dependent coordinates is singular.
    #[error(
        "the configuration constraints do not determine {coordinates} at {at}: their Jacobian in \
         these coordinates is singular (a toggle or dead-centre position)\n  help: start from a \
         configuration away from it, or choose other dependent speeds in CONSTRAIN"
    )]
    Singular {
        /// The dependent coordinates' names.
        coordinates: String,
        /// The state, `NAME = value, ...`.
        at: String,
    },
    /// Newton's method did not bring the residuals to zero.
    #[error(
        "the configuration constraints cannot be met near the initial state: residual {residual:e} \
         after {iterations} Newton steps in {coordinates} from {at}\n  help: give initial values \
         of {coordinates} near an assembled configuration, or check the constraints and lengths"
    )]
    NoConvergence {
        /// The dependent coordinates' names.
        coordinates: String,
        /// The largest residual left.
        residual: f64,
        /// Steps taken.
        iterations: usize,
        /// The coordinates Newton started from, `NAME = value, ...`.
        at: String,
    },
}

/// The output holding a model's configuration residuals, if it has one.
pub fn residual_output(info: &ModelInfo) -> Option<usize> {
    info.outputs.iter().position(|o| o.kind == OutputKind::ConfigurationResiduals)
}

/// The largest of `start` and the magnitudes of `values`; NaN when any of them is NaN (so a
/// residual that is not a number is never taken for a small one).
pub fn largest_magnitude(start: f64, values: &[f64]) -> f64 {
    values.iter().fold(start, |a, x| if a.is_nan() || x.is_nan() { f64::NAN } else { a.max(x.abs()) })
}

/// Solves the dependent coordinates of `y` (the others held) so the configuration residuals
/// vanish. `residual(y, dy, r, dr)` writes the residuals at `y` into `r` and their derivative
/// along `dy` into `dr` (a model's `output_rate` of [`residual_output`]).
pub fn assemble(
    info: &ModelInfo,
    y: &mut [f64],
    mut residual: impl FnMut(&[f64], &[f64], &mut [f64], &mut [f64]),
) -> Result<Assembly, AssemblyError> {
    let dependent = info.dependent_coordinates;
    let m = dependent.len();
    let start = y.to_vec();
    let before: Vec<f64> = dependent.iter().map(|i| y[*i]).collect();
    let (mut r, mut dr, mut dy) = (vec![0.0; m], vec![0.0; m], vec![0.0; y.len()]);
    let mut jacobian = DMatrix::zeros(m, m);
    let mut evaluate = |y: &[f64], r: &mut [f64], jacobian: &mut DMatrix<f64>| {
        for (j, &k) in dependent.iter().enumerate() {
            dy[k] = 1.0;
            residual(y, &dy, r, &mut dr);
            dy[k] = 0.0;
            jacobian.column_mut(j).copy_from_slice(&dr);
        }
    };
    evaluate(y, &mut r, &mut jacobian);
    let largest = |r: &[f64]| largest_magnitude(0.0, r);
    let goal = 1e-12 * largest(&r).max(1.0);
    let mut iterations = 0;
    loop {
        let size = largest(&r);
        if size <= goal {
            break;
        }
        if iterations == MAX_ITERATIONS || !size.is_finite() {
            return Err(no_convergence(info, &start, size, iterations));
        }
        let step = newton_step(&jacobian, &r).ok_or_else(|| AssemblyError::Singular {
            coordinates: names(info, dependent),
            at: state_text(info, y),
        })?;
        for (&k, dq) in dependent.iter().zip(step.iter()) {
            y[k] -= dq;
        }
        iterations += 1;
        evaluate(y, &mut r, &mut jacobian);
    }
    let moved = dependent.iter().zip(before).map(|(&k, b)| (info.state_names[k], b, y[k])).collect();
    Ok(Assembly { iterations, residual: largest(&r), moved })
}

/// `J^-1 r` by pivoted LU, or None when `J` is singular (a pivot below 1e-12 of the largest
/// entry).
fn newton_step(jacobian: &DMatrix<f64>, r: &[f64]) -> Option<DVector<f64>> {
    let scale = jacobian.amax();
    let lu = jacobian.clone().lu();
    let smallest = lu.u().diagonal().amin();
    if !(scale > 0.0 && smallest > 1e-12 * scale) {
        return None;
    }
    lu.solve(&DVector::from_column_slice(r))
}

fn no_convergence(info: &ModelInfo, y: &[f64], residual: f64, iterations: usize) -> AssemblyError {
    AssemblyError::NoConvergence {
        coordinates: names(info, info.dependent_coordinates),
        residual,
        iterations,
        at: state_text(info, y),
    }
}

fn names(info: &ModelInfo, states: &[usize]) -> String {
    states.iter().map(|i| info.state_names[*i]).collect::<Vec<_>>().join(", ")
}

/// The coordinates, `Q1 = 0.5, ...`.
fn state_text(info: &ModelInfo, y: &[f64]) -> String {
    (0..info.n_coordinates)
        .map(|i| format!("{} = {}", info.state_names[i], y[i]))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    const CIRCLE: ModelInfo = ModelInfo {
        name: "circle",
        state_names: &["X", "Y", "U"],
        state_units: &["", "", ""],
        n_coordinates: 2,
        param_names: &[],
        param_units: &[],
        inputs: &[],
        open_inputs: &[],
        outputs: &[],
        cyclic: &[],
        dependent_coordinates: &[1],
        op_counts: crate::runtime::OpCounts { rhs: 0, outputs: 0 },
        taylor_straight_line: &[],
    };

    /// `x^2 + y^2 - 1` and its derivative along `dy`.
    fn circle(y: &[f64], dy: &[f64], r: &mut [f64], dr: &mut [f64]) {
        r[0] = y[0] * y[0] + y[1] * y[1] - 1.0;
        dr[0] = 2.0 * (y[0] * dy[0] + y[1] * dy[1]);
    }

    #[test]
    fn newton_puts_the_dependent_coordinate_on_the_circle() {
        let mut y = [0.6, 0.5, 3.0];
        let a = assemble(&CIRCLE, &mut y, circle).unwrap();
        assert!((y[1] - 0.8).abs() < 1e-15, "{y:?}");
        assert_eq!((y[0], y[2]), (0.6, 3.0), "the others are held");
        assert_eq!(a.moved, vec![("Y", 0.5, y[1])]);
        assert!(a.iterations >= 3 && a.residual < 1e-15, "{a:?}");
        let again = assemble(&CIRCLE, &mut y, circle).unwrap();
        assert_eq!(again.iterations, 0, "an assembled state is left alone");
    }

    #[test]
    fn a_singular_or_unreachable_configuration_is_named() {
        let e = assemble(&CIRCLE, &mut [0.6, 0.0, 0.0], circle).unwrap_err();
        assert!(matches!(e, AssemblyError::Singular { .. }), "{e}");
        assert!(e.to_string().contains("do not determine Y at X = 0.6, Y = 0"), "{e}");
        let e = assemble(&CIRCLE, &mut [2.0, 0.5, 0.0], circle).unwrap_err();
        assert!(e.to_string().contains("cannot be met"), "{e}");
    }
}
