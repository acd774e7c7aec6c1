//! Crossings found step by step: in come each event's function on the dense output of every
//! accepted step; out go the crossings in time order, each located by [`super::root::illinois`]
//! between neighbouring points of [`super::isolate`] (which holds at most one sign change
//! between neighbours), filtered by direction and counted, the list cut at the first crossing
//! that ends the run, and the first time each event's sign changes outran the isolation.
//!
//! A crossing is a change of sign between the last nonzero value and the new one. A zero at the
//! start time is not a crossing, and neither is a start within round-off of zero (a value
//! within [`START_ROUND_OFF`] of the largest the first step's samples show, such as a rate at a
//! turning point): its sign is the one the function takes after it.

use super::isolate::{isolate, Isolation, Sample};
use super::root::illinois;
use crate::problem::Rule;
use crate::scene::Direction;

/// A start value this small relative to the largest value in the first step is the start's own
/// zero (round-off of a value that is zero there).
pub const START_ROUND_OFF: f64 = 64.0 * f64::EPSILON;

/// One crossing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Which event.
    pub event: usize,
    /// When it happened.
    pub t: f64,
    /// Whether the value goes up through zero.
    pub rising: bool,
    /// Whether the run ends here.
    pub stop: bool,
}

/// What one step showed: its crossings and the events whose isolation was not settled there.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Found {
    /// The crossings in time order, up to and including the first that stops the run.
    pub crossings: Vec<Crossing>,
    /// `(event, time, width)`: where an event's parts stayed unsettled at the finest split, and
    /// how wide that part was.
    pub unsettled: Vec<(usize, f64, f64)>,
}

/// The state of every event between steps.
#[derive(Clone, Debug)]
pub struct Detector {
    rules: Vec<Rule>,
    /// The sign of each event's last nonzero value (0: none yet).
    sign: Vec<f64>,
    /// Each event's sample at the end of the last step (its slope NaN before the first step).
    last: Vec<Sample>,
    /// Crossings counted so far.
    counts: Vec<usize>,
    /// No step taken yet: the start may be a round-off zero.
    first: bool,
}

fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

impl Detector {
    /// Events with `rules`, valued `g0` at the start `t0` of a run.
    pub fn new(rules: Vec<Rule>, t0: f64, g0: &[f64]) -> Detector {
        let n = rules.len();
        Detector {
            rules,
            sign: g0.iter().map(|g| sign(*g)).collect(),
            last: g0
                .iter()
                .map(|g| Sample { t: t0, value: *g, slope: f64::NAN, span: f64::INFINITY })
                .collect(),
            counts: vec![0; n],
            first: true,
        }
    }

    /// After a step from `t_prev` to `t`, `g(i, s)` evaluating event `i` at `s` inside it (the
    /// end included): the crossings in the step and where isolation stayed unsettled.
    pub fn step(&mut self, t_prev: f64, t: f64, mut g: impl FnMut(usize, f64) -> f64) -> Found {
        let mut found = Found::default();
        if t.is_nan() || t <= t_prev {
            return found;
        }
        let mut crossings = Vec::new();
        for i in 0..self.rules.len() {
            let mut gi = |s: f64| g(i, s);
            let mut start = self.last[i];
            if start.slope.is_nan() || start.t != t_prev {
                start = Sample::at(&mut gi, t_prev, (t - t_prev) / super::isolate::PARTS as f64, t);
            }
            let iso = isolate(start, t, &mut gi);
            if self.first {
                self.forget_round_off_start(i, &iso);
            }
            if let Some((at, width)) = iso.unsettled {
                found.unsettled.push((i, at, width));
            }
            let mut left = start;
            for p in &iso.points {
                crossings.extend(self.crossing(i, left, *p, &mut gi));
                left = *p;
            }
            self.last[i] = left;
        }
        self.first = false;
        crossings.sort_by(|a, b| a.t.total_cmp(&b.t));
        for mut c in crossings {
            self.counts[c.event] += 1;
            c.stop = self.rules[c.event].stop_after.is_some_and(|n| self.counts[c.event] >= n);
            found.crossings.push(c);
            if c.stop {
                break;
            }
        }
        found
    }

    /// Event `i` starts with no sign when its start value is round-off next to the values of
    /// the first step.
    fn forget_round_off_start(&mut self, i: usize, iso: &Isolation) {
        let scale = iso.points.iter().map(|p| p.value.abs()).filter(|v| v.is_finite()).fold(0.0, f64::max);
        if self.last[i].value.abs() <= START_ROUND_OFF * scale {
            self.sign[i] = 0.0;
        }
    }

