//! Unit-norm groups (Euler parameters): in come a system and the state groups whose norm is 1;
//! out goes the same system whose stepper projects a group back onto the unit sphere when its
//! norm has drifted past a threshold (only then, so between projections the method keeps its
//! order), counting the projections and the largest drift met.

use std::cell::Cell;

use super::{System, TaylorWork};

/// How far the unit-norm states drifted in one run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormDrift {
    /// The largest `| |e| - 1 |` met before a projection or at a step's end.
    pub largest: f64,
    /// Projections back to norm 1.
    pub projections: usize,
    /// The drift allowed before projecting.
    pub threshold: f64,
}

/// `inner` with states in `groups` held at unit norm (indices into `inner`'s state).
pub struct UnitNorm<'a, S: System + ?Sized> {
    inner: &'a S,
    groups: &'a [Vec<usize>],
    threshold: f64,
    largest: Cell<f64>,
    projections: Cell<usize>,
}

impl<'a, S: System + ?Sized> UnitNorm<'a, S> {
    /// `inner`, its `groups` projected when their norm is off 1 by more than `threshold`.
    pub fn new(inner: &'a S, groups: &'a [Vec<usize>], threshold: f64) -> Self {
        UnitNorm { inner, groups, threshold, largest: Cell::new(0.0), projections: Cell::new(0) }
    }

    /// The drift so far.
    pub fn drift(&self) -> NormDrift {
        NormDrift {
            largest: self.largest.get(),
            projections: self.projections.get(),
            threshold: self.threshold,
        }
    }
}

impl<S: System + ?Sized> System for UnitNorm<'_, S> {
    const FIXED_DIM: usize = S::FIXED_DIM;
    const REDUCED_DIM: usize = S::REDUCED_DIM;
    const UNROLL_ANY_DIM: bool = S::UNROLL_ANY_DIM;
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.inner.rhs(t, y, dy)
    }

    fn taylor(&self, t: f64, y: &[f64], order: usize, out: &mut [f64], work: &mut TaylorWork) -> bool {
        self.inner.taylor(t, y, order, out, work)
    }

    fn taylor_straight_line(&self) -> &[usize] {
        self.inner.taylor_straight_line()
    }

    fn project(&self, y: &mut [f64]) -> bool {
        let mut moved = false;
        for group in self.groups {
            let norm = group.iter().map(|&i| y[i] * y[i]).sum::<f64>().sqrt();
            let drift = (norm - 1.0).abs();
            self.largest.set(self.largest.get().max(drift));
            if drift > self.threshold && norm > 0.0 {
                group.iter().for_each(|&i| y[i] /= norm);
                moved = true;
            }
        }
        if moved {
            self.projections.set(self.projections.get() + 1);
        }
        moved
    }
}

/// Each group of `y` scaled to unit norm (a zero group is left alone).
pub fn normalise(groups: &[Vec<usize>], y: &mut [f64]) {
    for group in groups {
        let norm = group.iter().map(|&i| y[i] * y[i]).sum::<f64>().sqrt();
        if norm > 0.0 {
            group.iter().for_each(|&i| y[i] /= norm);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::test_problems::Exponential;

    /// Five states at rest.
    const STILL: Exponential<5> = Exponential([0.0; 5]);

    #[test]
    fn projects_only_past_the_threshold_and_counts() {
        let groups = vec![vec![1, 2, 3, 4]];
        let sys = UnitNorm::new(&STILL, &groups, 1e-8);
        let mut y = [7.0, 0.5, 0.5, 0.5, 0.5 * (1.0 + 1e-9)];
        assert!(!sys.project(&mut y));
        assert_eq!(y[0], 7.0);
        y[1] = 0.6;
        assert!(sys.project(&mut y));
        let norm: f64 = y[1..].iter().map(|v| v * v).sum::<f64>().sqrt();
        assert!((norm - 1.0).abs() < 1e-15);
        assert_eq!(y[0], 7.0, "states outside the group untouched");
        let d = sys.drift();
        assert_eq!(d.projections, 1);
        assert!(d.largest > 0.05 && d.largest < 0.06, "{}", d.largest);
    }
}
