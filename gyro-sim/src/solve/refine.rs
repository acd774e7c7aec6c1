//! An accuracy asked of a trajectory: in come a goal, a method and one integration as a
//! function of the tolerances; out goes the run whose predecessor it agrees with to the goal.

use super::integration::Integration;
use crate::ode::{Method, Stats, Tolerances};
use crate::problem::Accuracy;
use crate::problem::SolveError;

/// Tolerances shrink by this factor from one run to the next when an accuracy is asked.
const REFINEMENT: f64 = 100.0;
/// The smallest relative tolerance the refinement tries (round-off dominates below).
const SMALLEST_RTOL: f64 = 1e-14;

/// Runs at `tol`, `tol / 100`, ... until two successive runs differ by at most `goal` (relative to
/// max(1, |value|)); returns the finer run, whose error is well below that difference (the
/// coarser run's error, to a few percent, for pairs of order 5 and 8). Only the first `compared`
/// values of each row (the time and the written columns) are compared: columns computed for a
/// view alone must not change the run written.
pub(crate) fn refine(
    goal: f64,
    method: Method,
    mut tol: Tolerances,
    compared: usize,
    integrate_at: impl Fn(Method) -> Result<Integration, SolveError>,
) -> Result<(Integration, Option<Accuracy>), SolveError> {
    let mut total = Stats::default();
    let mut add = |s: Stats| {
        total.steps += s.steps;
        total.rejected += s.rejected;
        total.rhs_evals += s.rhs_evals;
    };
    let first = integrate_at(method.with_tolerances(tol))?;
    add(first.stats);
    let mut coarse = first.rows;
    let mut runs = 1;
    loop {
        let finer = Tolerances { rtol: tol.rtol / REFINEMENT, atol: tol.atol / REFINEMENT };
        if finer.rtol < SMALLEST_RTOL {
            return Err(SolveError::AccuracyNotReached { goal, rtol: tol.rtol });
        }
        let fine = integrate_at(method.with_tolerances(finer))?;
        add(fine.stats);
        runs += 1;
        let estimate = largest_difference(&coarse, &fine.rows, compared);
        if estimate <= goal {
            let accuracy = Accuracy { goal, estimate, rtol: finer.rtol, atol: finer.atol, runs };
            return Ok((Integration { stats: total, ..fine }, Some(accuracy)));
        }
        coarse = fine.rows;
        tol = finer;
    }
}

/// The largest difference of two runs' rows (their values 1..`compared`) relative to
/// max(1, |value|).
pub(crate) fn largest_difference(a: &[Vec<f64>], b: &[Vec<f64>], compared: usize) -> f64 {
    let mut worst: f64 = 0.0;
    for (ra, rb) in a.iter().zip(b) {
        for (x, y) in ra[1..compared].iter().zip(&rb[1..compared]) {
            worst = worst.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    worst
}
