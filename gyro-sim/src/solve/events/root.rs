//! Bracketed root finding: in comes a function with a sign change on `[a, b]`; out goes the
//! crossing, to the precision of the time (the Illinois variant of regula falsi: superlinear,
//! never leaves the bracket; a bisection when two steps did not halve the bracket, as at a
//! multiple root).

/// Most iterations (the bracket shrinks superlinearly; far fewer are needed).
const MAX_ITERATIONS: usize = 200;

/// The time where `f` crosses zero in `[a, b]`, given `fa = f(a)` and `fb = f(b)` of opposite
/// signs (neither zero): the end of the final bracket on the side the crossing goes to, within
/// a few units of round-off of `|t|` of the root. A NaN value of `f` ends the search at the
/// bracket found so far.
pub fn illinois(mut f: impl FnMut(f64) -> f64, mut a: f64, mut fa: f64, mut b: f64, mut fb: f64) -> f64 {
    // Which end was kept twice in a row (-1: a, 1: b), whose value is then halved.
    let mut side = 0;
    // The widths one and two iterations ago: a bracket that did not halve in two steps is
    // bisected (a multiple root, where regula falsi crawls).
    let mut widths = [f64::INFINITY; 2];
    for _ in 0..MAX_ITERATIONS {
        let width = b - a;
        if width <= 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(f64::MIN_POSITIVE) {
            break;
        }
        let mut c = b - fb * width / (fb - fa);
        let slow = width > 0.5 * widths[1];
        widths = [width, widths[0]];
        if slow || !(c > a && c < b) {
            c = a + 0.5 * width;
        }
        let fc = f(c);
        if fc.is_nan() {
            break;
        }
        if fc == 0.0 {
            return c;
        }
        if (fc > 0.0) == (fb > 0.0) {
            (b, fb) = (c, fc);
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            (a, fa) = (c, fc);
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A function, a bracket and the root inside.
    type Case = (fn(f64) -> f64, f64, f64, f64);

    #[test]
    fn roots_to_the_precision_of_the_time() {
        let cases: [Case; 4] = [
            (|t| t.cos(), 1.0, 2.0, std::f64::consts::FRAC_PI_2),
            (|t| (t - 40.123_456_789).powi(3), 39.0, 41.0, 40.123_456_789),
            (|t| t.exp() - 10.0, 0.0, 5.0, 10f64.ln()),
            (|t| 1e-12 * (t - 0.3), 0.0, 1.0, 0.3),
        ];
        for (f, a, b, root) in cases {
            let mut calls = 0;
            let t = illinois(
                |t| {
                    calls += 1;
                    f(t)
                },
                a,
                f(a),
                b,
                f(b),
            );
            assert!((t - root).abs() <= 8.0 * f64::EPSILON * root, "{t} vs {root}");
            assert!(calls < 100, "{calls} calls for the root {root}");
        }
    }

    #[test]
    fn the_result_stays_in_the_bracket() {
        // A step function: no value is zero; the crossing is the jump.
        let t = illinois(|t| if t < 0.7 { -1.0 } else { 1.0 }, 0.0, -1.0, 1.0, 1.0);
        assert!((t - 0.7).abs() < 1e-15 && t >= 0.7, "{t}");
        let t = illinois(|_| f64::NAN, 0.0, -1.0, 1.0, 1.0);
        assert_eq!(t, 1.0);
    }
}
