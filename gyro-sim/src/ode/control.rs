//! Step sizes of adaptive stepping. In: error estimates of tried steps and the tableau's
//! [`StepControl`]; out: the first step size, the accepted step (after any rejections) and the
//! next step size.

use super::stages::StageBuffers;
use super::tableau::StepControl;
use super::{OdeError, System, Tolerances};

const SAFETY: f64 = 0.9;

/// PI step-size control `h_new = h * SAFETY * err^-alpha * err_old^beta` with
/// `alpha = 1/order - 0.75 beta` (Hairer, Norsett, Wanner, Solving ODEs I, section IV.2; the
/// tableau's [`StepControl`]), in logarithms: one `ln` and one `exp` per accepted step instead
/// of two `powf`.
pub(crate) struct PiControl {
    alpha: f64,
    control: StepControl,
    ln_err_old: f64,
}

impl PiControl {
    /// The controller for a method of order `order` with the tableau's `control` constants.
    pub(crate) fn new(order: u32, control: StepControl) -> Self {
        let alpha = 1.0 / order as f64 - 0.75 * control.beta;
        Self { alpha, control, ln_err_old: 1e-4f64.ln() }
    }

    /// The step-size factor after an accepted step with error `err <= 1`.
    pub(crate) fn accepted(&mut self, err: f64) -> f64 {
        let ln_err = err.max(1e-10).ln();
        let fac = (-self.alpha * ln_err + self.control.beta * self.ln_err_old).exp();
        self.ln_err_old = ln_err.max(1e-4f64.ln());
        (SAFETY * fac).clamp(self.control.min_factor, self.control.max_factor)
    }

    /// The step-size factor after a rejected step (`err > 1` or not finite).
    pub(crate) fn rejected(&self, err: f64) -> f64 {
        if err.is_finite() {
            (SAFETY * (-self.alpha * err.ln()).exp()).max(self.control.min_factor)
        } else {
            self.control.min_factor
        }
    }
}

/// An accepted step from `(t, y)` toward `target`, in `w.ynew` and the stages.
pub(super) struct AcceptedStep {
    /// The step size used.
    pub(super) h: f64,
    /// Where it ends: `target` exactly when it reaches it.
    pub(super) t_new: f64,
    /// Its error estimate (at most 1).
    pub(super) err: f64,
    /// It ends at `target`.
    pub(super) at_target: bool,
    /// A larger step was rejected first.
    after_rejection: bool,
}

impl AcceptedStep {
    /// The next step size from the controller's factor; after a rejection it does not grow
    /// (Hairer's codes: a rejected step's neighbourhood is no place to be bold).
    pub(super) fn next_h(&self, factor: f64) -> f64 {
        let h = self.h * factor;
        if self.after_rejection {
            h.min(self.h)
        } else {
            h
        }
    }
}

/// Tries `h` (or the rest of the way to `target` when `h` nearly reaches it), shrinking the step
/// after each rejection until the error estimate is at most 1; stage 0 must be `f(t, y)`.
pub(super) fn accepted_step<S: System + ?Sized, const N: usize>(
    w: &mut StageBuffers<'_, S, N>,
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

/// Hairer's starting step: a step whose explicit-Euler error is about the tolerance; stage 0
/// must be `f(t, y)`. Not yet bounded by the span to integrate: see [`bound_first_step`].
pub(super) fn initial_step<S: System + ?Sized, const N: usize>(
    w: &mut StageBuffers<'_, S, N>,
    t: f64,
    y: &[f64],
    tol: Tolerances,
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
    (100.0 * h0).min(h1)
}

/// The starting step `h` no longer than `span`, the length of the whole integration (`min` is
/// exact, so bounding later gives the same number as bounding at once).
pub(super) fn bound_first_step(h: f64, span: f64) -> f64 {
    h.min(span.abs().max(f64::MIN_POSITIVE))
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

    #[test]
    fn the_first_step_bound_is_the_span() {
        assert_eq!(bound_first_step(0.5, 0.25), 0.25);
        assert_eq!(bound_first_step(0.5, -2.0), 0.5);
        assert_eq!(bound_first_step(0.5, 0.0), f64::MIN_POSITIVE);
    }
}
