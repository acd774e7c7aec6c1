//! The Taylor method. In: a [`System`] that gives its own Taylor coefficients
//! ([`System::taylor`], generated from the model's equations), `(t0, y0)` and tolerances; out:
//! one step per [`Stepper::step`], values anywhere in the last step from the Taylor polynomial
//! itself ([`Stepper::interpolate`]), and the cost in [`Stats`].
//!
//! Order and step follow Jorba and Zou (2005), per component, for any order. Each component's
//! tolerance is `tol_i = atol + rtol |y_i|` (as the Runge-Kutta pairs weigh it) and
//! `eps = min_i tol_i / max(1, |y_i|)`. The order is theirs, `-ln(eps) / 2 + 1`, plus
//! [`ORDER_LEAD`], taken to the nearest order the system computes straight-line (rounded
//! when it has none). The step is
//! `h = min(rho_(p-1), rho_p) (eps / e^2)^(1/p) exp(-0.7 / (p - 1))` with
//! `rho_k = min_i (s_i / |y_ik|)^(1/k)`, `s_i = tol_i / eps`: term `p` stays near `tol_i / e^2`
//! in every component (heyoka takes one max norm over all, which lets a large component set the
//! error of small ones), and at their order it is their rule. Every step is accepted: the
//! estimate is made before the step, from the series itself.

use super::stages::Stats;
use super::stepper::{check_finite, Stepper, StopReason, DEFAULT_MAX_STEPS};
use super::{OdeError, System, TaylorWork, Tolerances};
/// The lowest order a step takes (the step-size rule reads orders `p - 1` and `p`).
const MIN_ORDER: usize = 2;
/// The highest order a step takes.
const MAX_ORDER: usize = kane_model::runtime::TAYLOR_MAX_ORDER;
/// How far above Jorba and Zou's order the stepper aims. Theirs minimises the cost of the
/// coefficients alone; a step also costs the step-size rule, the series' evaluation and the
/// linear operations, so fewer, longer steps of a higher order are cheaper (chosen from sweeps
/// of leads 0-7 at equal error on the top and the gimbal against heyoka: 4 with straight-line
/// order 14, 5 without it).
const ORDER_LEAD: f64 = 4.0;

/// The order to take where order `p` (not an integer) is best: the nearest of the orders
/// whose coefficients the system computes straight-line (`straight`, much faster than the
/// others; the cost per unit time is flat near its minimum), else `p` rounded.
fn straight_line_order(p: f64, straight: &[usize]) -> usize {
    let distance = |o: &usize| (*o as f64 - p).abs();
    straight.iter().copied().min_by(|a, b| distance(a).total_cmp(&distance(b))).unwrap_or(p.round() as usize)
}

/// A Taylor-method stepper for `sys`.
pub struct TaylorStepper<'a, S: System + ?Sized> {
    sys: &'a S,
    tol: Tolerances,
    t: f64,
    y: Vec<f64>,
    /// The last step: where it began, its size, its order and the coefficients there
    /// (state-major, `order + 1` per state).
    t_prev: f64,
    h_prev: f64,
    order: usize,
    coeffs: Vec<f64>,
    /// Each component's `eps` relative to its tolerance, `eps / (atol + rtol |y_i|)`.
    inverse_scales: Vec<f64>,
    /// `eps`, the smallest of the components' tolerances relative to `max(1, |y_i|)`, and its
    /// logarithm.
    eps: f64,
    ln_eps: f64,
    work: TaylorWork,
    stop: Option<f64>,
    max_steps: usize,
    stats: Stats,
}

impl<'a, S: System + ?Sized> TaylorStepper<'a, S> {
    /// A stepper at `(t0, y0)`. An error when `y0` is not finite or not of the system's
    /// dimension, or when the system has no Taylor coefficients.
    pub fn new(sys: &'a S, t0: f64, y0: &[f64], tol: Tolerances) -> Result<Self, OdeError> {
        let n = sys.dim();
        if y0.len() != n {
            return Err(OdeError::DimensionMismatch { expected: n, found: y0.len() });
        }
        check_finite(t0, y0)?;
        let mut stepper = TaylorStepper {
            sys,
            tol,
            t: t0,
            y: y0.to_vec(),
            t_prev: t0,
            h_prev: 0.0,
            order: 0,
            coeffs: y0.to_vec(),
            inverse_scales: Vec::new(),
            eps: f64::NAN,
            ln_eps: 0.0,
            work: Vec::new(),
            stop: None,
            max_steps: DEFAULT_MAX_STEPS,
            stats: Stats::default(),
        };
        // The coefficients at the start: the check that the system has them, and the first
        // step's (unless a projection moves the state first).
        stepper.expand()?;
        Ok(stepper)
    }

