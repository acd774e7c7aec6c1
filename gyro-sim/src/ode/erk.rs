//! Explicit Runge-Kutta integration: adaptive steps with PI control for embedded pairs, fixed
//! steps otherwise. Pairs with a continuous extension interpolate output times inside steps;
//! others shorten a step to land on them. Either way the value at `t_final` is a step's own value
//! at `t_final`, not at a sum of step sizes.

// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]

mod unrolled;

use super::tableau::{Dense, StepControl, Tableau};
use super::{OdeError, System};

/// Error tolerances in Autolev's sense: each component's local error is kept below
/// `atol + rtol * |y|` (RMS over components).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance (Autolev's RELERR).
    pub rtol: f64,
    /// Absolute tolerance (Autolev's ABSERR).
    pub atol: f64,
}

/// How to integrate.
#[derive(Clone, Copy, Debug)]
pub enum Method {
    /// An embedded pair with error control.
    Adaptive(&'static Tableau, Tolerances),
    /// A fixed step no larger than the given one (shortened evenly to land on output times).
    Fixed(&'static Tableau, f64),
}

/// What an integration cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Calls of the right-hand side.
    pub rhs_evals: usize,
}

const MAX_STEPS: usize = 10_000_000;
const SAFETY: f64 = 0.9;

/// PI step-size control `h_new = h * SAFETY * err^-alpha * err_old^beta` with
/// `alpha = 1/order - 0.75 beta` (Hairer, Norsett, Wanner, Solving ODEs I, section IV.2; the
/// tableau's [`StepControl`]), in logarithms: one `ln` and one `exp` per accepted step instead
/// of two `powf`.
struct PiControl {
    alpha: f64,
    control: StepControl,
    ln_err_old: f64,
}

impl PiControl {
    fn new(order: u32, control: StepControl) -> Self {
        let alpha = 1.0 / order as f64 - 0.75 * control.beta;
        Self { alpha, control, ln_err_old: 1e-4f64.ln() }
    }

    /// The step-size factor after an accepted step with error `err <= 1`.
    fn accepted(&mut self, err: f64) -> f64 {
        let ln_err = err.max(1e-10).ln();
        let fac = (-self.alpha * ln_err + self.control.beta * self.ln_err_old).exp();
        self.ln_err_old = ln_err.max(1e-4f64.ln());
        (SAFETY * fac).clamp(self.control.min_factor, self.control.max_factor)
    }

    /// The step-size factor after a rejected step (`err > 1` or not finite).
    fn rejected(&self, err: f64) -> f64 {
        if err.is_finite() {
            (SAFETY * (-self.alpha * err.ln()).exp()).max(self.control.min_factor)
        } else {
            self.control.min_factor
        }
    }
}

/// Stepping state. `N` is the dimension when known at compile time (0: read `n_dyn`); then the
/// component loops unroll, and the built-in tableaux take the fully unrolled step.
struct Work<'a, S: System + ?Sized, const N: usize> {
    sys: &'a S,
    tab: &'static Tableau,
    n_dyn: usize,
    /// Stage derivatives, stage-major: stage j is `k[j * n..(j + 1) * n]`.
    k: Vec<f64>,
    tmp: Vec<f64>,
    ynew: Vec<f64>,
    /// The error estimates `sum_j e_j k_j` (fifth order; DOP853's third order).
    err5: Vec<f64>,
    err3: Vec<f64>,
    /// The septic interpolant's seven coefficient vectors for the last accepted step.
    dense_coef: Vec<f64>,
    stats: Stats,
}

impl<'a, S: System + ?Sized, const N: usize> Work<'a, S, N> {
    /// Storage for stepping `sys` with `tab`.
    fn new(sys: &'a S, tab: &'static Tableau) -> Self {
        let n = sys.dim();
        let (extra_stages, coef_rows) = match &tab.dense {
            Some(Dense::Septic { c, d, .. }) => (c.len(), 3 + d.len()),
            _ => (0, 0),
        };
        Work {
            sys,
            tab,
            n_dyn: n,
            k: vec![0.0; n * (tab.c.len() + extra_stages)],
            tmp: vec![0.0; n],
            ynew: vec![0.0; n],
            err5: vec![0.0; n],
            err3: vec![0.0; n],
            dense_coef: vec![0.0; n * coef_rows],
            stats: Stats::default(),
        }
    }

