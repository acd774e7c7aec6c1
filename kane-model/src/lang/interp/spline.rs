//! Extension (Autolev has no tables): `SPLINE(X, [x0, x1, ...], [y0, y1, ...])`, the not-a-knot
//! cubic spline through the points, as an expression in `X`. Each interval's cubic is written
//! in the local coordinate `X - x_k` (well conditioned however many points) and switched on by
//! `(SIGN(X - x_k) - SIGN(X - x_(k+1))) / 2`; the first and last cubics continue outside the
//! points. Derivatives follow by differentiation, so a prescribed motion read from a table has
//! its rates and accelerations (continuous: the spline is twice continuously differentiable).

use crate::expr::{ExprId, Func};

use super::super::ast::Expr;
use super::super::diagnostic::Diagnostic;
use super::value::Value;
use super::{At, IResult, Interpreter};

/// One interval's cubic `a + b s + c s^2 + d s^3` in `s = x - x_k`.
pub(crate) type Cubic = [f64; 4];

impl Interpreter {
    /// `SPLINE(X, knots, values)`.
    pub(super) fn spline(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        super::arity("SPLINE", args, 3, &e.span)?;
        let x = self.scalar(&args[0])?;
        let knots = self.number_list(&args[1])?;
        let values = self.number_list(&args[2])?;
        if knots.len() != values.len() || knots.len() < 2 {
            return Err(Diagnostic::error(
                e.span.clone(),
                format!(
                    "SPLINE needs as many values as points, two or more: {} points, {} values",
                    knots.len(),
                    values.len()
                ),
            ));
        }
        if let Some(k) = knots.windows(2).position(|w| w[1] <= w[0]) {
            return Err(Diagnostic::error(
                args[1].span.clone(),
                format!(
                    "SPLINE's points must increase: point {} ({}) follows {}",
                    k + 2,
                    knots[k + 1],
                    knots[k]
                ),
            ));
        }
        let cubics = not_a_knot(&knots, &values);
        let ar = &mut self.model.ar;
        let half = ar.rational(1, 2).at(&e.span)?;
        let sign_at = |ar: &mut crate::expr::Arena, t: f64| -> Result<ExprId, crate::expr::ExprError> {
            let tk = ar.float(t)?;
            let s = ar.sub(x, tk)?;
            ar.func(Func::Sign, s)
        };
        let mut terms = Vec::with_capacity(cubics.len());
        let last = cubics.len() - 1;
        for (k, c) in cubics.iter().enumerate() {
            let (one, two) = (ar.integer(1), ar.integer(2));
            let (left, right) = (sign_at(ar, knots[k]).at(&e.span)?, sign_at(ar, knots[k + 1]).at(&e.span)?);
            // Twice the indicator of the interval (half at its ends); the end intervals extend
            // outwards.
            let window = match (k == 0, k == last) {
                (true, true) => Ok(two),
                (true, false) => ar.sub(one, right),
                (false, true) => ar.add(&[one, left]),
                (false, false) => ar.sub(left, right),
            }
            .at(&e.span)?;
            let tk = ar.float(knots[k]).at(&e.span)?;
            let s = ar.sub(x, tk).at(&e.span)?;
            let mut cubic = ar.float(c[3]).at(&e.span)?;
            for coefficient in [c[2], c[1], c[0]] {
                let times = ar.mul(&[cubic, s]).at(&e.span)?;
                let a = ar.float(coefficient).at(&e.span)?;
                cubic = ar.add(&[times, a]).at(&e.span)?;
            }
            terms.push(ar.mul(&[half, window, cubic]).at(&e.span)?);
        }
        Ok(Value::Scalar(ar.add(&terms).at(&e.span)?))
    }

    /// A row or column of numbers.
    fn number_list(&mut self, a: &Expr) -> IResult<Vec<f64>> {
        let data = match self.eval(a)? {
            Value::Matrix { rows, cols, data } if rows == 1 || cols == 1 => data,
            Value::Scalar(x) => vec![x],
            _ => {
                return Err(Diagnostic::error(
                    a.span.clone(),
                    "SPLINE takes its points and values as [a, b, ...]",
                ))
            }
        };
        let numbers =
            self.model.ar.eval::<f64>(&data, |_| None).map_err(|_| {
                Diagnostic::error(a.span.clone(), "SPLINE's points and values must be numbers")
            })?;
        if numbers.iter().any(|v| !v.is_finite()) {
            return Err(Diagnostic::error(a.span.clone(), "SPLINE's points and values must be finite"));
        }
        Ok(numbers)
    }
}

