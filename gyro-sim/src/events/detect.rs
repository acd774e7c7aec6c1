//! Crossings found step by step: in come each event's value at the end of every accepted step
//! and a way to evaluate it inside the step; out go the crossings in time order, each located by
//! [`super::root::illinois`], filtered by direction and counted, the list cut at the first
//! crossing that ends the run.
//!
//! A crossing is a change of sign between the last nonzero value and the new one, checked at
//! [`PARTS`] equal parts of each step (from the dense output), so two crossings cancel and are
//! missed only when they fall inside one part. A zero at the start time is not a crossing, and neither is
//! one within [`START_WINDOW`] of the span after it (the round-off of a value that starts at
//! zero, such as a rate at a turning point).

use super::root::illinois;
use super::Direction;

/// Each step is checked for sign changes in this many equal parts (its dense output evaluated at
/// the `PARTS - 1` points between), so two crossings inside one step are found unless they fall
/// in one part.
pub const PARTS: usize = 4;

/// Crossings this close after the start (relative to the span) are the start's own zero.
pub const START_WINDOW: f64 = 1e-12;

/// What is watched of one event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rule {
    /// The crossings that count.
    pub direction: Direction,
    /// The run ends at this crossing (counted from one), if any.
    pub stop_after: Option<usize>,
}

/// One crossing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Which event.
    pub event: usize,
    /// When.
    pub t: f64,
    /// Whether the value goes up through zero.
    pub rising: bool,
    /// Whether the run ends here.
    pub stop: bool,
}

/// The state of every event between steps.
#[derive(Clone, Debug)]
pub struct Detector {
    rules: Vec<Rule>,
    /// The sign of each event's last nonzero value (0: none yet).
    sign: Vec<f64>,
    /// Each event's value at the end of the last step.
    last: Vec<f64>,
    /// Crossings counted so far.
    counts: Vec<usize>,
    /// Crossings before this time are the start's own zero.
    t_min: f64,
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
    /// Events with `rules`, valued `g0` at the start `t0` of a run to `t_end`.
    pub fn new(rules: Vec<Rule>, t0: f64, t_end: f64, g0: &[f64]) -> Detector {
        let n = rules.len();
        let t_min = t0 + START_WINDOW * (t_end - t0).abs().max(f64::MIN_POSITIVE);
        Detector {
            rules,
            sign: g0.iter().map(|g| sign(*g)).collect(),
            last: g0.to_vec(),
            counts: vec![0; n],
            t_min,
        }
    }

    /// How many crossings of each event were counted.
    pub fn counts(&self) -> &[usize] {
        &self.counts
    }

    /// After a step from `t_prev` to `t`: `g_end` are the values at `t`, `g(i, s)` evaluates
    /// event `i` at `s` inside the step. The crossings in the step, in time order, up to and
    /// including the first that stops the run.
    pub fn step(
        &mut self,
        t_prev: f64,
        t: f64,
        g_end: &[f64],
        mut g: impl FnMut(usize, f64) -> f64,
    ) -> Vec<Crossing> {
        let mut found = Vec::new();
        for (i, &end) in g_end.iter().enumerate() {
            let mut start = t_prev;
            for part in 1..=PARTS {
                let (stop, value) = if part == PARTS {
                    (t, end)
                } else {
                    let s = t_prev + (t - t_prev) * part as f64 / PARTS as f64;
                    (s, g(i, s))
                };
                found.extend(self.crossing(i, start, stop, value, &mut g));
                start = stop;
            }
        }
        found.sort_by(|a, b| a.t.total_cmp(&b.t));
        let mut out = Vec::with_capacity(found.len());
        for mut c in found {
            self.counts[c.event] += 1;
            c.stop = self.rules[c.event].stop_after.is_some_and(|n| self.counts[c.event] >= n);
            out.push(c);
            if c.stop {
                break;
            }
        }
        out
    }
}

impl Detector {
    /// Event `i`'s crossing between `t0` (its last value there) and `t1` (value `end`), if it
    /// changes sign there and goes the way the rule asks.
    fn crossing(
        &mut self,
        i: usize,
        t0: f64,
        t1: f64,
        end: f64,
        g: &mut impl FnMut(usize, f64) -> f64,
    ) -> Option<Crossing> {
        let (before, last) = (self.sign[i], self.last[i]);
        let after = sign(end);
        self.last[i] = end;
        if after == 0.0 {
            return None;
        }
        self.sign[i] = after;
        if before == 0.0 || before == after {
            return None;
        }
        let at = if last == 0.0 { t0 } else { illinois(|s| g(i, s), t0, last, t1, end) };
        let rising = after > 0.0;
        let wanted = match self.rules[i].direction {
            Direction::Up => rising,
            Direction::Down => !rising,
            Direction::Both => true,
        };
        (wanted && at > self.t_min).then_some(Crossing { event: i, t: at, rising, stop: false })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steps of 0.1 over `f` on [0, t_end]; every crossing found.
    fn run(f: fn(f64) -> f64, rules: Vec<Rule>, t_end: f64) -> Vec<Crossing> {
        let n = rules.len();
        let mut d = Detector::new(rules, 0.0, t_end, &vec![f(0.0); n]);
        let mut all = Vec::new();
        let mut t = 0.0;
        while t < t_end {
            let next = (t + 0.1f64).min(t_end);
            let found = d.step(t, next, &vec![f(next); n], |_, s| f(s));
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
        let mut d = Detector::new(rules, 0.0, 1.0, &[-1.0, -1.0]);
        let g = |i: usize, s: f64| if i == 0 { s - 0.8 } else { s - 0.3 };
        let found = d.step(0.0, 1.0, &[0.2, 0.7], g);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].event, found[0].stop), (1, true));
        assert!((found[0].t - 0.3).abs() < 1e-15);
    }

    #[test]
    fn two_crossings_inside_one_step_are_both_found() {
        let both = Rule { direction: Direction::Both, stop_after: None };
        // Down through zero at 0.52 and up at 0.57, both inside the step 0.5 .. 0.6.
        let found = run(|t| (t - 0.52) * (t - 0.57), vec![both], 1.0);
        let times: Vec<(f64, bool)> = found.iter().map(|c| (c.t, c.rising)).collect();
        assert_eq!(times.len(), 2, "{times:?}");
        assert!((times[0].0 - 0.52).abs() < 1e-14 && !times[0].1, "{times:?}");
        assert!((times[1].0 - 0.57).abs() < 1e-14 && times[1].1, "{times:?}");
    }
}