    /// The dimension: a compile-time constant when `N > 0`.
    #[inline(always)]
    fn n(&self) -> usize {
        if N == 0 {
            self.n_dyn
        } else {
            N
        }
    }

    fn stage(&self, j: usize) -> &[f64] {
        let n = self.n();
        &self.k[j * n..(j + 1) * n]
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

    /// One step of size `h` from `(t, y)`, with stage 0 = f(t, y): fills `ynew` and the stages.
    fn step(&mut self, t: f64, y: &[f64], h: f64) {
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
    fn error(&mut self, y: &[f64], h: f64, tol: Tolerances) -> f64 {
        if let Some(err) = self.error_unrolled(y, h, tol) {
            return err;
        }
        let n = self.n();
        let mut e5 = std::mem::take(&mut self.err5);
        let mut e3 = std::mem::take(&mut self.err3);
        e5.fill(0.0);
        Self::accumulate(&self.k, n, 1.0, self.tab.e.unwrap_or(&[]), &mut e5);
        let third = self.tab.e3.map(|w| {
            e3.fill(0.0);
            Self::accumulate(&self.k, n, 1.0, w, &mut e3);
            &e3[..]
        });
        let err = self.error_norm(y, h, &e5, third, tol);
        self.err5 = e5;
        self.err3 = e3;
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
        match e3 {
            None => h.abs() * (sum5 / n.max(1) as f64).sqrt(),
            Some(_) if sum5 == 0.0 && sum3 == 0.0 => 0.0,
            Some(_) => h.abs() * sum5 / (n.max(1) as f64 * (sum5 + 0.01 * sum3)).sqrt(),
        }
    }

    /// Prepares interpolation in the accepted step `y0 -> ynew` of size `h` from `t` (before
    /// the stages are reused): for the septic extension, its three extra stages and the
    /// coefficient vectors of Hairer's `contd8`.
    fn prepare_dense(&mut self, t: f64, y0: &[f64], h: f64, dense: &Dense) {
        let Dense::Septic { c, a, d } = dense else { return };
        let (n, s) = (self.n(), self.tab.c.len());
        for (i, (ci, ai)) in c.iter().zip(a.iter()).enumerate() {
            Self::combine(&self.k, n, y0, h, ai, &mut self.tmp);
            let (_, rest) = self.k.split_at_mut((s + i) * n);
            self.sys.rhs(t + ci * h, &self.tmp, &mut rest[..n]);
            self.stats.rhs_evals += 1;
        }
        let coef = &mut self.dense_coef;
        for m in 0..n {
            let dy = self.ynew[m] - y0[m];
            let (f0, f1) = (self.k[m], self.k[(s - 1) * n + m]);
            coef[m] = dy;
            coef[n + m] = h * f0 - dy;
            coef[2 * n + m] = 2.0 * dy - h * (f0 + f1);
        }
        for (r, dr) in d.iter().enumerate() {
            let row = &mut coef[(3 + r) * n..(4 + r) * n];
            row.fill(0.0);
            Self::accumulate(&self.k, n, h, dr, row);
        }
    }

    /// `y(t_old + theta h)` in the accepted step `y0 -> ynew`, after [`Self::prepare_dense`].
    /// Quartic (Hairer's contd5): `y0 + th (dy + (1 - th)(b + th (dy - h k_last - b + (1 - th) h
    /// sum_j d_j k_j)))` with `dy = ynew - y0`, `b = h k_0 - dy`. Septic (contd8): the nested
    /// form `y0 + th (r0 + (1 - th)(r1 + th (r2 + ...)))` of the coefficient vectors.
    fn interpolate(&self, y0: &[f64], h: f64, theta: f64, dense: &Dense, out: &mut [f64]) {
        let n = self.n();
        let t1 = 1.0 - theta;
        match dense {
            Dense::Quartic(d) => {
                let last = self.tab.c.len() - 1;
                for m in 0..n {
                    let dy = self.ynew[m] - y0[m];
                    let bspl = h * self.k[m] - dy;
                    let r4 = dy - h * self.k[last * n + m] - bspl;
                    let mut r5 = 0.0;
                    for (j, dj) in d.iter().enumerate() {
                        if *dj != 0.0 {
                            r5 += dj * self.k[j * n + m];
                        }
                    }
                    out[m] = y0[m] + theta * (dy + t1 * (bspl + theta * (r4 + t1 * h * r5)));
                }
            }
            Dense::Septic { .. } => {
                let rows = self.dense_coef.len() / n.max(1);
                for m in 0..n {
                    let mut acc = 0.0;
                    for r in (0..rows).rev() {
                        acc = (acc + self.dense_coef[r * n + m]) * if r % 2 == 0 { theta } else { t1 };
                    }
                    out[m] = y0[m] + acc;
                }
            }
        }
    }

    /// Completes an accepted step ending at `t_new`: the first-same-as-last stage when the
    /// step left it for after its error test.
    fn complete(&mut self, t_new: f64) {
        let (n, s) = (self.n(), self.tab.c.len());
        if self.tab.stages_before_error() < s {
            let (_, rest) = self.k.split_at_mut((s - 1) * n);
            self.sys.rhs(t_new, &self.ynew, &mut rest[..n]);
            self.stats.rhs_evals += 1;
        }
    }

    /// The stage at the start of the next step: reused (FSAL) or computed.
    fn next_start(&mut self, t: f64) {
        let (n, s) = (self.n(), self.tab.c.len());
        if self.tab.fsal {
            self.k.copy_within((s - 1) * n..s * n, 0);
        } else {
            self.sys.rhs(t, &self.ynew, &mut self.k[..n]);
            self.stats.rhs_evals += 1;
        }
    }
}

fn check_finite(t: f64, y: &[f64]) -> Result<(), OdeError> {
    match y.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(OdeError::NonFinite { time: t, index, value: y[index] }),
        None => Ok(()),
    }
}

/// Integrates from `(t0, y0)` through the increasing output `times`, calling `out(t, y)` at each.
pub fn integrate<S: System + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    method: Method,
    out: impl FnMut(f64, &[f64]) -> Result<(), String>,
) -> Result<Stats, OdeError> {
    match sys.dim() {
        1 => integrate_n::<S, 1>(sys, t0, y0, times, method, out),
        2 => integrate_n::<S, 2>(sys, t0, y0, times, method, out),
        3 => integrate_n::<S, 3>(sys, t0, y0, times, method, out),
        4 => integrate_n::<S, 4>(sys, t0, y0, times, method, out),
        5 => integrate_n::<S, 5>(sys, t0, y0, times, method, out),
        6 => integrate_n::<S, 6>(sys, t0, y0, times, method, out),
        7 => integrate_n::<S, 7>(sys, t0, y0, times, method, out),
        8 => integrate_n::<S, 8>(sys, t0, y0, times, method, out),
        _ => integrate_n::<S, 0>(sys, t0, y0, times, method, out),
    }
}

