//! Test problems for the integrators. In: nothing; out: small systems `y' = f(t, y)`, each with
//! its closed-form solution where one is known ([`ClosedForm`]) and its Taylor coefficients
//! where the Taylor method is tried on it. The unit tests and the integration tests take their
//! systems from here, so each is written once.

use super::{System, TaylorWork};

/// A test problem whose solution is known in closed form, so a test can measure its error.
pub trait ClosedForm: System {
    /// The solution at `t` of the problem started at `(t0, y0)`.
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64>;
}

/// The harmonic oscillator `y1' = y2`, `y2' = -y1`, with Taylor coefficients.
///
/// The coefficients follow `c_{k+1} = A c_k / (k + 1)`, every order straight-line. From
/// `(0, [0, 1])` the solution is `(sin t, cos t)`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Oscillator;

impl System for Oscillator {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
    fn taylor(&self, _t: f64, y: &[f64], order: usize, out: &mut [f64], _work: &mut TaylorWork) -> bool {
        let n1 = order + 1;
        (out[0], out[n1]) = (y[0], y[1]);
        for k in 0..order {
            let kk = (k + 1) as f64;
            (out[k + 1], out[n1 + k + 1]) = (out[n1 + k] / kk, -out[k] / kk);
        }
        true
    }
    fn taylor_straight_line(&self) -> &[usize] {
        kane_model::runtime::TAYLOR_UNROLLED_ORDERS
    }
}

impl ClosedForm for Oscillator {
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64> {
        let (s, c) = (t - t0).sin_cos();
        vec![y0[0] * c + y0[1] * s, y0[1] * c - y0[0] * s]
    }
}

/// `y' = -2 t y`, whose solution `y0 exp(t0^2 - t^2)` is a Gaussian; time enters the
/// right-hand side, so every stage's node counts. With Taylor coefficients.
#[derive(Clone, Copy, Debug, Default)]
pub struct Gaussian;

impl System for Gaussian {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = -2.0 * t * y[0];
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], _work: &mut TaylorWork) -> bool {
        // With time `t + s`: (k + 1) c_{k+1} = -2 (t c_k + c_{k-1}).
        out[0] = y[0];
        for k in 0..order {
            let before = if k == 0 { 0.0 } else { out[k - 1] };
            out[k + 1] = -2.0 * (t * out[k] + before) / (k + 1) as f64;
        }
        true
    }
}

impl ClosedForm for Gaussian {
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64> {
        vec![y0[0] * (t0 * t0 - t * t).exp()]
    }
}

/// `y' = y^2`, whose solution `y0 / (1 - y0 (t - t0))` blows up at `t0 + 1 / y0`.
#[derive(Clone, Copy, Debug, Default)]
pub struct BlowUp;

impl System for BlowUp {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[0] * y[0];
    }
}

impl ClosedForm for BlowUp {
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64> {
        vec![y0[0] / (1.0 - y0[0] * (t - t0))]
    }
}

/// Independent exponentials `y_i' = rate_i y_i`, one per rate (`[-1.0]` a decay, `[1.0]`
/// growth, zeros a system at rest).
#[derive(Clone, Copy, Debug)]
pub struct Exponential<const N: usize>(pub [f64; N]);

impl<const N: usize> System for Exponential<N> {
    fn dim(&self) -> usize {
        N
    }
    fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
        for ((d, v), rate) in dy.iter_mut().zip(y).zip(&self.0) {
            *d = rate * v;
        }
    }
}

impl<const N: usize> ClosedForm for Exponential<N> {
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64> {
        y0.iter().zip(&self.0).map(|(v, rate)| v * (rate * (t - t0)).exp()).collect()
    }
}

/// A damped, driven pair of coupled pendulums: nonlinear, time-dependent, four states, no
/// closed form.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pendulums;

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

/// The problem `S` without its Taylor coefficients (the Taylor method refuses it).
#[derive(Clone, Copy, Debug, Default)]
pub struct WithoutTaylor<S>(pub S);

impl<S: System> System for WithoutTaylor<S> {
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.0.rhs(t, y, dy)
    }
}

impl<S: ClosedForm> ClosedForm for WithoutTaylor<S> {
    fn solution(&self, t0: f64, y0: &[f64], t: f64) -> Vec<f64> {
        self.0.solution(t0, y0, t)
    }
}

/// The problem `S` computing every order of its Taylor coefficients alike (no straight-line
/// orders).
#[derive(Clone, Copy, Debug, Default)]
pub struct NoStraightLine<S>(pub S);

impl<S: System> System for NoStraightLine<S> {
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.0.rhs(t, y, dy)
    }
    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        self.0.taylor(t, y, order, out, work)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each closed form solves its equation: its slope by central differences is `f`.
    fn check_solution<S: ClosedForm>(sys: &S, y0: &[f64]) {
        let (t0, t, h) = (0.2, 0.7, 1e-5);
        let y = sys.solution(t0, y0, t);
        assert_eq!(sys.solution(t0, y0, t0), y0);
        let (ahead, behind) = (sys.solution(t0, y0, t + h), sys.solution(t0, y0, t - h));
        let mut f = vec![0.0; y.len()];
        sys.rhs(t, &y, &mut f);
        for i in 0..y.len() {
            let slope = (ahead[i] - behind[i]) / (2.0 * h);
            assert!((slope - f[i]).abs() < 1e-8 * f[i].abs().max(1.0), "state {i}: {slope} vs {}", f[i]);
        }
    }

    #[test]
    fn closed_forms_solve_their_equations() {
        check_solution(&Oscillator, &[0.3, -1.2]);
        check_solution(&Gaussian, &[1.5]);
        check_solution(&BlowUp, &[0.8]);
        check_solution(&Exponential([-1.0, 0.5, 0.0]), &[1.0, 2.0, 3.0]);
        check_solution(&WithoutTaylor(Oscillator), &[1.0, 0.0]);
    }

    /// The Taylor coefficients of `sys` at `(t0, y0)` to order 24, summed at `t0 + 0.1`, are its
    /// closed form there.
    fn check_taylor<S: ClosedForm>(sys: &S, y0: &[f64]) {
        let (t0, h, order) = (0.4, 0.1, 24);
        let n = y0.len();
        let mut c = vec![0.0; n * (order + 1)];
        assert!(sys.taylor(t0, y0, order, &mut c, &mut Vec::new()));
        let exact = sys.solution(t0, y0, t0 + h);
        for (i, ci) in c.chunks_exact(order + 1).enumerate() {
            let sum = ci.iter().rev().fold(0.0, |acc, ck| acc * h + ck);
            assert!((sum - exact[i]).abs() < 1e-14, "state {i}: {sum} vs {}", exact[i]);
        }
    }

    #[test]
    fn taylor_coefficients_sum_to_the_solution() {
        check_taylor(&Oscillator, &[0.3, -1.2]);
        check_taylor(&Gaussian, &[1.5]);
        let (t0, order) = (0.4, 24);
        let mut c = vec![0.0; 2 * (order + 1)];
        assert!(!WithoutTaylor(Oscillator).taylor(t0, &[1.0, 0.0], order, &mut c, &mut Vec::new()));
        assert!(NoStraightLine(Oscillator).taylor_straight_line().is_empty());
    }
}
