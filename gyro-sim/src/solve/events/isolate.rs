//! Sign changes isolated inside one step: in come an event function on the step's dense output
//! and its value and slope at the step's start; out go points in time order such that, between
//! two neighbours, the function changes sign at most once (so every sign change in the step
//! lies between two neighbours of opposite signs), and whether some part could not be split
//! finely enough to say so.
//!
//! The step is cut into [`PARTS`] equal parts, each end sampled with its value and its slope (a
//! difference quotient on the dense output over [`SLOPE_SPAN`] of the part) and each part
//! probed for its value at [`PROBE`] of its width. A part is settled when, with the function's
//! curvature bounded by [`SAFETY`] times what the ends' slopes, their secant and the probe
//! show, either the slope keeps one sign over the part (the function is monotone: one crossing
//! or none) or neither end's value can reach zero within half the part.
//! A part not settled is halved, at most [`MAX_DEPTH`] times: the samples follow the function's
//! variation, not the step's length, so a crossing a millionth of a step from the start, or
//! crossings much closer together than the step, are each found.

/// Each step is first cut into this many equal parts.
pub const PARTS: usize = 2;

/// A part is halved at most this many times (a step is resolved to `1 / (PARTS 2^MAX_DEPTH)`
/// of its length).
pub const MAX_DEPTH: u32 = 24;

/// The function's curvature is taken as at most this many times what a part's ends show.
pub const SAFETY: f64 = 4.0;

/// A slope is the difference quotient over this fraction of the part its sample belongs to.
pub const SLOPE_SPAN: f64 = 1e-3;

/// Each part is also probed for its value at this fraction of its width (not a dyadic one, so
/// that a function periodic in a part's width, or in half of it, shows it).
pub const PROBE: f64 = 0.381_966_011_250_105_1;

/// An event function's value and slope at a time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// The time.
    pub t: f64,
    /// The value.
    pub value: f64,
    /// The slope (time derivative along the dense output).
    pub slope: f64,
    /// The time span the slope's difference quotient was taken over.
    pub span: f64,
}

impl Sample {
    /// `g` at `t`, with its slope over `SLOPE_SPAN * width`, taken toward `inside` (forward when
    /// it lies after `t`, else backward).
    pub fn at(g: &mut impl FnMut(f64) -> f64, t: f64, width: f64, inside: f64) -> Sample {
        let value = g(t);
        let mut s = Sample { t, value, slope: f64::NAN, span: f64::INFINITY };
        s.slope_over(g, width, inside);
        s
    }

    /// The slope again over `SLOPE_SPAN * width` toward `inside`.
    fn slope_over(&mut self, g: &mut impl FnMut(f64) -> f64, width: f64, inside: f64) {
        let t = self.t;
        let span = (SLOPE_SPAN * width).max(16.0 * f64::EPSILON * t.abs());
        let other = if inside > t { t + span } else { t - span };
        self.span = (other - t).abs();
        self.slope = (g(other) - self.value) / (other - t);
    }

    /// The slope retaken when it was taken over more than twice `SLOPE_SPAN * width`, as for a
    /// sample of a wider part next to a part of `width` now (toward `inside`).
    fn for_width(mut self, g: &mut impl FnMut(f64) -> f64, width: f64, inside: f64) -> Sample {
        if self.span > 2.0 * SLOPE_SPAN * width {
            self.slope_over(g, width, inside);
        }
        self
    }
}

/// Points of one step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Isolation {
    /// The samples after the step's start, in time order, the step's end last.
    pub points: Vec<Sample>,
    /// The first part that reached [`MAX_DEPTH`] unsettled, as its start and width: there two sign changes may lie between neighbours and be missed.
    pub unsettled: Option<(f64, f64)>,
}

/// The points of the step from `start` (the function's sample there) to `t_end`, `g` the
/// function on the step's dense output.
pub fn isolate(start: Sample, t_end: f64, g: &mut impl FnMut(f64) -> f64) -> Isolation {
    let mut out = Isolation::default();
    let h = t_end - start.t;
    let width = h / PARTS as f64;
    let mut left = start;
    for part in 1..=PARTS {
        let t = if part == PARTS { t_end } else { start.t + h * part as f64 / PARTS as f64 };
        let right = Sample::at(g, t, width, start.t);
        refine(left, right, g, &mut out);
        left = right;
    }
    out
}