/// [`integrate`] with the dimension `N` fixed at compile time (0: any).
fn integrate_n<S: System + ?Sized, const N: usize>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    times: &[f64],
    method: Method,
    mut out: impl FnMut(f64, &[f64]) -> Result<(), String>,
) -> Result<Stats, OdeError> {
    let tab = match method {
        Method::Adaptive(t, _) | Method::Fixed(t, _) => t,
    };
    let mut w = Work::<S, N>::new(sys, tab);
    let n = w.n();
    let mut t = t0;
    let mut y = y0.to_vec();
    check_finite(t, &y)?;
    sys.rhs(t, &y, &mut w.k[..n]);
    w.stats.rhs_evals += 1;
    let mut h = match method {
        Method::Adaptive(_, tol) => {
            initial_step(&mut w, t, &y, tol, times.last().copied().unwrap_or(t0) - t0)
        }
        Method::Fixed(_, step) => step,
    };
    if let (Method::Adaptive(_, tol), Some(d)) = (method, &tab.dense) {
        return dense_run(&mut w, t, y, h, tol, d, times, &mut out);
    }
    let mut control = PiControl::new(tab.order, tab.control);
    for &target in times {
        while t < target {
            if w.stats.steps >= MAX_STEPS {
                return Err(OdeError::TooManySteps { time: t, max: MAX_STEPS });
            }
            match method {
                Method::Fixed(_, step) => {
                    let count = ((target - t) / step - 1e-9).ceil().max(1.0);
                    let hs = (target - t) / count;
                    for i in 0..count as usize {
                        w.step(t, &y, hs);
                        t = if i + 1 == count as usize { target } else { t + hs };
                        w.complete(t);
                        check_finite(t, &w.ynew)?;
                        y.copy_from_slice(&w.ynew);
                        w.next_start(t);
                        w.stats.steps += 1;
                    }
                }
                Method::Adaptive(_, tol) => {
                    let step = accepted_step(&mut w, t, &y, h, target, tol, &control)?;
                    t = step.t_new;
                    check_finite(t, &w.ynew)?;
                    y.copy_from_slice(&w.ynew);
                    w.next_start(t);
                    w.stats.steps += 1;
                    let proposed = step.next_h(control.accepted(step.err));
                    // A step shortened to land on an output time does not shrink the next.
                    h = if step.at_target { proposed.max(h) } else { proposed };
                }
            }
        }
        out(target, &y).map_err(OdeError::Output)?;
    }
    Ok(w.stats)
}

