//! Steps of the built-in tableaux with every stage loop unrolled at compile time. In: a row of
//! [`METHODS`] (found by the tableau's address) and a compile-time dimension `N`; out: the same
//! step and error estimate as the general code, with the coefficients as constants, zero
//! coefficients gone, and no loop or branch left but the component loops over `N`. The
//! arithmetic and its order are those of the general step, so both give the same numbers.
// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]
// `seq!` writes `0 * N` and `(0 + 1) * N` for the first stage.
#![allow(clippy::identity_op, clippy::erasing_op)]

use seq_macro::seq;

use super::{StageBuffers, Tolerances};
use crate::ode::methods::METHODS;
use crate::ode::tableau::Tableau;
use crate::ode::System;

/// The most stages an unrolled step has (the `seq!` bounds of the stage loops below).
const MAX_STAGES: usize = 17;

/// Row `M` of [`METHODS`] as a compile-time tableau; None past the table's end (rows from
/// 8 on, the `seq!` bound of the row loops) or for more than [`MAX_STAGES`] stages: those
/// take the general step.
struct Row<const M: usize>;

impl<const M: usize> Row<M> {
    const TAB: Option<&'static Tableau> = if M < METHODS.len() {
        match METHODS[M].tableau {
            Some(tab) if tab.c.len() <= MAX_STAGES => Some(tab),
            _ => None,
        }
    } else {
        None
    };
}

impl<S: System + ?Sized, const N: usize> StageBuffers<'_, S, N> {
    /// One step like [`StageBuffers::step`] when the dimension is fixed and the tableau built in;
    /// false otherwise (nothing done).
    #[inline(always)]
    pub(super) fn step_unrolled(&mut self, t: f64, y: &[f64], h: f64) -> bool {
        if N == 0 {
            return false;
        }
        seq!(M in 0..8 {
            if let Some(tab) = Row::<M>::TAB {
                if std::ptr::eq(self.tab, tab) {
                    self.step_fixed::<M>(t, y, h);
                    return true;
                }
            }
        });
        false
    }

    /// The error estimate like [`StageBuffers::error`] when the step was unrolled; None otherwise.
    #[inline(always)]
    pub(super) fn error_unrolled(&self, y: &[f64], h: f64, tol: Tolerances) -> Option<f64> {
        if N == 0 {
            return None;
        }
        seq!(M in 0..8 {
            if let Some(tab) = Row::<M>::TAB {
                if tab.e.is_some() && std::ptr::eq(self.tab, tab) {
                    return Some(self.error_fixed::<M>(y, h, tol));
                }
            }
        });
        None
    }

    #[inline(always)]
    fn step_fixed<const M: usize>(&mut self, t: f64, y: &[f64], h: f64) {
        let Some(tab) = Row::<M>::TAB else { return };
        let stages = tab.stages_before_error();
        let y = &y[..N];
        seq!(I in 1..17 {
            if I < stages {
                let input = self.fixed_combine(tab.a[I], y, h);
                self.tmp[..N].copy_from_slice(&input);
                let (_, rest) = self.k.split_at_mut(I * N);
                self.sys.rhs(t + tab.c[I] * h, &self.tmp[..N], &mut rest[..N]);
                self.stats.rhs_evals += 1;
            }
        });
        let ynew = self.fixed_combine(tab.b, y, h);
        self.ynew[..N].copy_from_slice(&ynew);
    }

    /// [`StageBuffers::combine`] for a compile-time weight row `w` (at most 17 stages).
    #[inline(always)]
    fn fixed_combine(&self, w: &[f64], y: &[f64], h: f64) -> [f64; N] {
        let last = w.len() - 1;
        let mut acc = [0.0f64; N];
        seq!(J in 0..17 {
            if J < last && w[J] != 0.0 {
                let kj = &self.k[J * N..(J + 1) * N];
                for m in 0..N {
                    acc[m] += w[J] * kj[m];
                }
            }
        });
        for m in 0..N {
            acc[m] = y[m] + h * acc[m];
        }
        if w[last] != 0.0 {
            let c = h * w[last];
            let kl = &self.k[last * N..(last + 1) * N];
            for m in 0..N {
                acc[m] += c * kl[m];
            }
        }
        acc
    }

    /// `sum_j w_j k_j` over the `s` stages, `w` a compile-time weight row (at most 17 stages).
    #[inline(always)]
    fn fixed_sum(&self, s: usize, w: &[f64]) -> [f64; N] {
        let mut acc = [0.0f64; N];
        seq!(J in 0..17 {
            if J < s && w[J] != 0.0 {
                let kj = &self.k[J * N..(J + 1) * N];
                for m in 0..N {
                    acc[m] += w[J] * kj[m];
                }
            }
        });
        acc
    }

    #[inline(always)]
    fn error_fixed<const M: usize>(&self, y: &[f64], h: f64, tol: Tolerances) -> f64 {
        // Only rows with error weights come here (see `error_unrolled`).
        let Some(tab) = Row::<M>::TAB else { return f64::NAN };
        let Some(e) = tab.e else { return f64::NAN };
        let s = tab.c.len();
        let e5 = self.fixed_sum(s, e);
        match tab.e3 {
            Some(w3) => {
                let e3 = self.fixed_sum(s, w3);
                self.error_norm(y, h, &e5, Some(&e3), tol)
            }
            None => self.error_norm(y, h, &e5, None, tol),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::ode::test_problems::Exponential;

    const TOL: Tolerances = Tolerances { rtol: 1e-6, atol: 1e-6 };

    /// `y1' = -y1`, `y2' = -2 y2`.
    const DECAY: Exponential<2> = Exponential([-1.0, -2.0]);

    #[test]
    fn every_table_row_takes_the_unrolled_step_when_the_dimension_is_fixed() {
        let y = [1.0, 1.0];
        for tab in METHODS.iter().filter_map(|m| m.tableau) {
            let mut fixed = StageBuffers::<Exponential<2>, 2>::new(&DECAY, tab);
            DECAY.rhs(0.0, &y, &mut fixed.k[..2]);
            assert!(fixed.step_unrolled(0.0, &y, 0.1), "{}", tab.name);
            assert!((fixed.ynew[0] - (-0.1f64).exp()).abs() < 1e-6, "{}: {:?}", tab.name, fixed.ynew);
            let mut general = StageBuffers::<Exponential<2>, 0>::new(&DECAY, tab);
            assert!(!general.step_unrolled(0.0, &y, 0.1));
            assert_eq!(fixed.error_unrolled(&y, 0.1, TOL).is_some(), tab.e.is_some(), "{}", tab.name);
        }
        // A tableau with the same coefficients elsewhere in memory takes the general step.
        static COPY: Tableau = Tableau { name: "copy", dense: None, ..crate::ode::tableau::RK4 };
        let mut other = StageBuffers::<Exponential<2>, 2>::new(&DECAY, &COPY);
        assert!(!other.step_unrolled(0.0, &y, 0.1));
    }
}
