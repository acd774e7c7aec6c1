//! `N` numbers in lock step: every operation applied lane by lane, so code generic over
//! `num_traits::Float` (a generated model's `rhs_lanes`) computes `N` members at once; the
//! arrays of fixed length let the compiler use SIMD registers. Comparisons and the
//! classification methods read lane 0 (generated right-hand sides do not branch on values).

use std::cmp::Ordering;
use std::num::FpCategory;
use std::ops::{Add, Div, Mul, Neg, Rem, Sub};

use num_traits::{Float, Num, NumCast, One, ToPrimitive, Zero};

/// `N` lanes of `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(align(32))]
pub struct Lanes<const N: usize>(pub [f64; N]);

impl<const N: usize> Lanes<N> {
    /// Every lane `x`.
    #[inline(always)]
    pub fn splat(x: f64) -> Self {
        Lanes([x; N])
    }

    /// `f` of each lane.
    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Lanes(self.0.map(f))
    }

    /// `f` of each pair of lanes.
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        let mut out = self.0;
        for (a, b) in out.iter_mut().zip(o.0) {
            *a = f(*a, b);
        }
        Lanes(out)
    }
}

macro_rules! binary_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<const N: usize> $tr for Lanes<N> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                self.zip(o, |a, b| a $op b)
            }
        }
    };
}
binary_op!(Add, add, +);
binary_op!(Sub, sub, -);
binary_op!(Mul, mul, *);
binary_op!(Div, div, /);
binary_op!(Rem, rem, %);

impl<const N: usize> Neg for Lanes<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}

impl<const N: usize> PartialOrd for Lanes<N> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        self.0[0].partial_cmp(&o.0[0])
    }
}

impl<const N: usize> Zero for Lanes<N> {
    fn zero() -> Self {
        Self::splat(0.0)
    }
    fn is_zero(&self) -> bool {
        self.0.iter().all(|a| *a == 0.0)
    }
}

impl<const N: usize> One for Lanes<N> {
    fn one() -> Self {
        Self::splat(1.0)
    }
}

impl<const N: usize> Num for Lanes<N> {
    type FromStrRadixErr = num_traits::ParseFloatError;
    fn from_str_radix(s: &str, radix: u32) -> Result<Self, Self::FromStrRadixErr> {
        f64::from_str_radix(s, radix).map(Self::splat)
    }
}

impl<const N: usize> ToPrimitive for Lanes<N> {
    fn to_i64(&self) -> Option<i64> {
        self.0[0].to_i64()
    }
    fn to_u64(&self) -> Option<u64> {
        self.0[0].to_u64()
    }
    fn to_f64(&self) -> Option<f64> {
        Some(self.0[0])
    }
}

impl<const N: usize> NumCast for Lanes<N> {
    fn from<T: ToPrimitive>(n: T) -> Option<Self> {
        n.to_f64().map(Self::splat)
    }
}

macro_rules! lanewise {
    ($($name:ident),*) => {
        $(
            #[inline(always)]
            fn $name(self) -> Self {
                self.map(f64::$name)
            }
        )*
    };
}

macro_rules! lane0 {
    ($($name:ident),*) => {
        $(
            fn $name(self) -> bool {
                self.0[0].$name()
            }
        )*
    };
}

macro_rules! constant {
    ($($name:ident),*) => {
        $(
            fn $name() -> Self {
                Self::splat(f64::$name())
            }
        )*
    };
}

impl<const N: usize> Float for Lanes<N> {
    constant!(nan, infinity, neg_infinity, neg_zero, min_value, min_positive_value, max_value, epsilon);
    lane0!(is_nan, is_infinite, is_finite, is_normal, is_sign_positive, is_sign_negative);
    lanewise!(floor, ceil, round, trunc, fract, abs, signum, recip, sqrt, exp, exp2, ln, log2, log10);
    lanewise!(cbrt, sin, cos, tan, asin, acos, atan, exp_m1, ln_1p, sinh, cosh, tanh, asinh, acosh, atanh);
    fn classify(self) -> FpCategory {
        self.0[0].classify()
    }
    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        Lanes(std::array::from_fn(|k| self.0[k].mul_add(a.0[k], b.0[k])))
    }
    #[inline(always)]
    fn powi(self, n: i32) -> Self {
        self.map(|a| a.powi(n))
    }
    fn powf(self, n: Self) -> Self {
        self.zip(n, f64::powf)
    }
    fn log(self, base: Self) -> Self {
        self.zip(base, f64::log)
    }
    fn max(self, o: Self) -> Self {
        self.zip(o, f64::max)
    }
    fn min(self, o: Self) -> Self {
        self.zip(o, f64::min)
    }
    fn abs_sub(self, o: Self) -> Self {
        self.zip(o, |a, b| (a - b).max(0.0))
    }
    fn hypot(self, o: Self) -> Self {
        self.zip(o, f64::hypot)
    }
    fn atan2(self, o: Self) -> Self {
        self.zip(o, f64::atan2)
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        let both: [(f64, f64); N] = self.0.map(f64::sin_cos);
        (Lanes(both.map(|p| p.0)), Lanes(both.map(|p| p.1)))
    }
    fn integer_decode(self) -> (u64, i16, i8) {
        self.0[0].integer_decode()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generic expression like a generated right-hand side's.
    fn f<T: Float>(x: T, y: T) -> T {
        let (s, c) = x.sin_cos();
        (s * y.powi(2) - c / (T::one() + y.abs())).sqrt().max(T::zero()) + x.atan2(y) * T::from(0.5).unwrap()
    }

    #[test]
    fn each_lane_equals_the_scalar_computation_bit_for_bit() {
        let xs = [0.3, 1.7, -2.2, 4.0];
        let ys = [1.5, -0.25, 3.0, 0.0];
        let got = f(Lanes(xs), Lanes(ys));
        for k in 0..4 {
            assert_eq!(got.0[k].to_bits(), f(xs[k], ys[k]).to_bits(), "lane {k}");
        }
    }
}