    /// The order for the tolerances at the current state: `eps` the smallest of the components'
    /// tolerances `atol + rtol |y_i|` relative to `max(1, |y_i|)`, each component's
    /// `eps / (atol + rtol |y_i|)` into `inverse_scales`; the order Jorba and Zou give `eps`,
    /// plus [`ORDER_LEAD`], taken to the nearest straight-line one.
    fn order_and_scales(&mut self) -> usize {
        let Tolerances { rtol, atol } = self.tol;
        self.inverse_scales.clear();
        let mut eps = f64::INFINITY;
        for v in &self.y {
            let tol = atol + rtol * v.abs();
            self.inverse_scales.push(tol);
            eps = eps.min(tol / v.abs().max(1.0));
        }
        self.inverse_scales.iter_mut().for_each(|s| *s = eps / *s);
        if eps == self.eps {
            // Often so (a component at zero sets it): the logarithm and the order are known.
            return self.order;
        }
        self.eps = eps;
        self.ln_eps = eps.ln();
        let p = -self.ln_eps / 2.0 + 1.0 + ORDER_LEAD;
        if p.is_finite() {
            straight_line_order(p.max(MIN_ORDER as f64), self.sys.taylor_straight_line())
                .clamp(MIN_ORDER, MAX_ORDER)
        } else {
            MAX_ORDER
        }
    }

    /// The coefficients at the current state into `coeffs`, at the order the tolerances ask.
    fn expand(&mut self) -> Result<(), OdeError> {
        let p = self.order_and_scales();
        let n = self.y.len();
        self.coeffs.resize(n * (p + 1), 0.0);
        if !self.sys.taylor(self.t, &self.y, p, &mut self.coeffs, &mut self.work) {
            return Err(OdeError::NoTaylorCoefficients);
        }
        self.order = p;
        self.stats.rhs_evals += p;
        Ok(())
    }

    /// The step the last two coefficients allow: Jorba and Zou's rule for any order `p`,
    /// `h = min(rho_(p-1), rho_p) (eps / e^2)^(1/p) exp(-0.7 / (p - 1))` with
    /// `rho_k = min_i (scale_i / |c_ik|)^(1/k)`, `scale_i = (atol + rtol |y_i|) / eps`, so term
    /// `p` is about `tol_i / e^2` in every component (at their own order,
    /// `(eps / e^2)^(1/p) = 1 / e^2`: their rule exactly). Computed in logarithms.
    fn step_size(&self) -> f64 {
        let p = self.order;
        let n1 = p + 1;
        // ln rho_k = -ln(max_i |c_ik| / scale_i) / k.
        let ln_rho = |k: usize| {
            let norm = self
                .inverse_scales
                .iter()
                .enumerate()
                .fold(0.0f64, |m, (i, s)| m.max(s * self.coeffs[i * n1 + k].abs()));
            -norm.ln() / k as f64
        };
        let pf = p as f64;
        let ln_rho_m = ln_rho(p - 1).min(ln_rho(p));
        (ln_rho_m + (self.ln_eps - 2.0) / pf - 0.7 / (pf - 1.0)).exp()
    }

    /// The Taylor polynomial of the last expansion at `tau` past its start, into `out`.
    fn evaluate(&self, tau: f64, out: &mut [f64]) {
        for (o, c) in out.iter_mut().zip(self.coeffs.chunks_exact(self.order + 1)) {
            *o = polynomial(c, tau);
        }
    }
}

