//! The one loop from a stepper to output times. In: a [`Stepper`] (a Runge-Kutta or a Taylor
//! one), increasing output times, a watcher of each accepted step and an output callback; out:
//! the callback at each time, and how the run ended ([`Outcome`]).

use std::ops::ControlFlow;

use super::stages::Stats;
use super::stepper::{Stepper, StopReason};
use super::OdeError;

/// How a run ended: its cost and why it stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// The cost.
    pub stats: Stats,
    /// Why it stopped: [`StopReason::StopTimeReached`] at the last output time,
    /// [`StopReason::Event`] where the watcher ended it, [`StopReason::OutputBreak`] where the
    /// output callback did.
    pub reason: StopReason,
}

/// Steps `stepper` through the output `times`, calling `out(t, y)` at each (a break ends the
/// run, no error) and `watch(stepper)` after each accepted step; when that breaks with `t_stop`
/// inside the step, the outputs before `t_stop` are given and the run ends there, an event.
/// `interpolates`: the stepper steps freely to the last time (its stop time is set already) and
/// outputs inside a step come from its dense output; otherwise each output time is a stop time.
/// A stop signal ends the run after the step it arrived in, with [`OdeError::Interrupted`].
pub(super) fn drive<St: Stepper>(
    stepper: &mut St,
    times: &[f64],
    interpolates: bool,
    mut watch: impl FnMut(&dyn Stepper) -> ControlFlow<f64>,
    mut out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Outcome, OdeError> {
    let mut inside = vec![0.0; stepper.y().len()];
    let mut next = 0;
    let ended = |s: &St, reason| Ok(Outcome { stats: s.stats(), reason });
    loop {
        // The outputs the stepper has passed.
        while let Some(&target) = times.get(next) {
            if target > stepper.t() {
                break;
            }
            let y = if target == stepper.t() {
                stepper.y()
            } else {
                stepper.interpolate(target, &mut inside)?;
                &inside
            };
            next += 1;
            if out(target, y).is_break() {
                return ended(stepper, StopReason::OutputBreak { time: target });
            }
        }
        if next == times.len() {
            return ended(stepper, StopReason::StopTimeReached);
        }
        if !interpolates {
            stepper.set_stop_time(times[next]);
        }
        stepper.step()?;
        if let Some(by) = super::interrupt::requested() {
            return Err(OdeError::Interrupted { time: stepper.t(), by });
        }
        if let ControlFlow::Break(t_stop) = watch(stepper) {
            while let Some(&target) = times.get(next).filter(|t| **t < t_stop) {
                stepper.interpolate(target, &mut inside)?;
                next += 1;
                if out(target, &inside).is_break() {
                    break;
                }
            }
            return ended(stepper, StopReason::Event { time: t_stop });
        }
    }
}
