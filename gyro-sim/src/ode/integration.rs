//! One integration through output times. In: a system, a start `(t0, y0)`, a [`Method`], a step
//! limit and, for events, a watcher of each accepted step; out: a callback with the state at
//! each output time (until it breaks), and how the run ended ([`Outcome`]: the cost and a
//! [`StopReason`]). Runge-Kutta methods step with an [`ErkStepper`] (of the system's dimension
//! fixed at compile time for dimensions 1 to 8 when unwatched), the Taylor method with a
//! [`TaylorStepper`]; both go through the one loop of `drive`. Adaptive methods with a
//! continuous extension, and the Taylor method, step freely to the last time and interpolate the
//! outputs inside each step; the others stop at every output time. Either way the value at the
//! last time is a step's own.

use std::ops::ControlFlow;

use super::drive::{drive, Outcome};
use super::stepper::{ErkStepper, Stepper, StopReason, DEFAULT_MAX_STEPS};
use super::taylor::TaylorStepper;
use super::{Method, OdeError, System, Tolerances};

/// An integration to run: a system, its start and a method ([`Integration::new`]), optionally a
/// step limit ([`Integration::max_steps`]) and a watcher of each step
/// ([`Integration::watch`]), run through output times by `run`.
///
/// # Example
///
/// ```
/// use std::ops::ControlFlow;
/// use gyro_sim::test_problems::{ClosedForm, Oscillator};
/// use gyro_sim::{tableau, Integration, Method, StopReason, Tolerances};
///
/// let method = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: 1e-9, atol: 1e-9 });
/// let times = [0.5, 1.0, 1.5, 2.0];
/// let mut rows = Vec::new();
/// let run = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], method)
///     .max_steps(1000)
///     .watch(|s| if s.t() > 1.2 { ControlFlow::Break(1.2) } else { ControlFlow::Continue(()) })
///     .run(&times, |t, y| {
///         rows.push((t, y[0]));
///         ControlFlow::Continue(())
///     })
///     .unwrap();
/// assert_eq!(run.reason, StopReason::Event { time: 1.2 });
/// assert_eq!(rows.len(), 2);
/// assert!((rows[1].1 - Oscillator.solution(0.0, &[0.0, 1.0], 1.0)[0]).abs() < 1e-8);
/// ```
pub struct Integration<'a, S: System + ?Sized, W = Unwatched> {
    start: Start<'a, S>,
    watch: W,
}

/// The watcher of an integration without one (no events).
#[derive(Clone, Copy, Debug, Default)]
pub struct Unwatched;

impl<'a, S: System + ?Sized> Integration<'a, S> {
    /// An integration of `sys` from `(t0, y0)` by `method`, of at most `DEFAULT_MAX_STEPS` (10^7)
    /// accepted steps, unwatched.
    pub fn new(sys: &'a S, t0: f64, y0: &'a [f64], method: Method) -> Self {
        Integration { start: Start { sys, t0, y0, method, max_steps: DEFAULT_MAX_STEPS }, watch: Unwatched }
    }

    /// The integration with `watch` called after every accepted step with the stepper (to read
    /// the step or interpolate inside it); `ControlFlow::Break(t)` ends the run at `t` inside
    /// that step: the outputs before `t` are given and the outcome is [`StopReason::Event`]. The
    /// steps are those of the unwatched run: the watcher only reads the dense output, which a
    /// Runge-Kutta method must have ([`OdeError::NoDenseOutput`]).
    pub fn watch<W>(self, watch: W) -> Integration<'a, S, W>
    where
        W: FnMut(&dyn Stepper) -> ControlFlow<f64>,
    {
        Integration { start: self.start, watch }
    }