/// An accepted step from `(t, y)` toward `target`, in `w.ynew` and the stages.
struct AcceptedStep {
    /// The step size used.
    h: f64,
    /// Where it ends: `target` exactly when it reaches it.
    t_new: f64,
    /// Its error estimate (at most 1).
    err: f64,
    /// It ends at `target`.
    at_target: bool,
    /// A larger step was rejected first.
    after_rejection: bool,
}

impl AcceptedStep {
    /// The next step size from the controller's factor; after a rejection it does not grow
    /// (Hairer's codes: a rejected step's neighbourhood is no place to be bold).
    fn next_h(&self, factor: f64) -> f64 {
        let h = self.h * factor;
        if self.after_rejection {
            h.min(self.h)
        } else {
            h
        }
    }
}

/// Tries `h` (or the rest of the way to `target` when `h` nearly reaches it), shrinking the step
/// after each rejection until the error estimate is at most 1.
fn accepted_step<S: System + ?Sized, const N: usize>(
    w: &mut Work<'_, S, N>,
    t: f64,
    y: &[f64],
    h: f64,
    target: f64,
    tol: Tolerances,
    control: &PiControl,
) -> Result<AcceptedStep, OdeError> {
    let remaining = target - t;
    let (mut h_try, mut at_target) =
        if h >= remaining * (1.0 - 1e-12) { (remaining, true) } else { (h, false) };
    let mut rejected = false;
    loop {
        if h_try < 16.0 * f64::EPSILON * t.abs().max(1.0) {
            return Err(OdeError::StepSizeUnderflow { time: t, step: h_try });
        }
        w.step(t, y, h_try);
        let err = w.error(y, h_try, tol);
        if err <= 1.0 {
            let t_new = if at_target { target } else { t + h_try };
            w.complete(t_new);
            return Ok(AcceptedStep { h: h_try, t_new, err, at_target, after_rejection: rejected });
        }
        h_try *= control.rejected(err);
        at_target = false;
        rejected = true;
        w.stats.rejected += 1;
    }
}

/// Adaptive stepping to the last output time only, with outputs in between from the dense
/// interpolant; the last output is the last step's own value, at `t_final` exactly.
#[allow(clippy::too_many_arguments)]
fn dense_run<S: System + ?Sized, const N: usize>(
    w: &mut Work<'_, S, N>,
    mut t: f64,
    mut y: Vec<f64>,
    mut h: f64,
    tol: Tolerances,
    dense: &Dense,
    times: &[f64],
    out: &mut impl FnMut(f64, &[f64]) -> Result<(), String>,
) -> Result<Stats, OdeError> {
    let Some(&t_end) = times.last() else { return Ok(w.stats) };
    let mut next = 0;
    while next < times.len() && times[next] <= t {
        out(times[next], &y).map_err(OdeError::Output)?;
        next += 1;
    }
    let mut y_out = vec![0.0; w.n()];
    let mut control = PiControl::new(w.tab.order, w.tab.control);
    while t < t_end {
        if w.stats.steps >= MAX_STEPS {
            return Err(OdeError::TooManySteps { time: t, max: MAX_STEPS });
        }
        let step = accepted_step(w, t, &y, h, t_end, tol, &control)?;
        check_finite(step.t_new, &w.ynew)?;
        // Outputs inside the step, from the interpolant; the step's end exactly.
        let mut prepared = false;
        while next < times.len() && times[next] <= step.t_new {
            if times[next] == step.t_new {
                out(step.t_new, &w.ynew).map_err(OdeError::Output)?;
            } else {
                if !prepared {
                    w.prepare_dense(t, &y, step.h, dense);
                    prepared = true;
                }
                w.interpolate(&y, step.h, (times[next] - t) / step.h, dense, &mut y_out);
                out(times[next], &y_out).map_err(OdeError::Output)?;
            }
            next += 1;
        }
        t = step.t_new;
        y.copy_from_slice(&w.ynew);
        w.next_start(t);
        w.stats.steps += 1;
        h = step.next_h(control.accepted(step.err));
    }
    Ok(w.stats)
}

