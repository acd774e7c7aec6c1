//! The roots of a polynomial with number coefficients: the eigenvalues of its companion matrix,
//! each real one polished by Newton's method.
//!
//! In: coefficients from the highest power down (`[1, -3, 2]` is `x^2 - 3 x + 2`). Out: the
//! real roots, ascending, repeated ones repeated, or the complex roots when some are not real.

use nalgebra::{Complex, DMatrix};

/// A root whose imaginary part is below this (times the largest root's magnitude, at least 1)
/// is real: the companion matrix splits a double root into a pair `r +- i d` with `d` near
/// `sqrt(eps) |r|`, 1.5e-8 (roots of higher multiplicity split further and are not caught).
const NEAR_REAL: f64 = 1e-7;

/// The real roots of `c[0] x^n + ... + c[n]`, ascending (leading zeros dropped), or every
/// root (real ones polished) when some are not real. No coefficients but zeros, or one, give no
/// roots.
pub(super) fn real_roots(c: &[f64]) -> Result<Vec<f64>, Vec<Complex<f64>>> {
    let c: Vec<f64> = c.iter().copied().skip_while(|x| *x == 0.0).collect();
    let n = c.len().saturating_sub(1);
    if n == 0 {
        return Ok(Vec::new());
    }
    let mut companion = DMatrix::zeros(n, n);
    for j in 0..n {
        companion[(0, j)] = -c[j + 1] / c[0];
    }
    for i in 1..n {
        companion[(i, i - 1)] = 1.0;
    }
    let z = companion.complex_eigenvalues();
    let scale = z.iter().map(|z| z.norm()).fold(1.0, f64::max);
    if z.iter().any(|z| z.im.abs() > NEAR_REAL * scale) {
        let all = z.iter().map(|z| {
            if z.im.abs() > NEAR_REAL * scale {
                *z
            } else {
                Complex::new(polish(&c, z.re), 0.0)
            }
        });
        return Err(all.collect());
    }
    let mut roots: Vec<f64> = z.iter().map(|z| polish(&c, z.re)).collect();
    roots.sort_by(f64::total_cmp);
    Ok(roots)
}

/// Up to four Newton steps on `x`, each kept only when it makes `|p(x)|` smaller.
fn polish(c: &[f64], mut x: f64) -> f64 {
    let mut p = horner(c, x).0;
    for _ in 0..4 {
        let (value, slope) = horner(c, x);
        if value == 0.0 || slope == 0.0 || !slope.is_finite() {
            break;
        }
        let next = x - value / slope;
        let p_next = horner(c, next).0;
        if p_next.abs().partial_cmp(&p.abs()) != Some(std::cmp::Ordering::Less) {
            break;
        }
        (x, p) = (next, p_next);
    }
    x
}

/// `p(x)` and `p'(x)` by Horner's rule.
fn horner(c: &[f64], x: f64) -> (f64, f64) {
    c.iter().fold((0.0, 0.0), |(p, dp), a| (p * x + a, dp * x + p))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_products_of_linear_factors() {
        // (x - 1)(x - 2)(x - 3) = x^3 - 6 x^2 + 11 x - 6, with a leading zero written.
        let r = real_roots(&[0.0, 1.0, -6.0, 11.0, -6.0]).unwrap();
        assert_eq!(r.len(), 3);
        assert!(r.iter().zip([1.0, 2.0, 3.0]).all(|(a, b)| (a - b).abs() < 1e-13), "{r:?}");
        // A double root: (x + 2)^2 (x - 0.5) = x^3 + 3.5 x^2 + 2 x - 2.
        let r = real_roots(&[1.0, 3.5, 2.0, -2.0]).unwrap();
        assert!(r.iter().zip([-2.0, -2.0, 0.5]).all(|(a, b)| (a - b).abs() < 1e-7), "{r:?}");
        assert!(real_roots(&[5.0]).unwrap().is_empty());
    }

    #[test]
    fn complex_roots_are_returned_as_such() {
        // x^2 + 2 x + 3: -1 +- i sqrt(2).
        let z = real_roots(&[1.0, 2.0, 3.0]).unwrap_err();
        assert_eq!(z.len(), 2);
        assert!(z.iter().all(|z| (z.re + 1.0).abs() < 1e-14 && (z.im.abs() - 2f64.sqrt()).abs() < 1e-14));
    }
}
