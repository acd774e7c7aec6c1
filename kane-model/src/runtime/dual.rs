//! First-order dual numbers `re + eps·ε` (ε² = 0) implementing `num_traits::Float`, so any code
//! generic over `Float` computes a directional derivative exactly alongside its value.

use std::cmp::Ordering;
use std::num::FpCategory;
use std::ops::{Add, Div, Mul, Neg, Rem, Sub};

use num_traits::{Float, Num, NumCast, One, ToPrimitive, Zero};

/// A dual number: value `re` and derivative part `eps`.
///
/// # Example
/// ```
/// use kane_model::runtime::dual::Dual;
/// use num_traits::Float;
/// let x = Dual::variable(0.5_f64);
/// let y = (x * x).sin();
/// assert_eq!(y.re, 0.25_f64.sin());
/// assert_eq!(y.eps, 2.0 * 0.5 * 0.25_f64.cos());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Dual<T> {
    /// The value (real part).
    pub re: T,
    /// Derivative part.
    pub eps: T,
}

impl<T: Float> Dual<T> {
    /// `re + eps·ε`.
    pub fn new(re: T, eps: T) -> Self {
        Dual { re, eps }
    }

    /// A constant: zero derivative part.
    pub fn constant(re: T) -> Self {
        Dual { re, eps: T::zero() }
    }

    /// The independent variable: derivative part one.
    pub fn variable(re: T) -> Self {
        Dual { re, eps: T::one() }
    }

    /// `f(self)` given `f(re)` and `f'(re)`.
    fn chain(self, f: T, df: T) -> Self {
        Dual { re: f, eps: df * self.eps }
    }
}

impl<T: Float> Add for Dual<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Dual { re: self.re + o.re, eps: self.eps + o.eps }
    }
}

impl<T: Float> Sub for Dual<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Dual { re: self.re - o.re, eps: self.eps - o.eps }
    }
}

impl<T: Float> Mul for Dual<T> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Dual { re: self.re * o.re, eps: self.eps * o.re + self.re * o.eps }
    }
}

impl<T: Float> Div for Dual<T> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let inv = o.re.recip();
        Dual { re: self.re * inv, eps: (self.eps * o.re - self.re * o.eps) * inv * inv }
    }
}

impl<T: Float> Rem for Dual<T> {
    type Output = Self;
    fn rem(self, o: Self) -> Self {
        // x mod y = x - y trunc(x/y); the truncation is locally constant.
        Dual { re: self.re % o.re, eps: self.eps - o.eps * (self.re / o.re).trunc() }
    }
}

impl<T: Float> Neg for Dual<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Dual { re: -self.re, eps: -self.eps }
    }
}

impl<T: Float> PartialOrd for Dual<T> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        self.re.partial_cmp(&o.re)
    }
}

impl<T: Float> Zero for Dual<T> {
    fn zero() -> Self {
        Dual::constant(T::zero())
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.eps.is_zero()
    }
}

impl<T: Float> One for Dual<T> {
    fn one() -> Self {
        Dual::constant(T::one())
    }
}

impl<T: Float> Num for Dual<T> {
    type FromStrRadixErr = T::FromStrRadixErr;
    fn from_str_radix(s: &str, radix: u32) -> Result<Self, Self::FromStrRadixErr> {
        T::from_str_radix(s, radix).map(Dual::constant)
    }
}

impl<T: Float> ToPrimitive for Dual<T> {
    fn to_i64(&self) -> Option<i64> {
        self.re.to_i64()
    }
    fn to_u64(&self) -> Option<u64> {
        self.re.to_u64()
    }
    fn to_f64(&self) -> Option<f64> {
        self.re.to_f64()
    }
}

impl<T: Float> NumCast for Dual<T> {
    fn from<N: ToPrimitive>(n: N) -> Option<Self> {
        T::from(n).map(Dual::constant)
    }
}

macro_rules! on_value {
    ($($name:ident),*) => {$(
        fn $name(self) -> Self {
            Dual::constant(self.re.$name())
        }
    )*};
}

macro_rules! predicate {
    ($($name:ident),*) => {$(
        fn $name(self) -> bool {
            self.re.$name()
        }
    )*};
}

