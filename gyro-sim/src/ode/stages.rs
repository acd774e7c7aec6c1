//! One explicit Runge-Kutta step. In: a system, a tableau, `(t, y)`, a step size and stage 0
//! (`f(t, y)`); out: the other stages, the new state and the local error estimate, and after an
//! accepted step the stage that starts the next one. No step-size decisions here.

// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]

mod unrolled;

use super::tableau::Tableau;
use super::{System, Tolerances};

/// What integration cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Calls of the right-hand side.
    pub rhs_evals: usize,
}

/// The stage buffers of one integration, with the system and tableau they serve. `N` is the
/// dimension when known at compile time (0: read `n_dyn`); then the component loops unroll, and
/// the built-in tableaux take the fully unrolled step.
pub(super) struct StageBuffers<'a, S: System + ?Sized, const N: usize> {
    pub(super) sys: &'a S,
    pub(super) tab: &'static Tableau,
    n_dyn: usize,
    /// Stage derivatives, stage-major: stage j is `k[j * n..(j + 1) * n]`. After an accepted
    /// step they stay that step's until the next step begins (the interpolant reads them).
    pub(super) k: Vec<f64>,
    pub(super) tmp: Vec<f64>,
    pub(super) ynew: Vec<f64>,
    /// The embedded pair's error estimate `sum_j e_j k_j` (DOP853's fifth-order one).
    error_embedded: Vec<f64>,
    /// DOP853's third-order error estimate `sum_j e3_j k_j` (unused by other tableaux).
    error_order3: Vec<f64>,
    /// `f(t_new, y_new)` after an accepted step, for a tableau with a continuous extension and
    /// without first-same-as-last (empty otherwise).
    f_end: Vec<f64>,
    /// Stage 0 is `f(t, y)` of the current state (false between an accepted step and the next).
    start_ready: bool,
    pub(super) stats: Stats,
}

impl<'a, S: System + ?Sized, const N: usize> StageBuffers<'a, S, N> {
    /// Storage for stepping `sys` with `tab`; stage 0 still to be set.
    pub(super) fn new(sys: &'a S, tab: &'static Tableau) -> Self {
        let n = sys.dim();
        StageBuffers {
            sys,
            tab,
            n_dyn: n,
            k: vec![0.0; n * tab.c.len()],
            tmp: vec![0.0; n],
            ynew: vec![0.0; n],
            error_embedded: vec![0.0; n],
            error_order3: vec![0.0; n],
            f_end: vec![0.0; if tab.fsal || tab.dense.is_none() { 0 } else { n }],
            start_ready: true,
            stats: Stats::default(),
        }
    }

    /// The dimension: a compile-time constant when `N > 0`.
    #[inline(always)]
    pub(super) fn n(&self) -> usize {
        if N == 0 {
            self.n_dyn
        } else {
            N
        }
    }

    pub(super) fn stage(&self, j: usize) -> &[f64] {
        let n = self.n();
        &self.k[j * n..(j + 1) * n]
    }

    /// `f(t_new, y_new)` of the last accepted step, for its continuous extension: its last stage
    /// (first-same-as-last) or the one evaluated for the next step.
    pub(super) fn end_slope(&self) -> &[f64] {
        if self.tab.fsal {
            self.stage(self.tab.c.len() - 1)
        } else {
            &self.f_end
        }
    }

    /// `out = y + h * sum_j w_j k_j`, skipping zero weights; the last stage's term is added
    /// after `y` (`(y + h * rest) + (h w_last) k_last`), so the newest stage, the one a step
    /// waits for, passes through one multiply-add. The unrolled steps do the same arithmetic in
    /// the same order.
    fn combine(k: &[f64], n: usize, y: &[f64], h: f64, w: &[f64], out: &mut [f64]) {
        let (last, rest) = match w.split_last() {
            Some((wl, rest)) if *wl != 0.0 => (Some(h * wl), rest),
            _ => (None, w),
        };
        out.fill(0.0);
        Self::accumulate(k, n, 1.0, rest, out);
        for (o, yi) in out.iter_mut().zip(y) {
            *o = yi + h * *o;
        }
        if let Some(c) = last {
            let j = w.len() - 1;
            for (o, kj) in out.iter_mut().zip(&k[j * n..(j + 1) * n]) {
                *o += c * kj;
            }
        }
    }

