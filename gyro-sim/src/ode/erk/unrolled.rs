//! Steps of the built-in tableaux with every stage loop unrolled at compile time: the
//! coefficients become constants, zero coefficients vanish, and no loop or branch is left in a
//! step but the component loops over the compile-time dimension `N`. The arithmetic and its
//! order are those of the general step, so both give the same numbers.
// Stage arithmetic walks one component index over several arrays at once.
#![allow(clippy::needless_range_loop)]
// `seq!` writes `0 * N` and `(0 + 1) * N` for the first stage.
#![allow(clippy::identity_op, clippy::erasing_op)]

use seq_macro::seq;

use super::{Tolerances, Work};
use crate::ode::tableau::{Tableau, DOP853, DOPRI5, RK4};
use crate::ode::System;

/// A tableau known at compile time.
trait FixedTableau {
    const TAB: &'static Tableau;
}

struct Dop853;
struct Dopri5;
struct Rk4;

impl FixedTableau for Dop853 {
    const TAB: &'static Tableau = &DOP853;
}
impl FixedTableau for Dopri5 {
    const TAB: &'static Tableau = &DOPRI5;
}
impl FixedTableau for Rk4 {
    const TAB: &'static Tableau = &RK4;
}

/// The most stages an unrolled step has (the `seq!` bounds below).
const MAX_STAGES: usize = 13;
const _: () =
    assert!(DOP853.c.len() <= MAX_STAGES && DOPRI5.c.len() <= MAX_STAGES && RK4.c.len() <= MAX_STAGES);

impl<S: System + ?Sized, const N: usize> Work<'_, S, N> {
    /// One step like [`Work::step`] when the dimension is fixed and the tableau built in;
    /// false otherwise (nothing done).
    #[inline(always)]
    pub(super) fn step_unrolled(&mut self, t: f64, y: &[f64], h: f64) -> bool {
        if N == 0 {
            return false;
        }
        if std::ptr::eq(self.tab, Dop853::TAB) {
            self.step_fixed::<Dop853>(t, y, h);
        } else if std::ptr::eq(self.tab, Dopri5::TAB) {
            self.step_fixed::<Dopri5>(t, y, h);
        } else if std::ptr::eq(self.tab, Rk4::TAB) {
            self.step_fixed::<Rk4>(t, y, h);
        } else {
            return false;
        }
        true
    }

    /// The error estimate like [`Work::error`] when the step was unrolled; None otherwise.
    #[inline(always)]
    pub(super) fn error_unrolled(&self, y: &[f64], h: f64, tol: Tolerances) -> Option<f64> {
        if N == 0 {
            return None;
        }
        if std::ptr::eq(self.tab, Dop853::TAB) {
            Some(self.error_fixed::<Dop853>(y, h, tol))
        } else if std::ptr::eq(self.tab, Dopri5::TAB) {
            Some(self.error_fixed::<Dopri5>(y, h, tol))
        } else {
            None
        }
    }

    #[inline(always)]
    fn step_fixed<T: FixedTableau>(&mut self, t: f64, y: &[f64], h: f64) {
        let tab = T::TAB;
        let stages = tab.stages_before_error();
        let y = &y[..N];
        seq!(I in 1..13 {
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

    /// [`Work::combine`] for a compile-time weight row `w` (at most 13 stages).
    #[inline(always)]
    fn fixed_combine(&self, w: &[f64], y: &[f64], h: f64) -> [f64; N] {
        let last = w.len() - 1;
        let mut acc = [0.0f64; N];
        seq!(J in 0..13 {
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

    /// `sum_j w_j k_j` over the stages of `T`, `w` one of its weight rows.
    #[inline(always)]
    fn fixed_sum<T: FixedTableau>(&self, w: &[f64]) -> [f64; N] {
        let s = T::TAB.c.len();
        let mut acc = [0.0f64; N];
        seq!(J in 0..13 {
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
    fn error_fixed<T: FixedTableau>(&self, y: &[f64], h: f64, tol: Tolerances) -> f64 {
        let tab = T::TAB;
        let e5 = self.fixed_sum::<T>(tab.e.unwrap_or(&[]));
        match tab.e3 {
            Some(w3) => {
                let e3 = self.fixed_sum::<T>(w3);
                self.error_norm(y, h, &e5, Some(&e3), tol)
            }
            None => self.error_norm(y, h, &e5, None, tol),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Decay;
    impl System for Decay {
        fn dim(&self) -> usize {
            2
        }
        fn rhs(&self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = -y[0];
            dy[1] = -2.0 * y[1];
        }
    }

    #[test]
    fn built_in_tableaux_take_the_unrolled_step_when_the_dimension_is_fixed() {
        let y = [1.0, 1.0];
        for tab in [&DOP853, &DOPRI5, &RK4] {
            let mut fixed = Work::<Decay, 2>::new(&Decay, tab);
            Decay.rhs(0.0, &y, &mut fixed.k[..2]);
            assert!(fixed.step_unrolled(0.0, &y, 0.1), "{}", tab.name);
            assert!((fixed.ynew[0] - (-0.1f64).exp()).abs() < 1e-6, "{}: {:?}", tab.name, fixed.ynew);
            let mut general = Work::<Decay, 0>::new(&Decay, tab);
            assert!(!general.step_unrolled(0.0, &y, 0.1));
        }
        // A tableau with the same coefficients elsewhere in memory takes the general step.
        static COPY: Tableau = Tableau { name: "copy", dense: None, ..RK4 };
        let mut other = Work::<Decay, 2>::new(&Decay, &COPY);
        assert!(!other.step_unrolled(0.0, &y, 0.1));
    }
}