impl<T: Float> Float for Dual<T> {
    fn nan() -> Self {
        Dual::constant(T::nan())
    }
    fn infinity() -> Self {
        Dual::constant(T::infinity())
    }
    fn neg_infinity() -> Self {
        Dual::constant(T::neg_infinity())
    }
    fn neg_zero() -> Self {
        Dual::constant(T::neg_zero())
    }
    fn min_value() -> Self {
        Dual::constant(T::min_value())
    }
    fn min_positive_value() -> Self {
        Dual::constant(T::min_positive_value())
    }
    fn max_value() -> Self {
        Dual::constant(T::max_value())
    }
    fn epsilon() -> Self {
        Dual::constant(T::epsilon())
    }
    predicate!(is_nan, is_infinite, is_finite, is_normal, is_sign_positive, is_sign_negative);
    on_value!(floor, ceil, round, trunc);
    fn classify(self) -> FpCategory {
        self.re.classify()
    }
    fn fract(self) -> Self {
        Dual { re: self.re.fract(), eps: self.eps }
    }
    fn abs(self) -> Self {
        if self.re < T::zero() {
            -self
        } else {
            self
        }
    }
    fn signum(self) -> Self {
        Dual::constant(self.re.signum())
    }
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn recip(self) -> Self {
        let r = self.re.recip();
        self.chain(r, -r * r)
    }
    fn powi(self, n: i32) -> Self {
        if n == 0 {
            return Dual::one();
        }
        let p = self.re.powi(n - 1);
        self.chain(p * self.re, T::from(n).unwrap_or_else(T::nan) * p)
    }
    fn powf(self, n: Self) -> Self {
        if n.eps.is_zero() {
            let p = self.re.powf(n.re - T::one());
            return self.chain(p * self.re, n.re * p);
        }
        (n * self.ln()).exp()
    }
    fn sqrt(self) -> Self {
        let s = self.re.sqrt();
        self.chain(s, (s + s).recip())
    }
    fn cbrt(self) -> Self {
        let c = self.re.cbrt();
        self.chain(c, (T::from(3).unwrap_or_else(T::nan) * c * c).recip())
    }
    fn exp(self) -> Self {
        let e = self.re.exp();
        self.chain(e, e)
    }
    fn exp2(self) -> Self {
        let e = self.re.exp2();
        self.chain(e, e * T::from(std::f64::consts::LN_2).unwrap_or_else(T::nan))
    }
    fn exp_m1(self) -> Self {
        self.chain(self.re.exp_m1(), self.re.exp())
    }
    fn ln(self) -> Self {
        self.chain(self.re.ln(), self.re.recip())
    }
    fn log(self, base: Self) -> Self {
        self.ln() / base.ln()
    }
    fn log2(self) -> Self {
        let ln2 = T::from(std::f64::consts::LN_2).unwrap_or_else(T::nan);
        self.chain(self.re.log2(), (self.re * ln2).recip())
    }
    fn log10(self) -> Self {
        let ln10 = T::from(std::f64::consts::LN_10).unwrap_or_else(T::nan);
        self.chain(self.re.log10(), (self.re * ln10).recip())
    }
    fn ln_1p(self) -> Self {
        self.chain(self.re.ln_1p(), (T::one() + self.re).recip())
    }
    fn max(self, o: Self) -> Self {
        if o.re > self.re {
            o
        } else {
            self
        }
    }
    fn min(self, o: Self) -> Self {
        if o.re < self.re {
            o
        } else {
            self
        }
    }
    fn abs_sub(self, o: Self) -> Self {
        if self.re > o.re {
            self - o
        } else {
            Dual::zero()
        }
    }
    fn hypot(self, o: Self) -> Self {
        (self * self + o * o).sqrt()
    }
    fn sin(self) -> Self {
        self.chain(self.re.sin(), self.re.cos())
    }
    fn cos(self) -> Self {
        self.chain(self.re.cos(), -self.re.sin())
    }
    fn tan(self) -> Self {
        let t = self.re.tan();
        self.chain(t, T::one() + t * t)
    }
    fn asin(self) -> Self {
        self.chain(self.re.asin(), (T::one() - self.re * self.re).sqrt().recip())
    }
    fn acos(self) -> Self {
        self.chain(self.re.acos(), -(T::one() - self.re * self.re).sqrt().recip())
    }
    fn atan(self) -> Self {
        self.chain(self.re.atan(), (T::one() + self.re * self.re).recip())
    }
    fn atan2(self, x: Self) -> Self {
        let d = (self.re * self.re + x.re * x.re).recip();
        Dual { re: self.re.atan2(x.re), eps: (x.re * self.eps - self.re * x.eps) * d }
    }
    fn sin_cos(self) -> (Self, Self) {
        (self.sin(), self.cos())
    }
    fn sinh(self) -> Self {
        self.chain(self.re.sinh(), self.re.cosh())
    }
    fn cosh(self) -> Self {
        self.chain(self.re.cosh(), self.re.sinh())
    }
    fn tanh(self) -> Self {
        let t = self.re.tanh();
        self.chain(t, T::one() - t * t)
    }
    fn asinh(self) -> Self {
        self.chain(self.re.asinh(), (self.re * self.re + T::one()).sqrt().recip())
    }
    fn acosh(self) -> Self {
        self.chain(self.re.acosh(), (self.re * self.re - T::one()).sqrt().recip())
    }
    fn atanh(self) -> Self {
        self.chain(self.re.atanh(), (T::one() - self.re * self.re).recip())
    }
    fn integer_decode(self) -> (u64, i16, i8) {
        self.re.integer_decode()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(f: impl Fn(Dual<f64>) -> Dual<f64>, g: impl Fn(f64) -> f64, x: f64) {
        let d = f(Dual::variable(x));
        let h = 1e-6;
        let fd = (g(x + h) - g(x - h)) / (2.0 * h);
        assert!((d.re - g(x)).abs() < 1e-14);
        assert!((d.eps - fd).abs() < 1e-7 * fd.abs().max(1.0), "{} vs {}", d.eps, fd);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let x = 0.37;
        check(|v| v.sin() * v.cos(), |v| v.sin() * v.cos(), x);
        check(|v| v.tan() / (v + Dual::one()), |v| v.tan() / (v + 1.0), x);
        check(|v| v.asin() + v.acos().powi(3), |v| v.asin() + v.acos().powi(3), x);
        check(|v| v.atan2(v * v + Dual::one()), |v| v.atan2(v * v + 1.0), x);
        check(|v| v.sqrt().exp().ln_1p(), |v| v.sqrt().exp().ln_1p(), x);
        check(|v| v.powf(v), |v| v.powf(v), x);
        check(|v| v.tanh() + v.sinh() * v.cosh(), |v| v.tanh() + v.sinh() * v.cosh(), x);
        check(|v| v.log10() + v.log2() + v.cbrt(), |v| v.log10() + v.log2() + v.cbrt(), x);
        check(
            |v| v.asinh() + v.atanh() + (v + Dual::one()).acosh(),
            |v| v.asinh() + v.atanh() + (v + 1.0).acosh(),
            x,
        );
    }
}
