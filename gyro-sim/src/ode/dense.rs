//! Dense output. In: an accepted step (its start and end states, its stages, its size) and a
//! table of a continuous extension ([`DenseOutput`]); out: the state anywhere inside the step.
//! One routine evaluates every table: DOPRI5's and DOP853's extensions differ only in data.
//!
//! The interpolant is the nested form of Hairer's codes,
//! `y(t + theta h) = y0 + theta (c0 + (1 - theta) (c1 + theta (c2 + (1 - theta) (c3 + ...))))`,
//! with the cubic Hermite part `c0 = dy`, `c1 = h f0 - dy`, `c2 = 2 dy - h (f0 + f1)`
//! (`dy = y1 - y0`, `f0`, `f1` the slopes at the ends) and the rows `c_{3+r} = h sum_j d_rj k_j`
//! over the step's stages and the table's extra stages.

// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]

use super::System;

/// A continuous extension of an embedded pair, as data.
#[derive(Debug)]
pub struct DenseOutput {
    /// Nodes of the extra stages evaluated after an accepted step (none: the step's own suffice).
    pub c: &'static [f64],
    /// Rows of `a` for the extra stages, each over all stages before it (the step's, then extras).
    pub a: &'static [&'static [f64]],
    /// Rows `d`: the polynomial's coefficient `3 + r` is `h sum_j d_rj k_j`.
    pub d: &'static [&'static [f64]],
    /// The order of floating-point operations; the polynomial is the same either way.
    pub rounding: DenseRounding,
}

/// How an extension's coefficients are rounded: the order of operations of the code its
/// coefficients were published with, kept so that results stay the same bit for bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DenseRounding {
    /// Each weight times `h` first, `c_{3+r} = sum_j (h d_rj) k_j`, and `c2 = 2 dy - h (f0 + f1)`
    /// (Hairer's `contd8`); any number of rows. The choice for a new table.
    WeightsTimesStep,
    /// One row, its sum `sum_j d_j k_j` times `(1 - theta) h` when evaluated, and
    /// `c2 = (dy - h f1) - c1` (Hairer's `contd5`).
    SumTimesStep,
}

/// An accepted step as its interpolant reads it. `N` is the dimension when known at compile
/// time (0: read `n_dyn`), as in the stepping code.
pub(super) struct StepData<'s, const N: usize> {
    /// Where it began.
    pub t: f64,
    /// Its size.
    pub h: f64,
    /// The state at its start.
    pub y0: &'s [f64],
    /// The state at its end.
    pub y1: &'s [f64],
    /// Its stages, stage-major.
    pub k: &'s [f64],
    /// How many stages `k` holds.
    pub s: usize,
    /// `f(t + h, y1)`.
    pub f1: &'s [f64],
    /// The dimension when `N` is 0.
    pub n_dyn: usize,
}

impl<const N: usize> StepData<'_, N> {
    /// The dimension: a compile-time constant when `N > 0`.
    #[inline(always)]
    fn n(&self) -> usize {
        if N == 0 {
            self.n_dyn
        } else {
            N
        }
    }
}

/// The interpolant's coefficients for the last accepted step, computed when first asked for.
pub(super) struct DenseCache {
    /// The extra stages, stage-major.
    extra: Vec<f64>,
    /// The coefficient vectors `c_r`, row-major.
    coef: Vec<f64>,
    tmp: Vec<f64>,
    /// `coef` belongs to the last accepted step.
    ready: bool,
}

impl DenseCache {
    /// Storage for `dense` in dimension `n` (none without an extension).
    pub fn new(n: usize, dense: Option<&DenseOutput>) -> Self {
        let (extra, rows) = dense.map_or((0, 0), |d| (d.c.len(), 3 + d.d.len()));
        DenseCache { extra: vec![0.0; n * extra], coef: vec![0.0; n * rows], tmp: vec![0.0; n], ready: false }
    }

    /// A new step was accepted: the coefficients are stale.
    #[inline(always)]
    pub fn invalidate(&mut self) {
        self.ready = false;
    }

    /// `y(step.t + theta step.h)` into `out`, preparing the coefficients first if this step has
    /// none yet; returns the right-hand-side evaluations that took (the extra stages).
    #[inline]
    pub fn interpolate<S: System + ?Sized, const N: usize>(
        &mut self,
        sys: &S,
        dense: &DenseOutput,
        step: &StepData<'_, N>,
        theta: f64,
        out: &mut [f64],
    ) -> usize {
        let evals = if self.ready { 0 } else { self.prepare(sys, dense, step) };
        self.evaluate(dense, step, theta, out);
        evals
    }

