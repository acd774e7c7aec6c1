//! Explicit Runge-Kutta integration: adaptive steps with PI control for embedded pairs, fixed
//! steps otherwise. Output times are hit exactly (a step is shortened to land on them), so the
//! value at `t_final` is at `t_final`, not at a sum of step sizes.

// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]

use super::tableau::Tableau;
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

struct Work<'a, S: System + ?Sized> {
    sys: &'a S,
    tab: &'static Tableau,
    k: Vec<Vec<f64>>,
    tmp: Vec<f64>,
    ynew: Vec<f64>,
    stats: Stats,
}

impl<S: System + ?Sized> Work<'_, S> {
    /// One step of size `h` from `(t, y)`, with `k[0] = f(t, y)`: fills `ynew` and the stages.
    fn step(&mut self, t: f64, y: &[f64], h: f64) {
        let n = y.len();
        for i in 1..self.tab.c.len() {
            let row = self.tab.a[i];
            for m in 0..n {
                let mut acc = 0.0;
                for (j, a) in row.iter().enumerate() {
                    if *a != 0.0 {
                        acc += a * self.k[j][m];
                    }
                }
                self.tmp[m] = y[m] + h * acc;
            }
            self.sys.rhs(t + self.tab.c[i] * h, &self.tmp, &mut self.k[i]);
            self.stats.rhs_evals += 1;
        }
        for m in 0..n {
            let mut acc = 0.0;
            for (j, b) in self.tab.b.iter().enumerate() {
                if *b != 0.0 {
                    acc += b * self.k[j][m];
                }
            }
            self.ynew[m] = y[m] + h * acc;
        }
    }

    /// RMS of the local error estimate over `atol + rtol * max(|y|, |ynew|)`.
    fn error(&self, y: &[f64], h: f64, e: &[f64], tol: Tolerances) -> f64 {
        let n = y.len();
        let mut sum = 0.0;
        for m in 0..n {
            let mut est = 0.0;
            for (j, ej) in e.iter().enumerate() {
                if *ej != 0.0 {
                    est += ej * self.k[j][m];
                }
            }
            let scale = tol.atol + tol.rtol * y[m].abs().max(self.ynew[m].abs());
            let r = h * est / scale;
            sum += r * r;
        }
        (sum / n.max(1) as f64).sqrt()
    }

    /// The stage at the start of the next step: reused (FSAL) or computed.
    fn next_start(&mut self, t: f64) {
        let s = self.tab.c.len();
        if self.tab.fsal {
            self.k.swap(0, s - 1);
        } else {
            self.sys.rhs(t, &self.ynew, &mut self.k[0]);
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
    let mut w = Work {
        sys,
        tab,
        k: vec![vec![0.0; n]; tab.c.len()],
        tmp: vec![0.0; n],
        ynew: vec![0.0; n],
        stats: Stats::default(),
    };
    let mut t = t0;
    let mut y = y0.to_vec();
    check_finite(t, &y)?;
    sys.rhs(t, &y, &mut w.k[0]);
    w.stats.rhs_evals += 1;
    let mut h = match method {
        Method::Adaptive(_, tol) => {
            initial_step(&mut w, t, &y, tol, times.last().copied().unwrap_or(t0) - t0)
        }
        Method::Fixed(_, step) => step,
    };
    let mut err_old: f64 = 1e-4;
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
                    let e = tab.e.unwrap_or(&[]);
                    let remaining = target - t;
                    let (mut h_try, mut last) =
                        if h >= remaining * (1.0 - 1e-12) { (remaining, true) } else { (h, false) };
                    loop {
                        if h_try < 16.0 * f64::EPSILON * t.abs().max(1.0) {
                            return Err(OdeError::StepSizeUnderflow { time: t, step: h_try });
                        }
                        w.step(t, &y, h_try);
                        let err = w.error(&y, h_try, e, tol);
                        if err <= 1.0 {
                            t = if last { target } else { t + h_try };
                            check_finite(t, &w.ynew)?;
                            y.copy_from_slice(&w.ynew);
                            w.next_start(t);
                            w.stats.steps += 1;
                            // PI control: h err^-alpha err_old^beta, alpha = 1/order - 0.75 beta.
                            let alpha = 1.0 / tab.order as f64 - 0.75 * BETA;
                            let fac =
                                (SAFETY * err.max(1e-10).powf(-alpha) * err_old.powf(BETA)).clamp(0.2, 10.0);
                            let proposed = h_try * fac;
                            // A step shortened to land on an output time does not shrink the next.
                            h = if last { proposed.max(h) } else { proposed };
                            err_old = err.max(1e-4);
                            break;
                        }
                        if !err.is_finite() {
                            h_try *= 0.2;
                        } else {
                            h_try *= (SAFETY * err.powf(-1.0 / tab.order as f64)).max(0.2);
                        }
                        last = false;
                        w.stats.rejected += 1;
                    }
                }
            }
        }
        out(target, &y).map_err(OdeError::Output)?;
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
    let d0 = norm(y);
    let d1 = norm(&w.k[0]);
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
    for m in 0..n {
        w.tmp[m] = y[m] + h0 * w.k[0][m];
    }
    let mut f1 = vec![0.0; n];
    w.sys.rhs(t + h0, &w.tmp, &mut f1);
    w.stats.rhs_evals += 1;
    let diff: Vec<f64> = f1.iter().zip(&w.k[0]).map(|(a, b)| a - b).collect();
    let d2 = norm(&diff) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / (w.tab.order as f64 + 1.0))
    };
    (100.0 * h0).min(h1).min(span.abs().max(f64::MIN_POSITIVE))
}
