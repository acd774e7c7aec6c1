//! Steppers. The [`Stepper`] trait every stepper implements, and the explicit Runge-Kutta one.
//! In: a system, `(t0, y0)`, a [`Method`] and optionally a stop time; out: one accepted step
//! per [`Stepper::step`] (its state, why it stopped there), values inside the last step from
//! [`Stepper::interpolate`], and the cost so far in [`Stats`].
//!
//! Adaptive methods choose each step by PI error control; fixed-step methods take the given
//! step, shortened evenly to land on the stop time. The step that reaches the stop time ends on
//! it exactly: the value there is a step's own value at that time, not at a sum of step sizes.

use std::cell::{Cell, RefCell};

use super::control::{accepted_step, bound_first_step, initial_step, PiControl};
use super::dense::{DenseCache, StepData};
use super::stages::{StageBuffers, Stats};
use super::{Method, OdeError, System, Tolerances};

/// Most accepted steps a stepper takes unless told otherwise ([`Stepper::set_max_steps`]).
pub const DEFAULT_MAX_STEPS: usize = 10_000_000;

/// Why a stepper's step ([`Stepper::step`]) or a whole run ([`super::Integration`]) returned.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum StopReason {
    /// An accepted step short of the stop time (or without one).
    StepTaken,
    /// At the stop time: the step just taken ended on it, or the stepper already was there; for
    /// a run, it reached its last output time.
    StopTimeReached,
    /// A run's watcher ended it at `time`, inside the last step: an event.
    Event {
        /// Where the run ended.
        time: f64,
    },
    /// A run's output callback ended it (`ControlFlow::Break`) at the output time `time`.
    OutputBreak {
        /// The output time it broke at.
        time: f64,
    },
}

/// A stepper: one accepted step at a time, values inside the last step, the cost so far. What
/// every stepper does (the Runge-Kutta [`ErkStepper`], the Taylor [`super::TaylorStepper`]) and
/// all a run ([`super::Integration`]) asks of one.
pub trait Stepper {
    /// The current time.
    fn t(&self) -> f64;
    /// The current state.
    fn y(&self) -> &[f64];
    /// Where the last accepted step began (`t0` before the first).
    fn step_start(&self) -> f64;
    /// Takes one accepted step, or none when the stepper is at the stop time already.
    fn step(&mut self) -> Result<StopReason, OdeError>;
    /// The state at `t` inside the last accepted step into `out` (at its end, the step's own
    /// value). An error outside the step or for `out` of the wrong length.
    fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), OdeError>;
    /// Steps never pass `t_stop`; the one that reaches it ends on it exactly.
    fn set_stop_time(&mut self, t_stop: f64);
    /// At most `max` accepted steps in all: [`Stepper::step`] fails with
    /// [`OdeError::TooManySteps`] before taking one more.
    fn set_max_steps(&mut self, max: usize);
    /// The cost so far.
    fn stats(&self) -> Stats;
}

/// Fixed steps still to take toward the stop time: the rest of the way in `left` equal steps.
#[derive(Clone, Copy, Debug, Default)]
struct FixedPlan {
    h: f64,
    left: usize,
}

/// An explicit Runge-Kutta stepper for `sys`. `N` is the dimension when fixed at compile time
/// (then the built-in tableaux take fully unrolled steps; see [`ErkStepper::new_sized`]), 0 for
/// any ([`ErkStepper::new`]).
pub struct ErkStepper<'a, S: System + ?Sized, const N: usize = 0> {
    work: StageBuffers<'a, S, N>,
    method: Method,
    t0: f64,
    t: f64,
    y: Vec<f64>,
    /// The last accepted step: where it began, the state there (kept only for a tableau with a
    /// continuous extension: nothing else reads it), its size.
    t_prev: f64,
    y_prev: Vec<f64>,
    h_prev: f64,
    /// The next step size to try (adaptive).
    h: f64,
    control: PiControl,
    stop: Option<f64>,
    horizon: Option<f64>,
    plan: FixedPlan,
    /// Most accepted steps; the next one after them is an error.
    max_steps: usize,
    /// The tableau has a continuous extension.
    dense_output: bool,
    dense: RefCell<DenseCache>,
    /// Right-hand-side evaluations of the interpolants' extra stages.
    dense_evals: Cell<usize>,
}