impl<S: System + ?Sized> Stepper for TaylorStepper<'_, S> {
    fn set_stop_time(&mut self, t_stop: f64) {
        self.stop = Some(t_stop);
    }

    fn set_max_steps(&mut self, max: usize) {
        self.max_steps = max;
    }

    fn t(&self) -> f64 {
        self.t
    }

    fn y(&self) -> &[f64] {
        &self.y
    }

    fn step_start(&self) -> f64 {
        self.t_prev
    }

    /// The cost so far: steps, and in `rhs_evals` the coefficient passes (order `p` takes `p`;
    /// pass 0 is one evaluation of the right-hand side, pass `k` up to `k` times its products).
    fn stats(&self) -> Stats {
        self.stats
    }

    /// Takes one step, or none when the stepper is at the stop time already; first the system
    /// may project the state.
    fn step(&mut self) -> Result<StopReason, OdeError> {
        if self.stop.is_some_and(|stop| self.t >= stop) {
            return Ok(StopReason::StopTimeReached);
        }
        if self.stats.steps >= self.max_steps {
            return Err(OdeError::TooManySteps { time: self.t, max: self.max_steps });
        }
        let projected = self.sys.project(&mut self.y);
        // The first step's coefficients were computed by `new` (unless the state moved since).
        let fresh = self.stats.steps == 0 && !projected;
        if !fresh {
            self.expand()?;
        }
        let mut h = self.step_size();
        let target = self.stop;
        if !h.is_finite() {
            // A polynomial solution: nothing bounds the step but the way to go.
            h = target.map_or(1.0, |end| end - self.t);
        }
        let lands = target.filter(|end| self.t + h >= *end);
        if let Some(end) = lands {
            h = end - self.t;
        }
        if self.t + h <= self.t {
            return Err(OdeError::StepSizeUnderflow { time: self.t, step: h });
        }
        let t_new = lands.unwrap_or(self.t + h);
        let mut y_new = std::mem::take(&mut self.y);
        self.evaluate(h, &mut y_new);
        check_finite(t_new, &y_new)?;
        self.y = y_new;
        (self.t_prev, self.h_prev, self.t) = (self.t, h, t_new);
        self.stats.steps += 1;
        let reached = self.stop.is_some_and(|stop| t_new >= stop);
        Ok(if reached { StopReason::StopTimeReached } else { StopReason::StepTaken })
    }

    /// The state at `t` in the last step into `out`, from its Taylor polynomial (at its end,
    /// the step's own value). An error outside the step or for `out` of the wrong length.
    fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), OdeError> {
        if out.len() != self.y.len() {
            return Err(OdeError::DimensionMismatch { expected: self.y.len(), found: out.len() });
        }
        if t == self.t {
            out.copy_from_slice(&self.y);
            return Ok(());
        }
        if !(self.t_prev <= t && t < self.t) {
            return Err(OdeError::OutsideStep { t, start: self.t_prev, end: self.t });
        }
        self.evaluate(t - self.t_prev, out);
        Ok(())
    }
}