/// The not-a-knot cubic spline through `(x, y)` (two points: the line; three: the parabola),
/// one cubic per interval.
pub(crate) fn not_a_knot(x: &[f64], y: &[f64]) -> Vec<Cubic> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let slope: Vec<f64> = (0..n - 1).map(|k| (y[k + 1] - y[k]) / h[k]).collect();
    let second = match n {
        2 => vec![0.0; 2],
        3 => vec![2.0 * (slope[1] - slope[0]) / (h[0] + h[1]); 3],
        _ => second_derivatives(&h, &slope),
    };
    (0..n - 1)
        .map(|k| {
            let (m0, m1) = (second[k], second[k + 1]);
            [y[k], slope[k] - h[k] * (2.0 * m0 + m1) / 6.0, m0 / 2.0, (m1 - m0) / (6.0 * h[k])]
        })
        .collect()
}

/// The second derivatives at the points (four or more) with the third derivative continuous
/// across the second and the last-but-one point: a tridiagonal system in the interior ones.
fn second_derivatives(h: &[f64], slope: &[f64]) -> Vec<f64> {
    let n = h.len() + 1;
    let m = n - 2;
    let (mut lower, mut diag, mut upper, mut rhs) = (vec![0.0; m], vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    for i in 0..m {
        lower[i] = h[i];
        diag[i] = 2.0 * (h[i] + h[i + 1]);
        upper[i] = h[i + 1];
        rhs[i] = 6.0 * (slope[i + 1] - slope[i]);
    }
    // M0 = (1 + h0/h1) M1 - (h0/h1) M2, and the same at the other end.
    let (r0, r1) = (h[0] / h[1], h[n - 2] / h[n - 3]);
    diag[0] += lower[0] * (1.0 + r0);
    upper[0] -= lower[0] * r0;
    diag[m - 1] += upper[m - 1] * (1.0 + r1);
    lower[m - 1] -= upper[m - 1] * r1;
    let interior = thomas(&lower, &diag, &upper, &rhs);
    let mut second = Vec::with_capacity(n);
    second.push((1.0 + r0) * interior[0] - r0 * interior[1.min(m - 1)]);
    second.extend(&interior);
    second.push((1.0 + r1) * interior[m - 1] - r1 * interior[m.saturating_sub(2)]);
    second
}

/// The tridiagonal system `lower[i] x[i-1] + diag[i] x[i] + upper[i] x[i+1] = rhs[i]` solved by
/// elimination (diagonally dominant here but for the end rows, which stay well conditioned).
fn thomas(lower: &[f64], diag: &[f64], upper: &[f64], rhs: &[f64]) -> Vec<f64> {
    let m = diag.len();
    let (mut c, mut d) = (vec![0.0; m], vec![0.0; m]);
    for i in 0..m {
        let denominator = diag[i] - if i > 0 { lower[i] * c[i - 1] } else { 0.0 };
        c[i] = upper[i] / denominator;
        d[i] = (rhs[i] - if i > 0 { lower[i] * d[i - 1] } else { 0.0 }) / denominator;
    }
    let mut x = d;
    for i in (0..m.saturating_sub(1)).rev() {
        x[i] -= c[i] * x[i + 1];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::not_a_knot;

    /// The spline's value, slope and curvature at `t`.
    fn at(x: &[f64], pieces: &[[f64; 4]], t: f64) -> [f64; 3] {
        let k = x.windows(2).position(|w| t < w[1]).unwrap_or(pieces.len() - 1);
        let [a, b, c, d] = pieces[k];
        let s = t - x[k];
        [a + s * (b + s * (c + s * d)), b + s * (2.0 * c + 3.0 * d * s), 2.0 * c + 6.0 * d * s]
    }

    #[test]
    fn cubics_are_reproduced_exactly_with_their_derivatives() {
        let f =
            |t: f64| [t * t * t - 2.0 * t * t + 0.5 * t - 1.0, 3.0 * t * t - 4.0 * t + 0.5, 6.0 * t - 4.0];
        for x in [vec![0.0, 0.3, 0.35, 1.0, 1.7, 2.0], vec![-1.0, 0.0, 1.0, 2.5]] {
            let y: Vec<f64> = x.iter().map(|t| f(*t)[0]).collect();
            let pieces = not_a_knot(&x, &y);
            for t in [-1.0, -0.2, 0.0, 0.31, 0.9, 1.99, 2.0] {
                let (got, want) = (at(&x, &pieces, t), f(t));
                for (g, w) in got.iter().zip(want) {
                    assert!((g - w).abs() < 1e-12, "at {t}: {got:?} vs {want:?}");
                }
            }
        }
    }

    #[test]
    fn two_and_three_points_give_the_line_and_the_parabola() {
        let line = not_a_knot(&[0.0, 2.0], &[1.0, 5.0]);
        assert_eq!(line, vec![[1.0, 2.0, 0.0, 0.0]]);
        let parabola = not_a_knot(&[0.0, 1.0, 3.0], &[0.0, 1.0, 9.0]);
        assert!(parabola.iter().all(|p| (p[2] - 1.0).abs() < 1e-15 && p[3].abs() < 1e-15), "{parabola:?}");
    }
}