impl<'a, S: System + ?Sized> ErkStepper<'a, S> {
    /// A stepper at `(t0, y0)`; `f(t0, y0)` and, for an adaptive method, the starting step size
    /// are evaluated now. An error when `y0` is not finite or not of the system's dimension.
    pub fn new(sys: &'a S, t0: f64, y0: &[f64], method: Method) -> Result<Self, OdeError> {
        Self::new_sized(sys, t0, y0, method)
    }
}

impl<'a, S: System + ?Sized, const N: usize> ErkStepper<'a, S, N> {
    /// [`ErkStepper::new`] with the dimension `N` fixed at compile time (0: any); an error
    /// unless `N` is 0 or `sys.dim()`.
    pub fn new_sized(sys: &'a S, t0: f64, y0: &[f64], method: Method) -> Result<Self, OdeError> {
        let n = sys.dim();
        if N != 0 && N != n {
            return Err(OdeError::DimensionMismatch { expected: N, found: n });
        }
        if y0.len() != n {
            return Err(OdeError::DimensionMismatch { expected: n, found: y0.len() });
        }
        check_finite(t0, y0)?;
        let tab = method.tableau().ok_or(OdeError::NotRungeKutta)?;
        let mut work = StageBuffers::<S, N>::new(sys, tab);
        sys.rhs(t0, y0, &mut work.k[..n]);
        work.stats.rhs_evals += 1;
        let h = match method {
            Method::Adaptive(_, tol) => initial_step(&mut work, t0, y0, tol),
            Method::Fixed(_, step) => step,
            Method::Taylor(_) => return Err(OdeError::NotRungeKutta),
        };
        Ok(ErkStepper {
            work,
            method,
            t0,
            t: t0,
            y: y0.to_vec(),
            t_prev: t0,
            y_prev: y0.to_vec(),
            h_prev: 0.0,
            h,
            control: PiControl::new(tab.order, tab.control),
            stop: None,
            horizon: None,
            plan: FixedPlan::default(),
            max_steps: DEFAULT_MAX_STEPS,
            dense_output: tab.dense.is_some(),
            dense: RefCell::new(DenseCache::new(n, tab.dense.as_ref())),
            dense_evals: Cell::new(0),
        })
    }

    /// Where the whole integration ends: an adaptive method's first step is no longer than the
    /// way there (without a horizon, than the way to the stop time). No effect after that step.
    pub fn set_horizon(&mut self, t_end: f64) {
        self.horizon = Some(t_end);
    }

    /// An adaptive step toward the stop time (if any), of the size the control proposes or
    /// smaller.
    #[inline(always)]
    fn adaptive_step(&mut self, tol: Tolerances) -> Result<StopReason, OdeError> {
        if self.work.stats.steps == 0 {
            // The first step: Hairer's estimate, now bounded by the span to integrate.
            if let Some(end) = self.horizon.or(self.stop) {
                self.h = bound_first_step(self.h, end - self.t0);
            }
        }
        let target = self.stop.unwrap_or(f64::INFINITY);
        self.work.begin();
        let step = accepted_step(&mut self.work, self.t, &self.y, self.h, target, tol, &self.control)?;
        self.accept(step.t_new, step.h)?;
        let proposed = step.next_h(self.control.accepted(step.err));
        // A step shortened to land on the stop time does not shrink the next.
        self.h = if step.at_target { proposed.max(self.h) } else { proposed };
        Ok(if step.at_target { StopReason::StopTimeReached } else { StopReason::StepTaken })
    }

    /// A fixed step: of size `step` without a stop time; toward one, the rest of the way divided
    /// evenly into the fewest steps no longer than `step`. An error for a step too small to move
    /// the time.
    #[inline(always)]
    fn fixed_step(&mut self, step: f64) -> Result<StopReason, OdeError> {
        if self.plan.left == 0 {
            self.plan = match self.stop {
                Some(stop) => {
                    let count = ((stop - self.t) / step - 1e-9).ceil().max(1.0);
                    FixedPlan { h: (stop - self.t) / count, left: count as usize }
                }
                None => FixedPlan { h: step, left: 1 },
            };
        }
        let h = self.plan.h;
        if self.t + h <= self.t {
            return Err(OdeError::StepSizeUnderflow { time: self.t, step: h });
        }
        let lands = match self.stop {
            Some(stop) if self.plan.left == 1 => Some(stop),
            _ => None,
        };
        self.work.begin();
        self.work.step(self.t, &self.y, h);
        let t_new = lands.unwrap_or(self.t + h);
        self.work.complete(t_new);
        self.accept(t_new, h)?;
        self.plan.left -= 1;
        Ok(if lands.is_some() { StopReason::StopTimeReached } else { StopReason::StepTaken })
    }