/// Hairer's starting step: a step whose explicit-Euler error is about the tolerance.
fn initial_step<S: System + ?Sized, const N: usize>(
    w: &mut Work<'_, S, N>,
    t: f64,
    y: &[f64],
    tol: Tolerances,
    span: f64,
) -> f64 {
    let n = y.len();
    let scale: Vec<f64> = y.iter().map(|v| tol.atol + tol.rtol * v.abs()).collect();
    let norm = |v: &[f64]| {
        (v.iter().zip(&scale).map(|(a, s)| (a / s).powi(2)).sum::<f64>() / n.max(1) as f64).sqrt()
    };
    let f0 = w.stage(0).to_vec();
    let d0 = norm(y);
    let d1 = norm(&f0);
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
    for m in 0..n {
        w.tmp[m] = y[m] + h0 * f0[m];
    }
    let mut f1 = vec![0.0; n];
    w.sys.rhs(t + h0, &w.tmp, &mut f1);
    w.stats.rhs_evals += 1;
    let diff: Vec<f64> = f1.iter().zip(&f0).map(|(a, b)| a - b).collect();
    let d2 = norm(&diff) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / (w.tab.order as f64 + 1.0))
    };
    (100.0 * h0).min(h1).min(span.abs().max(f64::MIN_POSITIVE))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pi_control_matches_the_power_law() {
        let control = StepControl { beta: 0.04, min_factor: 0.2, max_factor: 10.0 };
        let mut pi = PiControl::new(5, control);
        let alpha = 1.0 / 5.0 - 0.75 * 0.04;
        let mut err_old: f64 = 1e-4;
        for err in [0.5f64, 1e-3, 1e-12, 0.9, 1.0, 0.0] {
            let want = (SAFETY * err.max(1e-10).powf(-alpha) * err_old.powf(0.04)).clamp(0.2, 10.0);
            let got = pi.accepted(err);
            assert!((got - want).abs() <= 1e-13 * want, "err {err}: {got} vs {want}");
            err_old = err.max(1e-4);
        }
        let rejected = pi.rejected(4.0);
        assert!((rejected - (SAFETY * 4.0f64.powf(-alpha)).max(0.2)).abs() < 1e-14);
        assert_eq!(pi.rejected(f64::NAN), 0.2);
        assert_eq!(pi.rejected(f64::INFINITY), 0.2);
    }

    /// A damped, driven pendulum pair: nonlinear, time-dependent, two components.
    struct Pendulums;
    impl System for Pendulums {
        fn dim(&self) -> usize {
            4
        }
        fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[2];
            dy[1] = y[3];
            dy[2] = -y[0].sin() - 0.1 * y[2] + 0.3 * (y[1] - y[0]) + 0.2 * t.cos();
            dy[3] = -2.0 * y[1].sin() - 0.3 * (y[1] - y[0]);
        }
    }

    #[test]
    fn unrolled_and_general_steps_give_identical_numbers() {
        use crate::ode::tableau::{DOP853, DOPRI5, RK4};
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
                    Ok(())
                };
                let stats = if fixed {
                    integrate_n::<_, 4>(&Pendulums, 0.0, &y0, &times, method, record)
                } else {
                    integrate_n::<_, 0>(&Pendulums, 0.0, &y0, &times, method, record)
                };
                (stats.unwrap(), rows)
            };
            let (unrolled, general) = (run(true), run(false));
            assert_eq!(unrolled.0, general.0);
            assert!(unrolled
                .1
                .iter()
                .flatten()
                .zip(general.1.iter().flatten())
                .all(|(a, b)| a.to_bits() == b.to_bits()));
            assert!(unrolled.0.steps > 10);
        }
    }

    #[test]
    fn no_step_grows_right_after_a_rejection() {
        let step = |after_rejection| AcceptedStep {
            h: 0.1,
            t_new: 0.1,
            err: 0.5,
            at_target: false,
            after_rejection,
        };
        assert_eq!(step(true).next_h(1.5), 0.1);
        assert_eq!(step(true).next_h(0.5), 0.05);
        assert!((step(false).next_h(1.5) - 0.15).abs() < 1e-15);
    }
}