    /// `out += h * sum_j w_j k_j`.
    fn accumulate(k: &[f64], n: usize, h: f64, w: &[f64], out: &mut [f64]) {
        for (j, wj) in w.iter().enumerate() {
            if *wj != 0.0 {
                let c = h * wj;
                for (o, kj) in out.iter_mut().zip(&k[j * n..(j + 1) * n]) {
                    *o += c * kj;
                }
            }
        }
    }

    /// Makes stage 0 `f(t, y)` of the current state: after an accepted step, the last stage
    /// (first-same-as-last) or `f_end`, unless already there. Called before a step's first
    /// attempt.
    #[inline(always)]
    pub(super) fn begin(&mut self) {
        if self.start_ready {
            return;
        }
        let (n, s) = (self.n(), self.tab.c.len());
        if self.tab.fsal {
            self.k.copy_within((s - 1) * n..s * n, 0);
        } else {
            self.k[..n].copy_from_slice(&self.f_end[..n]);
        }
        self.start_ready = true;
    }

    /// Stage 0 evaluated afresh at `(t, y)`: the state was moved since the last step.
    pub(super) fn restart(&mut self, t: f64, y: &[f64]) {
        let n = self.n();
        self.sys.rhs(t, y, &mut self.k[..n]);
        self.stats.rhs_evals += 1;
        self.start_ready = true;
    }

    /// One step of size `h` from `(t, y)`, with stage 0 = f(t, y): fills `ynew` and the stages.
    pub(super) fn step(&mut self, t: f64, y: &[f64], h: f64) {
        if self.step_unrolled(t, y, h) {
            return;
        }
        let n = self.n();
        for i in 1..self.tab.stages_before_error() {
            Self::combine(&self.k, n, y, h, self.tab.a[i], &mut self.tmp);
            let (_, rest) = self.k.split_at_mut(i * n);
            self.sys.rhs(t + self.tab.c[i] * h, &self.tmp, &mut rest[..n]);
            self.stats.rhs_evals += 1;
        }
        Self::combine(&self.k, n, y, h, self.tab.b, &mut self.ynew);
    }

    /// The local error estimate of the last step (see [`Self::error_norm`]).
    pub(super) fn error(&mut self, y: &[f64], h: f64, tol: Tolerances) -> f64 {
        if let Some(err) = self.error_unrolled(y, h, tol) {
            return err;
        }
        let n = self.n();
        let mut e5 = std::mem::take(&mut self.error_embedded);
        let mut e3 = std::mem::take(&mut self.error_order3);
        e5.fill(0.0);
        Self::accumulate(&self.k, n, 1.0, self.tab.e.unwrap_or(&[]), &mut e5);
        let third = self.tab.e3.map(|w| {
            e3.fill(0.0);
            Self::accumulate(&self.k, n, 1.0, w, &mut e3);
            &e3[..]
        });
        let err = self.error_norm(y, h, &e5, third, tol);
        self.error_embedded = e5;
        self.error_order3 = e3;
        err
    }

    /// The error `h sum_j e_j k_j` (`e5`; DOP853 also `e3`) relative to `atol + rtol *
    /// max(|y|, |ynew|)`: an RMS for embedded pairs; for DOP853, Hairer's blend of its fifth- and
    /// third-order estimates, `|h| e5^2 / sqrt(n (e5^2 + 0.01 e3^2))`.
    #[inline(always)]
    fn error_norm(&self, y: &[f64], h: f64, e5: &[f64], e3: Option<&[f64]>, tol: Tolerances) -> f64 {
        let n = self.n();
        let (mut sum5, mut sum3) = (0.0, 0.0);
        for m in 0..n {
            let inv_scale = 1.0 / (tol.atol + tol.rtol * y[m].abs().max(self.ynew[m].abs()));
            let r5 = e5[m] * inv_scale;
            sum5 += r5 * r5;
            if let Some(e3) = e3 {
                let r3 = e3[m] * inv_scale;
                sum3 += r3 * r3;
            }
        }
        blended_norm(h, n, sum5, e3.map(|_| sum3))
    }