    /// The extra stages and the coefficients, once per step (out of line: the evaluation, once
    /// per output, is the part worth inlining); returns the evaluations of the extra stages.
    #[inline(never)]
    fn prepare<S: System + ?Sized, const N: usize>(
        &mut self,
        sys: &S,
        dense: &DenseOutput,
        step: &StepData<'_, N>,
    ) -> usize {
        let evals = self.extra_stages(sys, dense, step);
        self.coefficients(dense, step);
        self.ready = true;
        evals
    }

    /// The extra stages `f(t + c_i h, y0 + h sum_j a_ij k_j)`; returns how many.
    fn extra_stages<S: System + ?Sized, const N: usize>(
        &mut self,
        sys: &S,
        dense: &DenseOutput,
        step: &StepData<'_, N>,
    ) -> usize {
        let n = step.n();
        for (i, (ci, ai)) in dense.c.iter().zip(dense.a).enumerate() {
            let (done, rest) = self.extra.split_at_mut(i * n);
            combine(step, done, ai, &mut self.tmp);
            sys.rhs(step.t + ci * step.h, &self.tmp, &mut rest[..n]);
        }
        dense.c.len()
    }

    /// The coefficient vectors `c_r` (see the module's comment), rounded as `dense.rounding` says.
    fn coefficients<const N: usize>(&mut self, dense: &DenseOutput, step: &StepData<'_, N>) {
        let (n, h) = (step.n(), step.h);
        let coef = &mut self.coef;
        for m in 0..n {
            let dy = step.y1[m] - step.y0[m];
            let (f0, f1) = (step.k[m], step.f1[m]);
            coef[m] = dy;
            coef[n + m] = h * f0 - dy;
            coef[2 * n + m] = match dense.rounding {
                DenseRounding::WeightsTimesStep => 2.0 * dy - h * (f0 + f1),
                DenseRounding::SumTimesStep => dy - h * f1 - coef[n + m],
            };
        }
        let scale = match dense.rounding {
            DenseRounding::WeightsTimesStep => h,
            DenseRounding::SumTimesStep => 1.0,
        };
        for (r, dr) in dense.d.iter().enumerate() {
            let row = &mut coef[(3 + r) * n..(4 + r) * n];
            row.fill(0.0);
            accumulate(step, &self.extra, scale, dr, row);
        }
    }

    /// The nested form at `theta`: factors `theta` and `1 - theta` alternate from `c0` inward.
    /// Row by row over all components (independent chains); each component's operations are
    /// those of the nested form from the innermost row out.
    fn evaluate<const N: usize>(
        &self,
        dense: &DenseOutput,
        step: &StepData<'_, N>,
        theta: f64,
        out: &mut [f64],
    ) {
        let n = step.n();
        let (out, y0) = (&mut out[..n], &step.y0[..n]);
        let t1 = 1.0 - theta;
        let factor = |r: usize| if r.is_multiple_of(2) { theta } else { t1 };
        let row = |r: usize| &self.coef[r * n..(r + 1) * n];
        // The rows entering the nest as `(acc + c_r) factor_r`: all, or all but the one the step
        // size multiplies here.
        let nested = match dense.rounding {
            DenseRounding::WeightsTimesStep => {
                out.fill(0.0);
                3 + dense.d.len()
            }
            DenseRounding::SumTimesStep => {
                let f = factor(3) * step.h;
                for (acc, c) in out.iter_mut().zip(row(3)) {
                    *acc = f * c;
                }
                3
            }
        };
        for r in (0..nested).rev() {
            let f = factor(r);
            for (acc, c) in out.iter_mut().zip(row(r)) {
                *acc = (*acc + c) * f;
            }
        }
        for (acc, y) in out.iter_mut().zip(y0) {
            *acc += y; // y0 + acc: addition commutes exactly
        }
    }
}

/// Stage `j`: one of the step's, or past them one of the extra stages.
#[inline(always)]
fn stage<'s, const N: usize>(step: &StepData<'s, N>, extra: &'s [f64], j: usize) -> &'s [f64] {
    let (n, s) = (step.n(), step.s);
    if j < s {
        &step.k[j * n..(j + 1) * n]
    } else {
        &extra[(j - s) * n..(j - s + 1) * n]
    }
}