/// The points between `left` and `right` (pushing `right` last), halving the part until it is
/// settled.
fn refine(left: Sample, right: Sample, g: &mut impl FnMut(f64) -> f64, out: &mut Isolation) {
    // Halved parts in wait, the nearest last: (left, right, depth).
    let mut pending = vec![(left, right, 0)];
    while let Some((l, r, depth)) = pending.pop() {
        let w = r.t - l.t;
        let (l, r) = (l.for_width(g, w, r.t), r.for_width(g, w, l.t));
        let probe = l.t + PROBE * w;
        if settled(&l, &r, g(probe)) {
            out.points.push(r);
            continue;
        }
        let mid = l.t + 0.5 * w;
        if depth >= MAX_DEPTH || !(mid > l.t && mid < r.t) {
            // A part at the time's resolution holds no two crossing times apart.
            if depth >= MAX_DEPTH {
                out.unsettled.get_or_insert((l.t, w));
            }
            out.points.push(r);
            continue;
        }
        let m = Sample::at(g, mid, 0.5 * w, l.t);
        pending.push((m, r, depth + 1));
        pending.push((l, m, depth + 1));
    }
}

/// Whether the function changes sign at most once between `l` and `r`, given its value
/// `probed` at the fraction [`PROBE`] of the way: with its curvature at most `K` ([`SAFETY`]
/// times the largest the slopes' change, the slopes' differences from the secant and the probe's
/// distance from the chord show), its slope keeps one sign throughout, or neither end's value
/// can reach zero in the half of the part nearer it. A NaN counts as settled (nothing better
/// can be said).
fn settled(l: &Sample, r: &Sample, probed: f64) -> bool {
    let values = [l.value, l.slope, r.value, r.slope, probed];
    if values.iter().any(|v| v.is_nan()) {
        return true;
    }
    let w = r.t - l.t;
    let secant = (r.value - l.value) / w;
    let change =
        (r.slope - l.slope).abs().max(2.0 * (secant - l.slope).abs()).max(2.0 * (secant - r.slope).abs());
    let chord = l.value + PROBE * (r.value - l.value);
    let bend = 2.0 * (probed - chord).abs() / (PROBE * (1.0 - PROBE) * w * w);
    let curvature = SAFETY * (change / w).max(bend);
    let monotone = l.slope * r.slope > 0.0 && l.slope.abs().min(r.slope.abs()) > 0.5 * curvature * w;
    let reach = |s: &Sample| s.slope.abs() * 0.5 * w + curvature * w * w / 8.0;
    let clear = l.value * r.value > 0.0 && l.value.abs() > reach(l) && r.value.abs() > reach(r);
    monotone || clear
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sign changes between the points of `f` over steps of `h` on `[0, t_end]`, and whether
    /// any part stayed unsettled.
    fn sign_changes(f: fn(f64) -> f64, h: f64, t_end: f64) -> (usize, bool) {
        let mut g = |t: f64| f(t);
        let mut start = Sample::at(&mut g, 0.0, h, h);
        let (mut changes, mut unsettled) = (0, false);
        let mut t = 0.0;
        while t < t_end {
            let next = (t + h).min(t_end);
            let iso = isolate(start, next, &mut g);
            let mut last = start.value;
            for p in &iso.points {
                if p.value * last < 0.0 {
                    changes += 1;
                }
                last = p.value;
            }
            unsettled |= iso.unsettled.is_some();
            start = *iso.points.last().unwrap();
            t = next;
        }
        (changes, unsettled)
    }

    #[test]
    fn every_crossing_of_a_fast_sine_in_long_steps() {
        // sin(10000 t) on (0, 1]: floor(10000 / pi) crossings, 318 in each step of 0.1.
        let (n, unsettled) = sign_changes(|t| (10000.0 * t).sin(), 0.1, 1.0);
        assert_eq!(n, (10000.0 / std::f64::consts::PI).floor() as usize);
        assert!(!unsettled);
    }

    #[test]
    fn two_crossings_close_together_inside_one_part() {
        // Down at 0.5201, up at 0.5202: a ten-thousandth of the step apart.
        let (n, unsettled) = sign_changes(|t| (t - 0.5201) * (t - 0.5202), 1.0, 1.0);
        assert_eq!(n, 2);
        assert!(!unsettled);
    }

    #[test]
    fn crossings_a_millionth_of_the_step_from_its_start() {
        let (n, unsettled) = sign_changes(|t| t - 1e-9, 1.0, 1.0);
        assert_eq!((n, unsettled), (1, false));
        let (n, unsettled) = sign_changes(|t| (t - 1e-6) * (t - 3e-6) * (t - 2.0), 1.0, 1.0);
        assert_eq!((n, unsettled), (2, false));
        // Closer together than the finest split (2^-25 of the step): said, not hidden.
        let (_, unsettled) = sign_changes(|t| (t - 1e-9) * (t - 3e-9) * (t - 2.0), 1.0, 1.0);
        assert!(unsettled);
    }

    #[test]
    fn a_double_root_is_reported_unsettled() {
        // Touches zero at 0.3 without crossing: the parts around it cannot be settled.
        let iso = isolate(Sample::at(&mut |t: f64| (t - 0.3).powi(2), 0.0, 1.0, 1.0), 1.0, &mut |t: f64| {
            (t - 0.3).powi(2)
        });
        let (at, _) = iso.unsettled.expect("unsettled");
        assert!((at - 0.3).abs() < 1e-6, "{at}");
    }
}
