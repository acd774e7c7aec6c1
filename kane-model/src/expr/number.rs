//! Exact rationals and floating literals: the numeric coefficients of expressions.

use std::cmp::Ordering;
use std::fmt;

use super::error::ExprError;

/// An exact rational number `num/den` in lowest terms with `den > 0`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Rational {
    num: i128,
    den: i128,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        let r = a % b;
        a = b;
        b = r;
    }
    a
}

impl Rational {
    /// The rational zero, 0/1.
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    /// The rational one, 1/1.
    pub const ONE: Rational = Rational { num: 1, den: 1 };
    /// Minus one.
    pub const MINUS_ONE: Rational = Rational { num: -1, den: 1 };

    /// The integer `n`.
    pub const fn integer(n: i128) -> Rational {
        Rational { num: n, den: 1 }
    }

    /// `num/den` reduced to lowest terms; errors on a zero denominator or overflow.
    pub fn new(num: i128, den: i128) -> Result<Rational, ExprError> {
        if den == 0 {
            return Err(ExprError::DivisionByZero);
        }
        let g = gcd(num, den);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = n.checked_neg().ok_or(ExprError::RationalOverflow)?;
            d = d.checked_neg().ok_or(ExprError::RationalOverflow)?;
        }
        Ok(Rational { num: n, den: d })
    }

    /// Numerator (carries the sign).
    pub fn numer(self) -> i128 {
        self.num
    }

    /// Denominator (always positive).
    pub fn denom(self) -> i128 {
        self.den
    }

    /// True for zero.
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// True for one.
    pub fn is_one(self) -> bool {
        self.num == 1 && self.den == 1
    }

    /// True when the denominator is one.
    pub fn is_integer(self) -> bool {
        self.den == 1
    }

    /// True when strictly negative.
    pub fn is_negative(self) -> bool {
        self.num < 0
    }

    /// The value as an `i64` if it is an integer that fits.
    pub fn as_i64(self) -> Option<i64> {
        if self.den == 1 {
            i64::try_from(self.num).ok()
        } else {
            None
        }
    }

    /// Checked sum.
    pub fn checked_add(self, o: Rational) -> Result<Rational, ExprError> {
        let g = gcd(self.den, o.den);
        let (a, b) = (self.den / g, o.den / g);
        let n = mul_i128(self.num, b)?.checked_add(mul_i128(o.num, a)?).ok_or(ExprError::RationalOverflow)?;
        Rational::new(n, mul_i128(self.den, b)?)
    }

    /// Checked difference.
    pub fn checked_sub(self, o: Rational) -> Result<Rational, ExprError> {
        self.checked_add(o.checked_neg()?)
    }

    /// Checked negation.
    pub fn checked_neg(self) -> Result<Rational, ExprError> {
        Ok(Rational { num: self.num.checked_neg().ok_or(ExprError::RationalOverflow)?, den: self.den })
    }

    /// Checked product.
    pub fn checked_mul(self, o: Rational) -> Result<Rational, ExprError> {
        let g1 = gcd(self.num, o.den).max(1);
        let g2 = gcd(o.num, self.den).max(1);
        Rational::new(mul_i128(self.num / g1, o.num / g2)?, mul_i128(self.den / g2, o.den / g1)?)
    }

    /// Checked reciprocal; errors on zero.
    pub fn recip(self) -> Result<Rational, ExprError> {
        Rational::new(self.den, self.num)
    }

    /// Checked quotient; errors on a zero divisor.
    pub fn checked_div(self, o: Rational) -> Result<Rational, ExprError> {
        self.checked_mul(o.recip()?)
    }

    /// Checked integer power; errors on `0^negative` and overflow.
    pub fn powi(self, e: i64) -> Result<Rational, ExprError> {
        let base = if e < 0 { self.recip()? } else { self };
        let mut acc = Rational::ONE;
        let mut b = base;
        let mut k = e.unsigned_abs();
        while k > 0 {
            if k & 1 == 1 {
                acc = acc.checked_mul(b)?;
            }
            k >>= 1;
            if k > 0 {
                b = b.checked_mul(b)?;
            }
        }
        Ok(acc)
    }

    /// Nearest `f64`.
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

fn mul_i128(a: i128, b: i128) -> Result<i128, ExprError> {
    a.checked_mul(b).ok_or(ExprError::RationalOverflow)
}

