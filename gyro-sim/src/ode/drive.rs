//! The one loop from a stepper to output times. In: a [`Stepping`] (a Runge-Kutta or a Taylor
//! stepper), increasing output times, a watcher of each accepted step and an output callback;
//! out: the callback at each time, and where the watcher stopped the run, if it did.

use std::ops::ControlFlow;

use super::stages::Stats;
use super::stepper::{ErkStepper, StopReason};
use super::taylor::TaylorStepper;
use super::{OdeError, System};

/// What the output loop asks of a stepper.
pub trait Stepping {
    /// The current time.
    fn t(&self) -> f64;
    /// The current state.
    fn y(&self) -> &[f64];
    /// Where the last accepted step began.
    fn step_start(&self) -> f64;
    /// Takes one accepted step, or none at the stop time.
    fn step(&mut self) -> Result<StopReason, OdeError>;
    /// The state at `t` inside the last accepted step, into `out`.
    fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), OdeError>;
    /// Steps never pass `t_stop`.
    fn set_stop_time(&mut self, t_stop: f64);
    /// The cost so far.
    fn stats(&self) -> Stats;
}

/// How a driven integration ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Watched {
    /// The cost.
    pub stats: Stats,
    /// The time the watcher stopped the run at (`None`: it ran to the last output time, or the
    /// output callback broke).
    pub stopped_at: Option<f64>,
}

/// Steps `stepper` through the output `times`, calling `out(t, y)` at each (a break ends the
/// run, no error) and `watch(stepper)` after each accepted step; when that returns
/// `Some(t_stop)` inside the step, the outputs before `t_stop` are given and the run ends there.
/// `interpolates`: the stepper steps freely to the last time (its stop time is set already) and
/// outputs inside a step come from its dense output; otherwise each output time is a stop time.
/// A stop signal ends the run after the step it arrived in, with [`OdeError::Interrupted`].
pub fn drive<St: Stepping>(
    stepper: &mut St,
    times: &[f64],
    interpolates: bool,
    mut watch: impl FnMut(&St) -> Option<f64>,
    mut out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
) -> Result<Watched, OdeError> {
    let mut inside = vec![0.0; stepper.y().len()];
    let mut next = 0;
    let ran = |s: &St, stopped_at| Ok(Watched { stats: s.stats(), stopped_at });
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
                return ran(stepper, None);
            }
        }
        let Some(&target) = times.get(next) else { return ran(stepper, None) };
        if !interpolates {
            stepper.set_stop_time(target);
        }
        stepper.step()?;
        if let Some(by) = super::interrupt::requested() {
            return Err(OdeError::Interrupted { time: stepper.t(), by });
        }
        if let Some(t_stop) = watch(stepper) {
            while let Some(&target) = times.get(next).filter(|t| **t < t_stop) {
                stepper.interpolate(target, &mut inside)?;
                next += 1;
                if out(target, &inside).is_break() {
                    break;
                }
            }
            return ran(stepper, Some(t_stop));
        }
    }
}

/// Forwards [`Stepping`] to a stepper's own methods of the same names.
macro_rules! stepping_by_inherent_methods {
    ($ty:ty, $($generics:tt)*) => {
        impl<$($generics)*> Stepping for $ty {
            fn t(&self) -> f64 {
                <$ty>::t(self)
            }
            fn y(&self) -> &[f64] {
                <$ty>::y(self)
            }
            fn step_start(&self) -> f64 {
                <$ty>::step_start(self)
            }
            fn step(&mut self) -> Result<StopReason, OdeError> {
                <$ty>::step(self)
            }
            fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), OdeError> {
                <$ty>::interpolate(self, t, out)
            }
            fn set_stop_time(&mut self, t_stop: f64) {
                <$ty>::set_stop_time(self, t_stop)
            }
            fn stats(&self) -> Stats {
                <$ty>::stats(self)
            }
        }
    };
}

stepping_by_inherent_methods!(ErkStepper<'_, S, N>, S: System + ?Sized, const N: usize);
stepping_by_inherent_methods!(TaylorStepper<'_, S>, S: System + ?Sized);
