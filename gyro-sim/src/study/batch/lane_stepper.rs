//! Lock-step integration of lanes: in come a system over [`Lanes`], a start, an end time, an
//! embedded tableau and tolerances; out goes the state at the end time (every lane) and the
//! cost. One step size for all lanes: a step is accepted when every lane's error estimate (the
//! scalar stepper's norm, lane by lane) is within tolerance, so each lane is at least as
//! accurate as alone, at the price of the smallest lane's steps.

use super::lanes::Lanes;
use crate::ode::tableau::Tableau;
use crate::ode::{blended_norm, OdeError, PiControl, Stats, Tolerances};

/// A system `y' = f(t, y)` whose every number carries `N` lanes.
pub trait LaneSystem<const N: usize> {
    /// Number of states.
    fn dim(&self) -> usize;
    /// Writes `f(t, y)` into `dy`.
    fn rhs(&self, t: f64, y: &[Lanes<N>], dy: &mut [Lanes<N>]);
}

/// The stages and scratch of one step.
struct Stages<const N: usize> {
    k: Vec<Vec<Lanes<N>>>,
    tmp: Vec<Lanes<N>>,
    ynew: Vec<Lanes<N>>,
}

/// Integrates `sys` from `(t0, y0)` to `t_end` with the embedded pair `tab`; an error when
/// `tab` has no error estimate or a step underflows.
pub fn integrate_lanes<S: LaneSystem<N>, const N: usize>(
    sys: &S,
    t0: f64,
    y0: &[Lanes<N>],
    t_end: f64,
    tab: &Tableau,
    tol: Tolerances,
) -> Result<(Vec<Lanes<N>>, Stats), OdeError> {
    let n = sys.dim();
    let s = tab.c.len();
    let zero = vec![Lanes::splat(0.0); n];
    let mut st = Stages { k: vec![zero.clone(); s], tmp: zero.clone(), ynew: zero };
    let mut stats = Stats::default();
    let (mut t, mut y) = (t0, y0.to_vec());
    let mut control = PiControl::new(tab.order, tab.control);
    let mut h = (t_end - t0) * 1e-3;
    sys.rhs(t, &y, &mut st.k[0]);
    stats.rhs_evals += 1;
    while t < t_end {
        let last = h >= (t_end - t) * (1.0 - 1e-12);
        let h_try = if last { t_end - t } else { h };
        if h_try < 16.0 * f64::EPSILON * t.abs().max(1.0) {
            return Err(OdeError::StepSizeUnderflow { time: t, step: h_try });
        }
        stats.rhs_evals += stages(sys, tab, t, &y, h_try, &mut st);
        let err = error(tab, &y, &st, h_try, tol)?;
        if err > 1.0 || !err.is_finite() {
            h = h_try * control.rejected(err);
            stats.rejected += 1;
            continue;
        }
        t = if last { t_end } else { t + h_try };
        std::mem::swap(&mut y, &mut st.ynew);
        h = h_try * control.accepted(err);
        stats.steps += 1;
        if tab.fsal && tab.stages_before_error() == s {
            st.k.swap(0, s - 1);
        } else {
            sys.rhs(t, &y, &mut st.k[0]);
            stats.rhs_evals += 1;
        }
    }
    Ok((y, stats))
}

/// The stages after the first and the new state; the number of evaluations.
fn stages<S: LaneSystem<N>, const N: usize>(
    sys: &S,
    tab: &Tableau,
    t: f64,
    y: &[Lanes<N>],
    h: f64,
    st: &mut Stages<N>,
) -> usize {
    let used = tab.stages_before_error();
    for i in 1..used {
        combine(&st.k, y, h, tab.a[i], &mut st.tmp);
        sys.rhs(t + tab.c[i] * h, &st.tmp, &mut st.k[i]);
    }
    combine(&st.k, y, h, tab.b, &mut st.ynew);
    used - 1
}

/// `out = y + h sum_j w_j k_j`.
#[inline(always)]
fn combine<const N: usize>(k: &[Vec<Lanes<N>>], y: &[Lanes<N>], h: f64, w: &[f64], out: &mut [Lanes<N>]) {
    out.copy_from_slice(y);
    for (j, wj) in w.iter().enumerate() {
        if *wj == 0.0 {
            continue;
        }
        let c = Lanes::splat(h * wj);
        for (o, kj) in out.iter_mut().zip(&k[j]) {
            *o = *o + c * *kj;
        }
    }
}

/// The largest over lanes of the scalar stepper's error norm ([`blended_norm`]).
fn error<const N: usize>(
    tab: &Tableau,
    y: &[Lanes<N>],
    st: &Stages<N>,
    h: f64,
    tol: Tolerances,
) -> Result<f64, OdeError> {
    let e5 = tab.e.ok_or(OdeError::NoErrorEstimate { method: tab.name })?;
    let (n, used) = (y.len(), tab.stages_before_error());
    let mut worst: f64 = 0.0;
    for lane in 0..N {
        let (mut sum5, mut sum3) = (0.0, 0.0);
        for m in 0..n {
            let inv = 1.0 / (tol.atol + tol.rtol * y[m].0[lane].abs().max(st.ynew[m].0[lane].abs()));
            let weighted = |w: &[f64]| {
                w.iter().zip(&st.k).take(used).map(|(wj, kj)| wj * kj[m].0[lane]).sum::<f64>() * inv
            };
            sum5 += weighted(e5).powi(2);
            if let Some(e3) = tab.e3 {
                sum3 += weighted(e3).powi(2);
            }
        }
        let err = blended_norm(h, n, sum5, tab.e3.map(|_| sum3));
        worst = worst.max(if err.is_nan() { f64::INFINITY } else { err });
    }
    Ok(worst)
}
