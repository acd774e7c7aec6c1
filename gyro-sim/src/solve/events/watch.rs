//! Events watched during an integration: in come the problem's events, the bound model and, after
//! each accepted step, the stepper; out go the crossings found in the step (each with its
//! trajectory row, built by the caller's row function) and, for one that stops the run, the
//! time to stop at.

use std::ops::ControlFlow;

use crate::ode::normalise;
use crate::ode::{Stepper, System};
use crate::problem::{EventLog, EventRecord, Problem, SolveError};
use crate::solve::bound::{BoundModel, Reduced};

use super::detect::Detector;
use super::eval::EventFns;
use super::limits::Limits;

/// The row of a trajectory at a time and full state.
pub type RowFn<'r> = dyn Fn(f64, &[f64]) -> Result<Vec<f64>, SolveError> + 'r;

/// What is watched and what was found.
pub struct Watch<'a, B: BoundModel> {
    problem: &'a Problem,
    sys: &'a Reduced<'a, B>,
    fns: EventFns<'a, B>,
    detector: Option<Detector>,
    limits: Limits,
    reduced: Vec<f64>,
    full: Vec<f64>,
    values: Vec<f64>,
    /// The events so far.
    pub log: EventLog,
    /// The full state at the stop, if the run stopped.
    pub stop_state: Option<Vec<f64>>,
    /// The row at the stop.
    pub stop_row: Option<Vec<f64>>,
    /// A failure met while building a row.
    pub error: Option<SolveError>,
}

impl<'a, B: BoundModel> Watch<'a, B> {
    /// The events of `problem` over `sys` (whose full model is `model`).
    pub fn new(problem: &'a Problem, sys: &'a Reduced<'a, B>, model: &'a B) -> Self {
        let n = model.dim();
        Watch {
            problem,
            sys,
            fns: EventFns::new(model, &problem.events, &problem.params),
            detector: None,
            limits: Limits::new(problem.events.len()),
            reduced: vec![0.0; sys.dim()],
            full: vec![0.0; n],
            values: vec![0.0; problem.events.len()],
            log: EventLog {
                names: problem.events.iter().map(|e| e.name.clone()).collect(),
                ..EventLog::default()
            },
            stop_state: None,
            stop_row: None,
            error: None,
        }
    }

    /// After an accepted step of `stepper`: the crossings in it recorded (rows from `row`);
    /// a break at the time to stop at when one ends the run (or a row failed).
    pub fn observe(&mut self, stepper: &dyn Stepper, row: &RowFn<'_>) -> ControlFlow<f64> {
        let (t_prev, t) = (stepper.step_start(), stepper.t());
        let Watch { problem, sys, fns, reduced, full, values, .. } = self;
        let mut at = |s: f64, full: &mut [f64]| {
            if stepper.interpolate(s, reduced).is_err() {
                full.fill(f64::NAN);
                return;
            }
            sys.expand(reduced, full);
            normalise(&problem.unit_norms, full);
        };
        if self.detector.is_none() {
            at(t_prev, full);
            fns.values(t_prev, full, values);
            let rules = problem.events.iter().map(|e| e.rule).collect();
            self.detector = Some(Detector::new(rules, t_prev, values));
        }
        let Some(detector) = self.detector.as_mut() else { return ControlFlow::Continue(()) };
        let found = detector.step(t_prev, t, |i, s| {
            at(s, full);
            fns.value(i, s, full)
        });
        for &(i, at, width) in &found.unsettled {
            self.limits.unsettled(i, at, width);
        }
        for c in &found.crossings {
            self.limits.crossing(c.event, c.t, &problem.times);
        }
        self.limits.write_into(&mut self.log);
        for c in found.crossings {
            at(c.t, full);
            let r = match row(c.t, full) {
                Ok(r) => r,
                Err(e) => {
                    self.error = Some(e);
                    return ControlFlow::Break(c.t);
                }
            };
            let name = problem.events[c.event].name.clone();
            self.log.records.push(EventRecord {
                event: c.event,
                name: name.clone(),
                rising: c.rising,
                row: r.clone(),
            });
            if c.stop {
                self.log.stopped = Some((name, c.t));
                self.stop_state = Some(full.clone());
                self.stop_row = Some(r);
                return ControlFlow::Break(c.t);
            }
        }
        ControlFlow::Continue(())
    }
}
