//! Integration through output times. In: a system, `(t0, y0)`, increasing output times, a
//! [`Method`] and a callback; out: the callback called with the state at each output time (until
//! it breaks), and the cost. One loop over an [`ErkStepper`]: adaptive methods with a continuous
//! extension step freely to the last time and interpolate the outputs inside each step; the
//! others stop at every output time. Either way the value at the last time is a step's own.

use std::ops::ControlFlow;

use super::drive::drive;
use super::stages::Stats;
use super::stepper::{ErkStepper, DEFAULT_MAX_STEPS};
use super::{Method, OdeError, System};

/// Integrates from `(t0, y0)` through the increasing output `times` (none before `t0`), calling
/// `out(t, y)` at each; `ControlFlow::Break` stops early, which is no error. The cost so far.
/// At most `DEFAULT_MAX_STEPS` steps.
pub fn integrate<S: System + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    method: Method,
    out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Stats, OdeError> {
    integrate_limited(sys, t0, y0, times, method, DEFAULT_MAX_STEPS, out)
}

/// [`integrate`] with at most `max_steps` accepted steps (then [`OdeError::TooManySteps`]).
pub fn integrate_limited<S: System + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    method: Method,
    max_steps: usize,
    out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Stats, OdeError> {
    if let Method::Taylor(_) = method {
        let watch = |_: &dyn super::Stepping| None;
        return super::integrate_watched(sys, t0, y0, times, method, max_steps, watch, out).map(|w| w.stats);
    }
    let limits = Limits { method, max_steps };
    match sys.dim() {
        1 => integrate_n::<S, 1>(sys, t0, y0, times, limits, out),
        2 => integrate_n::<S, 2>(sys, t0, y0, times, limits, out),
        3 => integrate_n::<S, 3>(sys, t0, y0, times, limits, out),
        4 => integrate_n::<S, 4>(sys, t0, y0, times, limits, out),
        5 => integrate_n::<S, 5>(sys, t0, y0, times, limits, out),
        6 => integrate_n::<S, 6>(sys, t0, y0, times, limits, out),
        7 => integrate_n::<S, 7>(sys, t0, y0, times, limits, out),
        8 => integrate_n::<S, 8>(sys, t0, y0, times, limits, out),
        _ => integrate_n::<S, 0>(sys, t0, y0, times, limits, out),
    }
}

/// The method and the step limit.
#[derive(Clone, Copy)]
struct Limits {
    method: Method,
    max_steps: usize,
}

/// [`integrate_limited`] with the dimension `N` fixed at compile time (0: any).
fn integrate_n<S: System + ?Sized, const N: usize>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    limits: Limits,
    out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Stats, OdeError> {
    let method = limits.method;
    let mut stepper = ErkStepper::<S, N>::new_sized(sys, t0, y0, method)?;
    stepper.set_max_steps(limits.max_steps);
    let Some(&t_end) = times.last() else { return Ok(stepper.stats()) };
    stepper.set_horizon(t_end);
    // Fixed steps land on every output time, so the step between two is at most the one asked.
    let interpolates = matches!(method, Method::Adaptive(tab, _) if tab.dense.is_some());
    if interpolates {
        stepper.set_stop_time(t_end);
    }
    Ok(drive(&mut stepper, times, interpolates, |_| None, out)?.stats)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::test_problems::Pendulums;

    #[test]
    fn unrolled_and_general_steps_give_identical_numbers() {
        use crate::ode::tableau::{DOP853, DOPRI5, RK4};
        use crate::ode::Tolerances;
        let y0 = [1.0, -0.5, 0.0, 2.0];
        let times: Vec<f64> = (0..=40).map(|i| 0.25 * i as f64).collect();
        let tol = Tolerances { rtol: 1e-8, atol: 1e-10 };
        for method in
            [Method::Adaptive(&DOP853, tol), Method::Adaptive(&DOPRI5, tol), Method::Fixed(&RK4, 0.01)]
        {
            let run = |fixed: bool| {
                let mut rows: Vec<Vec<f64>> = Vec::new();
                let record = |_: f64, y: &[f64]| {
                    rows.push(y.to_vec());
                    ControlFlow::Continue(())
                };
                let limits = Limits { method, max_steps: DEFAULT_MAX_STEPS };
                let stats = if fixed {
                    integrate_n::<_, 4>(&Pendulums, 0.0, &y0, &times, limits, record)
                } else {
                    integrate_n::<_, 0>(&Pendulums, 0.0, &y0, &times, limits, record)
                };
                (stats.unwrap(), rows)
            };
            let (unrolled, general) = (run(true), run(false));
            assert_eq!(unrolled.0, general.0);
            assert!(unrolled
                .1
                .iter()
                .flatten()
                .zip(general.1.iter().flatten())
                .all(|(a, b)| a.to_bits() == b.to_bits()));
            assert!(unrolled.0.steps > 10);
        }
    }
}
