//! Where a failed integration went wrong: in come the system, its last good output `(t0, y0)` and
//! the method; the same integration is run again from there, watching every evaluation of the
//! rates; out goes the first state at which they are not finite, else the state of the last
//! step taken (where the step size collapsed). Run only after a failure, so a run that succeeds
//! pays nothing.

use std::cell::RefCell;
use std::ops::ControlFlow;

use crate::ode::{Integration, Method, Stepper, System, TaylorWork};

/// A system that remembers the first finite state whose rates are not.
struct Watched<'a, S: System + ?Sized> {
    inner: &'a S,
    first_bad: RefCell<Option<(f64, Vec<f64>)>>,
}

impl<S: System + ?Sized> Watched<'_, S> {
    fn check(&self, t: f64, y: &[f64], values: &[f64]) {
        let bad = values.iter().any(|v| !v.is_finite()) && y.iter().all(|v| v.is_finite());
        if bad && self.first_bad.borrow().is_none() {
            *self.first_bad.borrow_mut() = Some((t, y.to_vec()));
        }
    }
}

impl<S: System + ?Sized> System for Watched<'_, S> {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.inner.rhs(t, y, dy);
        self.check(t, y, dy);
    }
    fn project(&self, y: &mut [f64]) -> bool {
        self.inner.project(y)
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        let has = self.inner.taylor(t, y, order, out, work);
        if has {
            self.check(t, y, out);
        }
        has
    }
    fn taylor_straight_line(&self) -> &[usize] {
        self.inner.taylor_straight_line()
    }
}

/// Integrates `sys` again from `(t0, y0)` towards `t_end` with `method`; the time and state where
/// its rates are first not finite, else the last step's end (None when no step was taken).
pub(crate) fn probe<S: System + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    t_end: f64,
    method: Method,
    max_steps: usize,
) -> Option<(f64, Vec<f64>)> {
    let watched = Watched { inner: sys, first_bad: RefCell::new(None) };
    let integration = Integration::new(&watched, t0, y0, method).max_steps(max_steps);
    let ignore = |_: f64, _: &[f64]| ControlFlow::Continue(());
    if method.tableau().is_some_and(|t| t.dense.is_none()) {
        // Without a continuous extension steps cannot be watched; the rates still are.
        let _ = integration.run(&[t_end], ignore);
        return watched.first_bad.into_inner();
    }
    let mut last: Option<(f64, Vec<f64>)> = None;
    let watch = |s: &dyn Stepper| {
        if s.y().iter().all(|v| v.is_finite()) {
            last = Some((s.t(), s.y().to_vec()));
        }
        ControlFlow::Continue(())
    };
    // The run fails again (that is why it is probed); what it met on the way is the answer.
    let _ = integration.watch(watch).run(&[t_end], ignore);
    watched.first_bad.into_inner().or(last)
}