    /// An error when the steps taken are already the most allowed.
    #[inline(always)]
    fn check_step_limit(&self) -> Result<(), OdeError> {
        if self.work.stats.steps >= self.max_steps {
            return Err(OdeError::TooManySteps { time: self.t, max: self.max_steps });
        }
        Ok(())
    }

    /// Makes the step of size `h` to `(t_new, work.ynew)` the current state, unless that state
    /// is not finite.
    #[inline(always)]
    fn accept(&mut self, t_new: f64, h: f64) -> Result<(), OdeError> {
        check_finite(t_new, &self.work.ynew)?;
        self.work.finish(t_new);
        if self.dense_output {
            std::mem::swap(&mut self.y_prev, &mut self.y);
        }
        std::mem::swap(&mut self.y, &mut self.work.ynew);
        (self.t_prev, self.t, self.h_prev) = (self.t, t_new, h);
        self.dense.get_mut().invalidate();
        Ok(())
    }
}

impl<S: System + ?Sized, const N: usize> Stepper for ErkStepper<'_, S, N> {
    fn set_stop_time(&mut self, t_stop: f64) {
        if self.stop.map(f64::to_bits) != Some(t_stop.to_bits()) {
            self.stop = Some(t_stop);
            self.plan = FixedPlan::default();
        }
    }

    fn set_max_steps(&mut self, max: usize) {
        self.max_steps = max;
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn y(&self) -> &[f64] {
        &self.y
    }

    fn step_start(&self) -> f64 {
        self.t_prev
    }

    /// The cost so far, the interpolants' extra stages included.
    fn stats(&self) -> Stats {
        let mut stats = self.work.stats;
        stats.rhs_evals += self.dense_evals.get();
        stats
    }

    /// Takes one accepted step, or none when the stepper is at the stop time already; first the
    /// system may project the state (then the last step can no longer be interpolated). After an
    /// error the state is the last accepted one, and only it can be interpolated (the failed
    /// attempt overwrote the stages).
    #[inline(always)]
    fn step(&mut self) -> Result<StopReason, OdeError> {
        if self.stop.is_some_and(|stop| self.t >= stop) {
            return Ok(StopReason::StopTimeReached);
        }
        self.check_step_limit()?;
        if self.work.sys.project(&mut self.y) {
            check_finite(self.t, &self.y)?;
            self.work.restart(self.t, &self.y);
            self.t_prev = self.t;
        }
        let result = match self.method {
            Method::Adaptive(_, tol) => self.adaptive_step(tol),
            Method::Fixed(_, step) => self.fixed_step(step),
            Method::Taylor(_) => Err(OdeError::NotRungeKutta),
        };
        if result.is_err() {
            self.t_prev = self.t;
        }
        result
    }

    /// The state at `t` in the last accepted step into `out`: at its end the step's own value;
    /// before that (its start included) from the tableau's continuous extension, exact at the
    /// start. An error outside the step, before its end without an extension, or for `out` of
    /// the wrong length.
    #[inline]
    fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), OdeError> {
        let n = self.work.n();
        if out.len() != n {
            return Err(OdeError::DimensionMismatch { expected: n, found: out.len() });
        }
        if t == self.t {
            out.copy_from_slice(&self.y);
            return Ok(());
        }
        if !(self.t_prev <= t && t < self.t) {
            return Err(OdeError::OutsideStep { t, start: self.t_prev, end: self.t });
        }
        let tab = self.work.tab;
        let dense = tab.dense.as_ref().ok_or(OdeError::NoDenseOutput { method: tab.name })?;
        if t == self.t_prev {
            out.copy_from_slice(&self.y_prev);
            return Ok(());
        }
        let step = StepData::<N> {
            t: self.t_prev,
            h: self.h_prev,
            y0: &self.y_prev,
            y1: &self.y,
            k: &self.work.k,
            s: tab.c.len(),
            f1: self.work.end_slope(),
            n_dyn: n,
        };
        let theta = (t - self.t_prev) / self.h_prev;
        let evals = self.dense.borrow_mut().interpolate(self.work.sys, dense, &step, theta, out);
        self.dense_evals.set(self.dense_evals.get() + evals);
        Ok(())
    }
}

/// An error at the first state of `y` that is not finite.
pub(super) fn check_finite(t: f64, y: &[f64]) -> Result<(), OdeError> {
    match y.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(OdeError::NonFinite { time: t, index, value: y[index] }),
        None => Ok(()),
    }
}