    /// Event `i`'s crossing between the samples `l` and `r`, if it changes sign there (from
    /// its last nonzero value) and goes the way the rule asks.
    fn crossing(
        &mut self,
        i: usize,
        l: Sample,
        r: Sample,
        g: &mut impl FnMut(f64) -> f64,
    ) -> Option<Crossing> {
        let before = self.sign[i];
        let after = sign(r.value);
        if after == 0.0 {
            return None;
        }
        self.sign[i] = after;
        if before == 0.0 || before == after {
            return None;
        }
        let at = if l.value == 0.0 { l.t } else { illinois(&mut *g, l.t, l.value, r.t, r.value) };
        let rising = after > 0.0;
        let wanted = match self.rules[i].direction {
            Direction::Up => rising,
            Direction::Down => !rising,
            Direction::Both => true,
        };
        wanted.then_some(Crossing { event: i, t: at, rising, stop: false })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steps of 0.1 over `f` on [0, t_end]; every crossing found.
    fn run(f: fn(f64) -> f64, rules: Vec<Rule>, t_end: f64) -> Vec<Crossing> {
        let n = rules.len();
        let mut d = Detector::new(rules, 0.0, &vec![f(0.0); n]);
        let mut all = Vec::new();
        let mut t = 0.0;
        while t < t_end {
            let next = (t + 0.1f64).min(t_end);
            let found = d.step(t, next, |_, s| f(s)).crossings;
            let stop = found.iter().any(|c| c.stop);
            all.extend(found);
            if stop {
                break;
            }
            t = next;
        }
        all
    }

    #[test]
    fn directions_counts_and_the_start() {
        let both = Rule { direction: Direction::Both, stop_after: None };
        // sin t: zero at the start (not counted), then at pi (down), 2 pi (up), 3 pi (down).
        let found = run(f64::sin, vec![both], 10.0);
        let times: Vec<f64> = found.iter().map(|c| c.t).collect();
        assert_eq!(times.len(), 3, "{times:?}");
        for (k, t) in times.iter().enumerate() {
            assert!((t - (k + 1) as f64 * std::f64::consts::PI).abs() < 1e-14, "{times:?}");
        }
        assert_eq!(found.iter().map(|c| c.rising).collect::<Vec<_>>(), [false, true, false]);
        let up = Rule { direction: Direction::Up, stop_after: None };
        let found = run(f64::sin, vec![up], 10.0);
        assert_eq!(found.len(), 1);
        assert!((found[0].t - 2.0 * std::f64::consts::PI).abs() < 1e-14);
        let second = Rule { direction: Direction::Down, stop_after: Some(2) };
        let found = run(f64::sin, vec![second], 10.0);
        assert_eq!(found.len(), 2);
        assert!(found[1].stop && (found[1].t - 3.0 * std::f64::consts::PI).abs() < 1e-14);
    }

    #[test]
    fn a_start_in_round_off_of_zero_is_no_crossing() {
        let both = Rule { direction: Direction::Both, stop_after: None };
        // Starts at +1e-17, goes negative at once: the start's zero, not an event.
        let found = run(|t| 1e-17 - (t * 3.0).sin(), vec![both], 2.0);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!((found[0].t - std::f64::consts::PI / 3.0).abs() < 1e-14);
    }

    #[test]
    fn the_earliest_stop_cuts_the_list() {
        let rules = vec![
            Rule { direction: Direction::Both, stop_after: None },
            Rule { direction: Direction::Both, stop_after: Some(1) },
        ];
        let g = |i: usize, s: f64| if i == 0 { s - 0.8 } else { s - 0.3 };
        let mut d = Detector::new(rules, 0.0, &[g(0, 0.0), g(1, 0.0)]);
        let found = d.step(0.0, 1.0, g).crossings;
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].event, found[0].stop), (1, true));
        assert!((found[0].t - 0.3).abs() < 1e-15);
    }

    #[test]
    fn a_crossing_early_in_a_long_run_is_no_round_off_zero() {
        // t - 1e-7 over steps of 0.1 to 1e6: its start is a value, not round-off.
        let stop = Rule { direction: Direction::Both, stop_after: Some(1) };
        let found = run(|t| t - 1e-7, vec![stop], 1e6);
        assert_eq!(found.len(), 1);
        assert!((found[0].t - 1e-7).abs() < 1e-20, "{}", found[0].t);
    }

    #[test]
    fn two_crossings_inside_one_step_are_both_found() {
        let both = Rule { direction: Direction::Both, stop_after: None };
        // Down through zero at 0.52 and up at 0.5201, both inside one part of the step 0.5 .. 0.6.
        let found = run(|t| (t - 0.52) * (t - 0.5201), vec![both], 1.0);
        let times: Vec<(f64, bool)> = found.iter().map(|c| (c.t, c.rising)).collect();
        assert_eq!(times.len(), 2, "{times:?}");
        assert!((times[0].0 - 0.52).abs() < 1e-14 && !times[0].1, "{times:?}");
        assert!((times[1].0 - 0.5201).abs() < 1e-14 && times[1].1, "{times:?}");
    }
}