/// `out = y0 + h sum_j w_j k_j` over the step's stages and the extra ones computed so far, in
/// the order of operations of the steps' own combination (the last stage's term added last).
fn combine<const N: usize>(step: &StepData<'_, N>, extra: &[f64], w: &[f64], out: &mut [f64]) {
    let h = step.h;
    let (last, rest) = match w.split_last() {
        Some((wl, rest)) if *wl != 0.0 => (Some(h * wl), rest),
        _ => (None, w),
    };
    out.fill(0.0);
    accumulate(step, extra, 1.0, rest, out);
    for (o, yi) in out.iter_mut().zip(step.y0) {
        *o = yi + h * *o;
    }
    if let Some(c) = last {
        for (o, kj) in out.iter_mut().zip(stage(step, extra, w.len() - 1)) {
            *o += c * kj;
        }
    }
}

/// `out += sum_j (scale w_j) k_j`, skipping zero weights, in stage order: the step's stages, then
/// the extra ones.
#[inline(always)]
fn accumulate<const N: usize>(step: &StepData<'_, N>, extra: &[f64], scale: f64, w: &[f64], out: &mut [f64]) {
    let n = step.n();
    let out = &mut out[..n];
    let (own, more) = w.split_at(w.len().min(step.s));
    for (j, wj) in own.iter().enumerate() {
        if *wj != 0.0 {
            let c = scale * wj;
            for (o, kj) in out.iter_mut().zip(&step.k[j * n..(j + 1) * n]) {
                *o += c * kj;
            }
        }
    }
    for (j, wj) in more.iter().enumerate() {
        if *wj != 0.0 {
            let c = scale * wj;
            for (o, kj) in out.iter_mut().zip(&extra[j * n..(j + 1) * n]) {
                *o += c * kj;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::test_problems::Exponential;

    /// `y' = y`: every stage is known in closed form for a given step.
    const GROWTH: Exponential<1> = Exponential([1.0]);

    #[test]
    fn the_hermite_part_alone_matches_ends_and_slopes() {
        // Without rows, the interpolant is the cubic Hermite one: exact for a cubic.
        static CUBIC: DenseOutput =
            DenseOutput { c: &[], a: &[], d: &[], rounding: DenseRounding::WeightsTimesStep };
        let p = |t: f64| 1.0 + t - 2.0 * t * t + 0.5 * t * t * t;
        let dp = |t: f64| 1.0 - 4.0 * t + 1.5 * t * t;
        let (t0, h) = (0.5, 0.25);
        let (y0, y1, f0, f1) = ([p(t0)], [p(t0 + h)], [dp(t0)], [dp(t0 + h)]);
        let step = StepData::<0> { t: t0, h, y0: &y0, y1: &y1, k: &f0, s: 1, f1: &f1, n_dyn: 1 };
        let mut cache = DenseCache::new(1, Some(&CUBIC));
        let mut out = [0.0];
        assert_eq!(cache.interpolate(&GROWTH, &CUBIC, &step, 0.3, &mut out), 0);
        assert!((out[0] - p(t0 + 0.3 * h)).abs() < 1e-15, "{} vs {}", out[0], p(t0 + 0.3 * h));
    }

    #[test]
    fn extra_stages_are_evaluated_once_per_step() {
        static ONE_EXTRA: DenseOutput = DenseOutput {
            c: &[0.5],
            a: &[&[0.5]],
            d: &[&[0.0, 0.0]],
            rounding: DenseRounding::WeightsTimesStep,
        };
        let (y0, y1, k, f1) = ([1.0], [1.1], [1.0], [1.1]);
        let step = StepData::<1> { t: 0.0, h: 0.1, y0: &y0, y1: &y1, k: &k, s: 1, f1: &f1, n_dyn: 1 };
        let mut cache = DenseCache::new(1, Some(&ONE_EXTRA));
        let mut out = [0.0];
        assert_eq!(cache.interpolate(&GROWTH, &ONE_EXTRA, &step, 0.5, &mut out), 1);
        assert_eq!(cache.extra, [1.05]);
        assert_eq!(cache.interpolate(&GROWTH, &ONE_EXTRA, &step, 0.7, &mut out), 0);
        cache.invalidate();
        assert_eq!(cache.interpolate(&GROWTH, &ONE_EXTRA, &step, 0.7, &mut out), 1);
    }
}