    /// Integrates through the increasing output `times` (none before `t0`), calling `out(t, y)`
    /// at each; `ControlFlow::Break` ends the run there, which is no error
    /// ([`StopReason::OutputBreak`]). A Runge-Kutta method's steps are unrolled for the
    /// system's [`System::FIXED_DIM`] or [`System::REDUCED_DIM`] (1 to 8) when its dimension
    /// is that one, or for any dimension 1 to 8 when [`System::UNROLL_ANY_DIM`].
    pub fn run(
        self,
        times: &[f64],
        out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
    ) -> Result<Outcome, OdeError> {
        let start = self.start;
        if let Method::Taylor(tol) = start.method {
            return start.run_taylor(tol, times, unwatched, out);
        }
        // Matched on a constant after monomorphisation: only the arm taken is compiled for `S`.
        macro_rules! unrolled_for {
            ($n:expr) => {
                match $n {
                    1 => start.run_erk::<1>(times, unwatched, out),
                    2 => start.run_erk::<2>(times, unwatched, out),
                    3 => start.run_erk::<3>(times, unwatched, out),
                    4 => start.run_erk::<4>(times, unwatched, out),
                    5 => start.run_erk::<5>(times, unwatched, out),
                    6 => start.run_erk::<6>(times, unwatched, out),
                    7 => start.run_erk::<7>(times, unwatched, out),
                    8 => start.run_erk::<8>(times, unwatched, out),
                    _ => start.run_erk::<0>(times, unwatched, out),
                }
            };
        }
        let dim = start.sys.dim();
        if dim == S::FIXED_DIM {
            unrolled_for!(S::FIXED_DIM)
        } else if dim == S::REDUCED_DIM {
            unrolled_for!(S::REDUCED_DIM)
        } else if S::UNROLL_ANY_DIM {
            unrolled_for!(dim)
        } else {
            start.run_erk::<0>(times, unwatched, out)
        }
    }
}

impl<S: System + ?Sized, W> Integration<'_, S, W> {
    /// At most `max` accepted steps in all: one more is [`OdeError::TooManySteps`].
    pub fn max_steps(mut self, max: usize) -> Self {
        self.start.max_steps = max;
        self
    }
}

impl<S: System + ?Sized, W> Integration<'_, S, W>
where
    W: FnMut(&dyn Stepper) -> ControlFlow<f64>,
{
    /// The run, watched: through the output `times`, calling `out(t, y)` at each and the
    /// watcher after each accepted step, until the last time, an event or a break. A
    /// Runge-Kutta method steps with any dimension (the watcher sees the stepper as
    /// `dyn Stepper`, so one stepper type serves).
    pub fn run(
        self,
        times: &[f64],
        out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
    ) -> Result<Outcome, OdeError> {
        let start = self.start;
        if let Method::Taylor(tol) = start.method {
            return start.run_taylor(tol, times, self.watch, out);
        }
        if let Some(tab) = start.method.tableau().filter(|t| t.dense.is_none()) {
            return Err(OdeError::NoDenseOutput { method: tab.name });
        }
        start.run_erk::<0>(times, self.watch, out)
    }
}

/// The watcher of an unwatched run: never stops it.
fn unwatched(_: &dyn Stepper) -> ControlFlow<f64> {
    ControlFlow::Continue(())
}

/// What an integration starts from: the system, `(t0, y0)`, the method and the step limit.
struct Start<'a, S: System + ?Sized> {
    sys: &'a S,
    t0: f64,
    y0: &'a [f64],
    method: Method,
    max_steps: usize,
}

impl<S: System + ?Sized> Start<'_, S> {
    /// The run by a Runge-Kutta method, the dimension `N` fixed at compile time (0: any).
    fn run_erk<const N: usize>(
        self,
        times: &[f64],
        watch: impl FnMut(&dyn Stepper) -> ControlFlow<f64>,
        out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
    ) -> Result<Outcome, OdeError> {
        let mut stepper = ErkStepper::<S, N>::new_sized(self.sys, self.t0, self.y0, self.method)?;
        stepper.set_max_steps(self.max_steps);
        let Some(&t_end) = times.last() else { return Ok(nothing_to_do(&stepper)) };
        stepper.set_horizon(t_end);
        // Fixed steps land on every output time, so the step between two is at most the one asked.
        let interpolates = matches!(self.method, Method::Adaptive(tab, _) if tab.dense.is_some());
        if interpolates {
            stepper.set_stop_time(t_end);
        }
        drive(&mut stepper, times, interpolates, watch, out)
    }

    /// The run by the Taylor method at `tol`.
    fn run_taylor(
        self,
        tol: Tolerances,
        times: &[f64],
        watch: impl FnMut(&dyn Stepper) -> ControlFlow<f64>,
        out: impl FnMut(f64, &[f64]) -> ControlFlow<()>,
    ) -> Result<Outcome, OdeError> {
        let mut stepper = TaylorStepper::new(self.sys, self.t0, self.y0, tol)?;
        stepper.set_max_steps(self.max_steps);
        let Some(&t_end) = times.last() else { return Ok(nothing_to_do(&stepper)) };
        stepper.set_stop_time(t_end);
        drive(&mut stepper, times, true, watch, out)
    }
}

