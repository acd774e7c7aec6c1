//! Explicit Runge-Kutta integration: adaptive steps with PI control for embedded pairs, fixed
//! steps otherwise. Pairs with a continuous extension interpolate output times inside steps;
//! others shorten a step to land on them. Either way the value at `t_final` is a step's own value
//! at `t_final`, not at a sum of step sizes.

// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]

use super::tableau::{Dense, Tableau};
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
/// PI controller (Hairer, Norsett, Wanner, Solving ODEs I, section II.4): beta = 0.04 for dopri5.
const BETA: f64 = 0.04;
const SAFETY: f64 = 0.9;

/// PI step-size control `h_new = h * SAFETY * err^-alpha * err_old^beta` with
/// `alpha = 1/order - 0.75 beta` (Hairer's DOPRI5/DOP853), in logarithms: one `ln` and one
/// `exp` per accepted step instead of two `powf`.
struct PiControl {
    alpha: f64,
    inv_order: f64,
    ln_err_old: f64,
}

impl PiControl {
    fn new(order: u32) -> Self {
        let inv_order = 1.0 / order as f64;
        Self { alpha: inv_order - 0.75 * BETA, inv_order, ln_err_old: 1e-4f64.ln() }
    }

    /// The step-size factor after an accepted step with error `err <= 1`.
    fn accepted(&mut self, err: f64) -> f64 {
        let ln_err = err.max(1e-10).ln();
        let fac = (-self.alpha * ln_err + BETA * self.ln_err_old).exp();
        self.ln_err_old = ln_err.max(1e-4f64.ln());
        (SAFETY * fac).clamp(0.2, 10.0)
    }

    /// The step-size factor after a rejected step (`err > 1` or not finite).
    fn rejected(&self, err: f64) -> f64 {
        if err.is_finite() {
            (SAFETY * (-self.inv_order * err.ln()).exp()).max(0.2)
        } else {
            0.2
        }
    }
}

struct Work<'a, S: System + ?Sized> {
    sys: &'a S,
    tab: &'static Tableau,
    n: usize,
    /// Stage derivatives, stage-major: stage j is `k[j * n..(j + 1) * n]`.
    k: Vec<f64>,
    tmp: Vec<f64>,
    ynew: Vec<f64>,
    scale: Vec<f64>,
    /// The septic interpolant's seven coefficient vectors for the last accepted step.
    dense_coef: Vec<f64>,
    stats: Stats,
}