impl Ord for Rational {
    fn cmp(&self, o: &Self) -> Ordering {
        // Compare a/b with c/d through i128 products when they fit, else through f64.
        match (self.num.checked_mul(o.den), o.num.checked_mul(self.den)) {
            (Some(l), Some(r)) => l.cmp(&r),
            _ => self.to_f64().total_cmp(&o.to_f64()),
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

/// A numeric value: exact rational or floating literal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Number {
    /// Exact rational.
    Rational(Rational),
    /// Floating literal (finite).
    Float(f64),
}

impl Number {
    /// Exact zero.
    pub const ZERO: Number = Number::Rational(Rational::ZERO);
    /// Exact one.
    pub const ONE: Number = Number::Rational(Rational::ONE);

    /// True if exactly zero (a float literal 0.0 counts).
    pub fn is_zero(self) -> bool {
        match self {
            Number::Rational(r) => r.is_zero(),
            Number::Float(x) => x == 0.0,
        }
    }

    /// True if exactly one.
    pub fn is_one(self) -> bool {
        match self {
            Number::Rational(r) => r.is_one(),
            Number::Float(x) => x == 1.0,
        }
    }

    /// True if strictly negative.
    pub fn is_negative(self) -> bool {
        match self {
            Number::Rational(r) => r.is_negative(),
            Number::Float(x) => x < 0.0,
        }
    }

    /// Nearest `f64`.
    pub fn to_f64(self) -> f64 {
        match self {
            Number::Rational(r) => r.to_f64(),
            Number::Float(x) => x,
        }
    }

    /// Sum; exact when both are rational.
    pub fn checked_add(self, o: Number) -> Result<Number, ExprError> {
        match (self, o) {
            (Number::Rational(a), Number::Rational(b)) => Ok(Number::Rational(a.checked_add(b)?)),
            _ => float(self.to_f64() + o.to_f64()),
        }
    }

    /// Product; exact when both are rational.
    pub fn checked_mul(self, o: Number) -> Result<Number, ExprError> {
        match (self, o) {
            (Number::Rational(a), Number::Rational(b)) => Ok(Number::Rational(a.checked_mul(b)?)),
            _ => float(self.to_f64() * o.to_f64()),
        }
    }

    /// The number negated; an error when that overflows.
    pub fn checked_neg(self) -> Result<Number, ExprError> {
        match self {
            Number::Rational(a) => Ok(Number::Rational(a.checked_neg()?)),
            Number::Float(x) => Ok(Number::Float(-x)),
        }
    }
}

/// Order-independent accumulation of numbers: rationals exactly, floats in sorted order, so a
/// sum or product of the same numbers gives the same bits whatever order they come in.
#[derive(Clone, Debug)]
pub(crate) struct NumberFold {
    exact: Rational,
    floats: Vec<f64>,
}

impl NumberFold {
    /// Starts a sum (at 0) or a product (at 1).
    pub(crate) fn new(product: bool) -> NumberFold {
        NumberFold { exact: if product { Rational::ONE } else { Rational::ZERO }, floats: Vec::new() }
    }

    /// Adds `n` to a sum.
    pub(crate) fn add(&mut self, n: Number) -> Result<(), ExprError> {
        match n {
            Number::Rational(r) => self.exact = self.exact.checked_add(r)?,
            Number::Float(x) => self.floats.push(x),
        }
        Ok(())
    }

    /// Multiplies a product by `n`.
    pub(crate) fn mul(&mut self, n: Number) -> Result<(), ExprError> {
        match n {
            Number::Rational(r) => self.exact = self.exact.checked_mul(r)?,
            Number::Float(x) => self.floats.push(x),
        }
        Ok(())
    }

    /// True when the product so far is exactly zero.
    pub(crate) fn is_exact_zero(&self) -> bool {
        self.exact.is_zero()
    }

    /// The sum.
    pub(crate) fn sum(mut self) -> Result<Number, ExprError> {
        if self.floats.is_empty() {
            return Ok(Number::Rational(self.exact));
        }
        self.floats.sort_unstable_by(f64::total_cmp);
        float(self.floats.iter().fold(self.exact.to_f64(), |a, b| a + b))
    }

    /// The product.
    pub(crate) fn product(mut self) -> Result<Number, ExprError> {
        if self.floats.is_empty() {
            return Ok(Number::Rational(self.exact));
        }
        self.floats.sort_unstable_by(f64::total_cmp);
        float(self.floats.iter().fold(self.exact.to_f64(), |a, b| a * b))
    }
}

/// A float literal, rejecting non-finite values.
pub(crate) fn float(x: f64) -> Result<Number, ExprError> {
    if x.is_finite() {
        Ok(Number::Float(if x == 0.0 { 0.0 } else { x }))
    } else {
        Err(ExprError::NonFiniteLiteral(x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduces_and_normalises_sign() {
        let r = Rational::new(6, -4).unwrap();
        assert_eq!((r.numer(), r.denom()), (-3, 2));
        assert_eq!(r.to_string(), "-3/2");
    }

    #[test]
    fn arithmetic_is_exact() {
        let a = Rational::new(1, 3).unwrap();
        let b = Rational::new(1, 6).unwrap();
        assert_eq!(a.checked_add(b).unwrap(), Rational::new(1, 2).unwrap());
        assert_eq!(a.checked_mul(b).unwrap(), Rational::new(1, 18).unwrap());
        assert_eq!(a.checked_div(b).unwrap(), Rational::integer(2));
        assert_eq!(b.powi(-2).unwrap(), Rational::integer(36));
    }

    #[test]
    fn overflow_is_reported_not_wrapped() {
        let big = Rational::integer(i128::MAX / 2 + 1);
        assert_eq!(big.checked_add(big), Err(ExprError::RationalOverflow));
        assert_eq!(Rational::integer(10).powi(60), Err(ExprError::RationalOverflow));
    }

    #[test]
    fn zero_divisor_is_an_error() {
        assert_eq!(Rational::new(1, 0), Err(ExprError::DivisionByZero));
        assert_eq!(Rational::ZERO.powi(-1), Err(ExprError::DivisionByZero));
    }

    #[test]
    fn ordering_compares_values() {
        let a = Rational::new(-1, 2).unwrap();
        let b = Rational::new(1, 3).unwrap();
        assert!(a < b);
    }
}