/// The outcome of a run without output times: no step taken.
fn nothing_to_do(stepper: &impl Stepper) -> Outcome {
    Outcome { stats: stepper.stats(), reason: StopReason::StopTimeReached }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::tableau::{DOP853, DOPRI5, RK4};
    use crate::ode::test_problems::{Oscillator, Pendulums};

    /// Every output of a run at `times`, as bits.
    fn bits(rows: &[Vec<f64>]) -> Vec<u64> {
        rows.iter().flatten().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn unrolled_and_general_steps_give_identical_numbers() {
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
                let start = Integration::new(&Pendulums, 0.0, &y0, method).start;
                let run = if fixed {
                    start.run_erk::<4>(&times, unwatched, record)
                } else {
                    start.run_erk::<0>(&times, unwatched, record)
                };
                (run.unwrap(), rows)
            };
            let (unrolled, general) = (run(true), run(false));
            assert_eq!(unrolled.0, general.0);
            assert_eq!(bits(&unrolled.1), bits(&general.1));
            assert!(unrolled.0.stats.steps > 10);
        }
    }

    #[test]
    fn watching_changes_neither_steps_nor_outputs_and_an_event_ends_the_run() {
        let tol = Tolerances { rtol: 1e-10, atol: 1e-10 };
        let method = Method::Adaptive(&DOP853, tol);
        let times: Vec<f64> = (0..=30).map(|i| 0.25 * i as f64).collect();
        let mut plain = Vec::new();
        let unwatched = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .run(&times, |_, y| {
                plain.push(y.to_vec());
                ControlFlow::Continue(())
            })
            .unwrap();
        assert_eq!(unwatched.reason, StopReason::StopTimeReached);
        let mut watched = Vec::new();
        let mut seen = 0;
        let run = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .watch(|_| {
                seen += 1;
                ControlFlow::Continue(())
            })
            .run(&times, |_, y| {
                watched.push(y.to_vec());
                ControlFlow::Continue(())
            })
            .unwrap();
        assert_eq!(run, unwatched);
        assert_eq!(bits(&watched), bits(&plain));
        assert_eq!(seen, unwatched.stats.steps);
        let mut rows = Vec::new();
        let run = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .watch(|s| if s.t() > 1.6 { ControlFlow::Break(1.6) } else { ControlFlow::Continue(()) })
            .run(&times, |t, _| {
                rows.push(t);
                ControlFlow::Continue(())
            })
            .unwrap();
        assert_eq!(run.reason, StopReason::Event { time: 1.6 });
        assert_eq!(rows.last(), Some(&1.5));
    }

    #[test]
    fn a_break_in_the_output_ends_the_run_there() {
        let method = Method::Fixed(&RK4, 0.1);
        let times = [0.5, 1.0, 1.5];
        let run = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .run(&times, |t, _| if t < 1.0 { ControlFlow::Continue(()) } else { ControlFlow::Break(()) })
            .unwrap();
        assert_eq!((run.reason, run.stats.steps), (StopReason::OutputBreak { time: 1.0 }, 10));
        let run = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .run(&[], |_, _| ControlFlow::Continue(()))
            .unwrap();
        assert_eq!((run.reason, run.stats.steps), (StopReason::StopTimeReached, 0));
    }

    #[test]
    fn a_watched_method_without_dense_output_is_refused() {
        let method = Method::Fixed(&RK4, 0.1);
        let e = Integration::new(&Oscillator, 0.0, &[1.0, 0.0], method)
            .max_steps(10)
            .watch(|_| ControlFlow::Continue(()))
            .run(&[0.0, 1.0], |_, _| ControlFlow::Continue(()));
        assert_eq!(e.unwrap_err(), OdeError::NoDenseOutput { method: "rk4" });
    }
}