    /// Completes a step about to be accepted, ending at `t_new`: the first-same-as-last stage
    /// when the step left it for after its error test.
    #[inline(always)]
    pub(super) fn complete(&mut self, t_new: f64) {
        let (n, s) = (self.n(), self.tab.c.len());
        if self.tab.stages_before_error() < s {
            let (_, rest) = self.k.split_at_mut((s - 1) * n);
            self.sys.rhs(t_new, &self.ynew, &mut rest[..n]);
            self.stats.rhs_evals += 1;
        }
    }

    /// After an accepted step to `(t_new, ynew)` (finite): the next step's first stage, evaluated
    /// now when the tableau is not first-same-as-last. Without a continuous extension straight
    /// into stage 0 (nothing reads the step's stages any more); otherwise into `f_end`, which
    /// [`Self::begin`] copies in as it copies a first-same-as-last stage.
    #[inline(always)]
    pub(super) fn finish(&mut self, t_new: f64) {
        self.stats.steps += 1;
        if self.tab.fsal {
            self.start_ready = false;
        } else if self.tab.dense.is_none() {
            let n = self.n();
            self.sys.rhs(t_new, &self.ynew[..n], &mut self.k[..n]);
            self.stats.rhs_evals += 1;
        } else {
            self.sys.rhs(t_new, &self.ynew, &mut self.f_end);
            self.stats.rhs_evals += 1;
            self.start_ready = false;
        }
    }
}

/// The error norm from the sums of squared scaled estimates over `n` states: the RMS of the
/// embedded estimate `sum5`, or with DOP853's third-order sum `sum3`, Hairer's blend
/// `|h| sum5 / sqrt(n (sum5 + 0.01 sum3))`.
#[inline(always)]
pub(crate) fn blended_norm(h: f64, n: usize, sum5: f64, sum3: Option<f64>) -> f64 {
    match sum3 {
        None => h.abs() * (sum5 / n.max(1) as f64).sqrt(),
        Some(sum3) if sum5 == 0.0 && sum3 == 0.0 => 0.0,
        Some(sum3) => h.abs() * sum5 / (n.max(1) as f64 * (sum5 + 0.01 * sum3)).sqrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::dense::{DenseOutput, DenseRounding};
    use crate::ode::tableau::{DOP853, RK4};
    use crate::ode::test_problems::Exponential;

    /// `y' = -y`.
    const DECAY: Exponential<1> = Exponential([-1.0]);

    #[test]
    fn the_next_first_stage_is_the_end_slope_every_way() {
        // First-same-as-last, evaluated into stage 0, evaluated into `f_end` for the interpolant.
        static RK4_DENSE: Tableau = Tableau {
            dense: Some(DenseOutput { c: &[], a: &[], d: &[], rounding: DenseRounding::WeightsTimesStep }),
            ..RK4
        };
        for tab in [&DOP853, &RK4, &RK4_DENSE] {
            let mut w = StageBuffers::<Exponential<1>, 0>::new(&DECAY, tab);
            let y = [1.0];
            w.k[0] = -1.0;
            w.step(0.0, &y, 0.1);
            w.complete(0.1);
            let evals = w.stats.rhs_evals;
            w.finish(0.1);
            assert_eq!(w.stats.rhs_evals - evals, usize::from(!tab.fsal), "{}", tab.name);
            if tab.dense.is_some() {
                assert_eq!(w.end_slope(), [-w.ynew[0]], "{}", tab.name);
                assert_eq!(w.stage(0), [-1.0], "{}: the step's first stage stays", tab.name);
            }
            w.begin();
            assert_eq!(w.stage(0), [-w.ynew[0]], "{}", tab.name);
            assert_eq!(w.stats.steps, 1);
        }
    }
}
