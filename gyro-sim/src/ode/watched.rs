//! Integration through output times with a watcher of each step (events). In: what
//! [`super::integrate_limited`] takes, and a watcher called after every accepted step with the
//! stepper (so it can interpolate inside the step); out: the same outputs and cost, ending at
//! the time the watcher asks to stop at, if it does. The steps are those `integrate_limited`
//! takes: the watcher only reads the dense output.

use std::ops::ControlFlow;

use super::drive::{drive, Stepping, Watched};
use super::stepper::ErkStepper;
use super::taylor::TaylorStepper;
use super::{Method, OdeError, System};

/// [`super::integrate_limited`], calling `watch(stepper)` after each accepted step; when it
/// returns `Some(t_stop)` (inside that step), the outputs before `t_stop` are given and the run
/// ends there. Needs a method with a continuous extension ([`OdeError::NoDenseOutput`]).
#[allow(clippy::too_many_arguments)]
pub fn integrate_watched<S: System + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    method: Method,
    max_steps: usize,
    mut watch: impl FnMut(&dyn Stepping) -> Option<f64>,
    out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Watched, OdeError> {
    if let Method::Taylor(tol) = method {
        let mut stepper = TaylorStepper::new(sys, t0, y0, tol)?;
        stepper.set_max_steps(max_steps);
        let Some(&t_end) = times.last() else {
            return Ok(Watched { stats: stepper.stats(), stopped_at: None });
        };
        stepper.set_stop_time(t_end);
        return drive(&mut stepper, times, true, |s| watch(s), out);
    }
    if let Some(tab) = method.tableau().filter(|t| t.dense.is_none()) {
        return Err(OdeError::NoDenseOutput { method: tab.name });
    }
    let mut stepper = ErkStepper::new(sys, t0, y0, method)?;
    stepper.set_max_steps(max_steps);
    let Some(&t_end) = times.last() else { return Ok(Watched { stats: stepper.stats(), stopped_at: None }) };
    stepper.set_horizon(t_end);
    // As in `integrate`: adaptive methods step freely to the end, the others land on each time.
    let interpolates = matches!(method, Method::Adaptive(..));
    if interpolates {
        stepper.set_stop_time(t_end);
    }
    drive(&mut stepper, times, interpolates, |s| watch(s), out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::tableau::DOP853;
    use crate::ode::test_problems::Oscillator as Spring;
    use crate::ode::{integrate, Tolerances};

    #[test]
    fn watching_changes_neither_steps_nor_outputs_and_a_stop_ends_the_run() {
        let tol = Tolerances { rtol: 1e-10, atol: 1e-10 };
        let method = Method::Adaptive(&DOP853, tol);
        let times: Vec<f64> = (0..=30).map(|i| 0.25 * i as f64).collect();
        let mut plain = Vec::new();
        let stats = integrate(&Spring, 0.0, &[1.0, 0.0], &times, method, |t, y| {
            plain.push((t, y[0].to_bits()));
            ControlFlow::Continue(())
        })
        .unwrap();
        let mut watched = Vec::new();
        let mut seen = 0;
        let run = integrate_watched(
            &Spring,
            0.0,
            &[1.0, 0.0],
            &times,
            method,
            usize::MAX,
            |_| {
                seen += 1;
                None
            },
            |t, y| {
                watched.push((t, y[0].to_bits()));
                ControlFlow::Continue(())
            },
        )
        .unwrap();
        assert_eq!((run.stats.steps, run.stopped_at), (stats.steps, None));
        assert_eq!(watched, plain);
        assert_eq!(seen, stats.steps);
        let mut rows = Vec::new();
        let run = integrate_watched(
            &Spring,
            0.0,
            &[1.0, 0.0],
            &times,
            method,
            usize::MAX,
            |s| (s.t() > 1.6).then_some(1.6),
            |t, _| {
                rows.push(t);
                ControlFlow::Continue(())
            },
        )
        .unwrap();
        assert_eq!(run.stopped_at, Some(1.6));
        assert_eq!(rows.last(), Some(&1.5));
    }

    #[test]
    fn a_method_without_dense_output_is_refused() {
        let method = Method::Fixed(&crate::ode::tableau::RK4, 0.1);
        let e = integrate_watched(
            &Spring,
            0.0,
            &[1.0, 0.0],
            &[0.0, 1.0],
            method,
            10,
            |_| None,
            |_, _| ControlFlow::Continue(()),
        );
        assert_eq!(e.unwrap_err(), OdeError::NoDenseOutput { method: "rk4" });
    }
}