/// `sum_k c[k] x^k` as `E(x^2) + x O(x^2)`, the even and the odd coefficients each by Horner's
/// rule: two independent chains of half the length (about half the time of one chain).
fn polynomial(c: &[f64], x: f64) -> f64 {
    let x2 = x * x;
    let pairs = c.chunks_exact(2);
    let mut even = pairs.remainder().first().copied().unwrap_or(0.0);
    let mut odd = 0.0;
    for pair in pairs.rev() {
        even = even * x2 + pair[0];
        odd = odd * x2 + pair[1];
    }
    even + x * odd
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::test_problems::{ClosedForm, NoStraightLine, Oscillator, WithoutTaylor};
    use crate::ode::{Integration, Method, Stepper};
    use std::ops::ControlFlow;

    /// The oscillator computing every order alike (no straight-line orders).
    const LOOP_ONLY: NoStraightLine<Oscillator> = NoStraightLine(Oscillator);
    /// The same equations without Taylor coefficients.
    const PLAIN: WithoutTaylor<Oscillator> = WithoutTaylor(Oscillator);

    fn run(tol: f64, times: &[f64]) -> (Vec<Vec<f64>>, Stats) {
        let mut rows = Vec::new();
        let method = Method::Taylor(Tolerances { rtol: tol, atol: tol });
        let stats = Integration::new(&Oscillator, 0.0, &[1.0, 0.5], method)
            .run(times, |_, y| {
                rows.push(y.to_vec());
                ControlFlow::Continue(())
            })
            .unwrap()
            .stats;
        (rows, stats)
    }

    #[test]
    fn errors_follow_the_tolerance_and_dense_output_is_as_accurate() {
        let times: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.02).collect();
        for tol in [1e-6, 1e-9, 1e-12, 1e-15] {
            let (rows, stats) = run(tol, &times);
            let worst = times.iter().zip(&rows).fold(0.0f64, |m, (t, y)| {
                let x = Oscillator.solution(0.0, &[1.0, 0.5], *t)[0];
                m.max((y[0] - x).abs())
            });
            // 20 time units: the global error is a few steps' local errors.
            assert!(worst < 30.0 * tol.max(1e-14), "tol {tol:e}: error {worst:e}");
            assert!(stats.steps < 100, "tol {tol:e}: {} steps", stats.steps);
            assert!(stats.rhs_evals >= stats.steps * MIN_ORDER);
        }
    }

    #[test]
    fn the_order_follows_the_tolerance() {
        let mut s =
            TaylorStepper::new(&Oscillator, 0.0, &[1.0, 0.0], Tolerances { rtol: 1e-12, atol: 1e-12 })
                .unwrap();
        // -ln(1e-12) / 2 + 1 + ORDER_LEAD = 18.8: the nearest straight-line order is 20.
        assert_eq!(s.order, 20);
        s.set_stop_time(1.0);
        while s.step().unwrap() == StopReason::StepTaken {}
        assert_eq!(s.t(), 1.0);
        let mut y = [0.0; 2];
        assert!(s.interpolate(2.0, &mut y).is_err());
    }

    #[test]
    fn polynomials_of_odd_and_even_length_are_summed_whole() {
        let x = 0.7f64;
        for n in 0..6 {
            let c: Vec<f64> = (0..n).map(|k| 1.0 + k as f64).collect();
            let horner = c.iter().rev().fold(0.0, |acc, ck| acc * x + ck);
            assert!((polynomial(&c, x) - horner).abs() <= 1e-15 * horner.abs().max(1.0), "length {n}");
        }
    }

    #[test]
    fn orders_go_to_the_nearest_straight_line_one() {
        let straight = kane_model::runtime::TAYLOR_UNROLLED_ORDERS;
        assert_eq!(straight_line_order(12.9, straight), 12);
        assert_eq!(straight_line_order(13.5, straight), 14);
        assert_eq!(straight_line_order(15.5, straight), 16);
        assert_eq!(straight_line_order(6.0, straight), 8);
        assert_eq!(straight_line_order(2.0, straight), 8);
        assert_eq!(straight_line_order(23.5, straight), 20);
        assert_eq!(straight_line_order(13.4, &[]), 13);
    }

    #[test]
    fn a_system_without_straight_line_orders_takes_the_order_it_needs() {
        let tol = Tolerances { rtol: 1e-12, atol: 1e-12 };
        let mut s = TaylorStepper::new(&LOOP_ONLY, 0.0, &[1.0, 0.0], tol).unwrap();
        // -ln(1e-12) / 2 + 1 + ORDER_LEAD = 18.8, rounded.
        assert_eq!(s.order, 19);
        s.set_stop_time(2.0);
        while s.step().unwrap() == StopReason::StepTaken {}
        let mut y = [0.0; 2];
        s.interpolate(2.0, &mut y).unwrap();
        assert!((y[0] - 2.0f64.cos()).abs() < 1e-11, "{}", y[0]);
    }

    #[test]
    fn a_system_without_coefficients_is_a_clear_error() {
        let method = Method::Taylor(Tolerances { rtol: 1e-9, atol: 1e-9 });
        let err = Integration::new(&PLAIN, 0.0, &[1.0, 0.0], method)
            .run(&[1.0], |_, _| ControlFlow::Continue(()))
            .unwrap_err();
        assert_eq!(err, OdeError::NoTaylorCoefficients);
        assert!(err.to_string().contains("use another method"), "{err}");
        let erk = crate::ode::ErkStepper::new(&PLAIN, 0.0, &[1.0, 0.0], method);
        assert!(matches!(erk, Err(OdeError::NotRungeKutta)));
    }
}