impl<S: System + ?Sized> Work<'_, S> {
    fn stage(&self, j: usize) -> &[f64] {
        &self.k[j * self.n..(j + 1) * self.n]
    }

    /// `out = y + h * sum_j w_j k_j`, skipping zero weights; contiguous loops.
    fn combine(k: &[f64], n: usize, y: &[f64], h: f64, w: &[f64], out: &mut [f64]) {
        out.copy_from_slice(y);
        Self::accumulate(k, n, h, w, out);
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
        let n = self.n;
        for i in 1..self.tab.c.len() {
            Self::combine(&self.k, n, y, h, self.tab.a[i], &mut self.tmp);
            let (_, rest) = self.k.split_at_mut(i * n);
            self.sys.rhs(t + self.tab.c[i] * h, &self.tmp, &mut rest[..n]);
            self.stats.rhs_evals += 1;
        }
        Self::combine(&self.k, n, y, h, self.tab.b, &mut self.ynew);
    }

    /// The local error estimate relative to `atol + rtol * max(|y|, |ynew|)`: an RMS for
    /// embedded pairs; for DOP853, Hairer's blend of its fifth- and third-order estimates,
    /// `|h| e5^2 / sqrt(n (e5^2 + 0.01 e3^2))`.
    fn error(&mut self, y: &[f64], h: f64, e: &[f64], tol: Tolerances) -> f64 {
        let n = self.n;
        // tmp = sum_j e_j k_j (h = 1: the step size multiplies the norm below).
        self.tmp.fill(0.0);
        Self::accumulate(&self.k, n, 1.0, e, &mut self.tmp);
        let mut sum5 = 0.0;
        for m in 0..n {
            self.scale[m] = tol.atol + tol.rtol * y[m].abs().max(self.ynew[m].abs());
            let r = self.tmp[m] / self.scale[m];
            sum5 += r * r;
        }
        match self.tab.e3 {
            None => h.abs() * (sum5 / n.max(1) as f64).sqrt(),
            Some(e3) => {
                self.tmp.fill(0.0);
                Self::accumulate(&self.k, n, 1.0, e3, &mut self.tmp);
                let sum3: f64 = self.tmp.iter().zip(&self.scale).map(|(v, s)| (v / s) * (v / s)).sum();
                if sum5 == 0.0 && sum3 == 0.0 {
                    0.0
                } else {
                    h.abs() * sum5 / (n.max(1) as f64 * (sum5 + 0.01 * sum3)).sqrt()
                }
            }
        }
    }

    /// Prepares interpolation in the accepted step `y0 -> ynew` of size `h` from `t` (before
    /// the stages are reused): for the septic extension, its three extra stages and the
    /// coefficient vectors of Hairer's `contd8`.
    fn prepare_dense(&mut self, t: f64, y0: &[f64], h: f64, dense: &Dense) {
        let Dense::Septic { c, a, d } = dense else { return };
        let (n, s) = (self.n, self.tab.c.len());
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
        let n = self.n;
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

    /// The stage at the start of the next step: reused (FSAL) or computed.
    fn next_start(&mut self, t: f64) {
        let (n, s) = (self.n, self.tab.c.len());
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
    mut out: impl FnMut(f64, &[f64]) -> Result<(), String>,
) -> Result<Stats, OdeError> {
    let n = sys.dim();
    let tab = match method {
        Method::Adaptive(t, _) | Method::Fixed(t, _) => t,
    };
    let (extra_stages, coef_rows) = match &tab.dense {
        Some(Dense::Septic { c, d, .. }) => (c.len(), 3 + d.len()),
        _ => (0, 0),
    };
    let mut w = Work {
        sys,
        tab,
        n,
        k: vec![0.0; n * (tab.c.len() + extra_stages)],
        tmp: vec![0.0; n],
        ynew: vec![0.0; n],
        scale: vec![0.0; n],
        dense_coef: vec![0.0; n * coef_rows],
        stats: Stats::default(),
    };
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
    let mut control = PiControl::new(tab.order);
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
                    let proposed = step.h * control.accepted(step.err);
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
}

/// Tries `h` (or the rest of the way to `target` when `h` nearly reaches it), shrinking the step
/// after each rejection until the error estimate is at most 1.
fn accepted_step<S: System + ?Sized>(
    w: &mut Work<'_, S>,
    t: f64,
    y: &[f64],
    h: f64,
    target: f64,
    tol: Tolerances,
    control: &PiControl,
) -> Result<AcceptedStep, OdeError> {
    let e = w.tab.e.unwrap_or(&[]);
    let remaining = target - t;
    let (mut h_try, mut at_target) =
        if h >= remaining * (1.0 - 1e-12) { (remaining, true) } else { (h, false) };
    loop {
        if h_try < 16.0 * f64::EPSILON * t.abs().max(1.0) {
            return Err(OdeError::StepSizeUnderflow { time: t, step: h_try });
        }
        w.step(t, y, h_try);
        let err = w.error(y, h_try, e, tol);
        if err <= 1.0 {
            let t_new = if at_target { target } else { t + h_try };
            return Ok(AcceptedStep { h: h_try, t_new, err, at_target });
        }
        h_try *= control.rejected(err);
        at_target = false;
        w.stats.rejected += 1;
    }
}

/// Adaptive stepping to the last output time only, with outputs in between from the dense
/// interpolant; the last output is the last step's own value, at `t_final` exactly.
#[allow(clippy::too_many_arguments)]
fn dense_run<S: System + ?Sized>(
    w: &mut Work<'_, S>,
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
    let mut y_out = vec![0.0; w.n];
    let mut control = PiControl::new(w.tab.order);
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
        h = step.h * control.accepted(step.err);
    }
    Ok(w.stats)
}

/// Hairer's starting step: a step whose explicit-Euler error is about the tolerance.
fn initial_step<S: System + ?Sized>(
    w: &mut Work<'_, S>,
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
        let mut control = PiControl::new(8);
        let alpha = 1.0 / 8.0 - 0.75 * BETA;
        let mut err_old: f64 = 1e-4;
        for err in [0.5f64, 1e-3, 1e-12, 0.9, 1.0, 0.0] {
            let want = (SAFETY * err.max(1e-10).powf(-alpha) * err_old.powf(BETA)).clamp(0.2, 10.0);
            let got = control.accepted(err);
            assert!((got - want).abs() <= 1e-13 * want, "err {err}: {got} vs {want}");
            err_old = err.max(1e-4);
        }
        let rejected = control.rejected(4.0);
        assert!((rejected - (SAFETY * 4.0f64.powf(-0.125)).max(0.2)).abs() < 1e-14);
        assert_eq!(control.rejected(f64::NAN), 0.2);
        assert_eq!(control.rejected(f64::INFINITY), 0.2);
    }
}
