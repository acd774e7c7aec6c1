//! Smart constructors: the only place where canonical form is decided.
//!
//! Sums and products are flattened, like terms and like bases collected, numbers folded, the
//! identities with 0 and 1 applied, operands put in a stable order (by id, with the number
//! first), and odd or even functions given a non-negative argument.

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Func, Node, Parity};
use super::number::{float, Number, NumberFold, Rational};

type Res = Result<ExprId, ExprError>;

impl Arena {
    /// The canonical sum of `terms`.
    pub fn add(&mut self, terms: &[ExprId]) -> Res {
        let mut flat: Vec<ExprId> = Vec::with_capacity(terms.len() + 4);
        for &t in terms {
            match self.node(t) {
                Node::Sum(children) => flat.extend_from_slice(children),
                _ => flat.push(t),
            }
        }
        let mut constant = NumberFold::new(false);
        let mut entries: Vec<(ExprId, Number)> = Vec::with_capacity(flat.len());
        for t in flat {
            match self.as_number(t) {
                Some(n) => constant.add(n)?,
                None => {
                    let (c, rest) = self.split_coefficient(t);
                    entries.push((rest, c));
                }
            }
        }
        // Like terms become adjacent; their coefficients fold independently of input order.
        entries.sort_unstable_by_key(|e| e.0);
        let constant = constant.sum()?;
        let mut out = Vec::with_capacity(entries.len() + 1);
        if !constant.is_zero() {
            out.push(self.number(constant));
        }
        let mut i = 0;
        while i < entries.len() {
            let rest = entries[i].0;
            let j = i + entries[i..].iter().take_while(|e| e.0 == rest).count();
            let c = if j == i + 1 {
                entries[i].1
            } else {
                let mut f = NumberFold::new(false);
                for e in &entries[i..j] {
                    f.add(e.1)?;
                }
                f.sum()?
            };
            if !c.is_zero() {
                out.push(self.scale(c, rest)?);
            }
            i = j;
        }
        Ok(match out.len() {
            0 => self.number(constant),
            1 => out[0],
            _ => self.intern(Node::Sum(out.into_boxed_slice())),
        })
    }

    /// The canonical product of `factors`.
    pub fn mul(&mut self, factors: &[ExprId]) -> Res {
        let mut flat: Vec<ExprId> = Vec::with_capacity(factors.len() + 4);
        for &f in factors {
            match self.node(f) {
                Node::Product(children) => flat.extend_from_slice(children),
                _ => flat.push(f),
            }
        }
        let mut fold = NumberFold::new(true);
        // (base, exponent, the factor itself)
        let mut powers: Vec<(ExprId, ExprId, ExprId)> = Vec::with_capacity(flat.len());
        let one = self.one();
        for f in flat {
            match self.node(f) {
                Node::Rational(_) | Node::Float(_) => fold.mul(self.as_number(f).unwrap_or(Number::ONE))?,
                Node::Pow([b, e]) => powers.push((*b, *e, f)),
                _ => powers.push((f, one, f)),
            }
        }
        if fold.is_exact_zero() {
            return Ok(self.zero());
        }
        powers.sort_unstable_by_key(|p| p.0);
        let mut out: Vec<ExprId> = Vec::with_capacity(powers.len());
        let mut regroup = false;
        let mut i = 0;
        while i < powers.len() {
            let b = powers[i].0;
            let j = i + powers[i..].iter().take_while(|p| p.0 == b).count();
            if j == i + 1 {
                out.push(powers[i].2);
                i = j;
                continue;
            }
            let exps: Vec<ExprId> = powers[i..j].iter().map(|p| p.1).collect();
            i = j;
            let e = self.add(&exps)?;
            let p = self.pow(b, e)?;
            match self.node(p) {
                Node::Rational(_) | Node::Float(_) => fold.mul(self.as_number(p).unwrap_or(Number::ONE))?,
                Node::Product(_) => {
                    regroup = true;
                    out.push(p);
                }
                _ => out.push(p),
            }
        }
        let coeff = fold.product()?;
        if regroup {
            let c = self.number(coeff);
            out.push(c);
            return self.mul(&out);
        }
        if coeff.is_zero() {
            return Ok(self.number(coeff));
        }
        out.sort_unstable();
        match out.len() {
            0 => Ok(self.number(coeff)),
            1 if coeff.is_one() => Ok(out[0]),
            1 if matches!(self.node(out[0]), Node::Sum(_)) => {
                // A number times a sum distributes, so 2*(x+y) - 2*x - 2*y cancels without expansion.
                self.scale(coeff, out[0])
            }
            _ => {
                if !coeff.is_one() {
                    out.insert(0, self.number(coeff));
                }
                Ok(self.intern(Node::Product(out.into_boxed_slice())))
            }
        }
    }

    /// `c * e` for a number `c`, with `e` already canonical and not a number.
    fn scale(&mut self, c: Number, e: ExprId) -> Res {
        if c.is_one() {
            return Ok(e);
        }
        if c.is_zero() {
            return Ok(self.number(c));
        }
        match self.node(e) {
            Node::Sum(terms) => {
                let terms = terms.clone();
                let mut scaled = Vec::with_capacity(terms.len());
                for &t in terms.iter() {
                    scaled.push(match self.as_number(t) {
                        Some(n) => {
                            let v = n.checked_mul(c)?;
                            self.number(v)
                        }
                        None => {
                            let (k, rest) = self.split_coefficient(t);
                            self.scale(k.checked_mul(c)?, rest)?
                        }
                    });
                }
                self.add(&scaled)
            }
            Node::Product(f) => {
                let n = f.len();
                let (k, rest) = self.split_coefficient(e);
                let k = k.checked_mul(c)?;
                if k.is_one() {
                    return Ok(rest);
                }
                let mut v = Vec::with_capacity(n + 1);
                v.push(self.number(k));
                match self.node(rest) {
                    Node::Product(g) => v.extend(g.iter().copied()),
                    _ => v.push(rest),
                }
                Ok(self.intern(Node::Product(v.into_boxed_slice())))
            }
            _ => {
                let n = self.number(c);
                Ok(self.intern(Node::Product(Box::new([n, e]))))
            }
        }
    }

    /// Splits a non-number term into its numeric coefficient and the rest (`3*x*y` -> `(3, x*y)`).
    pub(crate) fn split_coefficient(&mut self, t: ExprId) -> (Number, ExprId) {
        if let Node::Product(f) = self.node(t) {
            if let Some(c) = self.as_number(f[0]) {
                let rest = if f.len() == 2 {
                    f[1]
                } else {
                    let rest: Box<[ExprId]> = f[1..].into();
                    self.intern(Node::Product(rest))
                };
                return (c, rest);
            }
        }
        (Number::ONE, t)
    }

    /// The canonical power `base ^ exponent`.
    pub fn pow(&mut self, base: ExprId, exponent: ExprId) -> Res {
        let eb = self.as_number(base);
        let ee = self.as_number(exponent);
        if let Some(e) = ee {
            if e.is_zero() {
                return Ok(self.one());
            }
            if e.is_one() {
                return Ok(base);
            }
        }
        if let Some(b) = eb {
            if b.is_one() {
                return Ok(self.one());
            }
            if b.is_zero() {
                return match ee {
                    Some(e) if e.is_negative() => Err(ExprError::DivisionByZero),
                    Some(_) => Ok(self.zero()),
                    None => Ok(self.intern(Node::Pow([base, exponent]))),
                };
            }
        }
        match (eb, ee) {
            (Some(Number::Rational(b)), Some(Number::Rational(e))) => {
                if let Some(folded) = fold_rational_power(b, e)? {
                    return Ok(self.intern(Node::Rational(folded)));
                }
            }
            (Some(b), Some(e)) => {
                let v = b.to_f64().powf(e.to_f64());
                if v.is_finite() {
                    return Ok(self.number(float(v)?));
                }
            }
            _ => {}
        }
        if let Some(Number::Rational(e)) = ee {
            if e.is_integer() {
                match self.node(base).clone() {
                    Node::Pow([b, inner]) => {
                        let new_e = self.mul(&[inner, exponent])?;
                        return self.pow(b, new_e);
                    }
                    Node::Product(f) => {
                        let mut parts = Vec::with_capacity(f.len());
                        for &x in f.iter() {
                            parts.push(self.pow(x, exponent)?);
                        }
                        return self.mul(&parts);
                    }
                    _ => {}
                }
            }
        }
        Ok(self.intern(Node::Pow([base, exponent])))
    }

    /// `a - b`.
    pub fn sub(&mut self, a: ExprId, b: ExprId) -> Res {
        let nb = self.neg(b)?;
        self.add(&[a, nb])
    }

    /// `-a`.
    pub fn neg(&mut self, a: ExprId) -> Res {
        let m = self.minus_one();
        self.mul(&[m, a])
    }

    /// `a / b`; errors when `b` is exactly zero.
    pub fn div(&mut self, a: ExprId, b: ExprId) -> Res {
        if self.as_number(b).is_some_and(Number::is_zero) {
            return Err(ExprError::DivisionByZero);
        }
        let m = self.minus_one();
        let inv = self.pow(b, m)?;
        self.mul(&[a, inv])
    }

    /// `a ^ n` for an integer `n`.
    pub fn powi(&mut self, a: ExprId, n: i64) -> Res {
        let e = self.integer(n as i128);
        self.pow(a, e)
    }

    /// The square root `a ^ (1/2)`.
    pub fn sqrt(&mut self, a: ExprId) -> Res {
        let half = self.rational(1, 2)?;
        self.pow(a, half)
    }

    /// An elementary function of `x`.
    pub fn func(&mut self, f: Func, x: ExprId) -> Res {
        if let Some(n) = self.as_number(x) {
            if let Some(v) = exact_value(f, n) {
                return Ok(self.intern(Node::Rational(v)));
            }
            if let Number::Float(v) = n {
                let y = f.apply(v);
                if y.is_finite() {
                    return Ok(self.number(float(y)?));
                }
            }
        }
        if f == Func::Ln {
            if let Node::Func(Func::Exp, inner) = *self.node(x) {
                return Ok(inner);
            }
        }
        let parity = f.parity();
        if parity != Parity::None && self.is_negated(x) {
            let pos = self.neg(x)?;
            let inner = self.intern(Node::Func(f, pos));
            return match parity {
                Parity::Odd => self.neg(inner),
                _ => Ok(inner),
            };
        }
        Ok(self.intern(Node::Func(f, x)))
    }

    /// `sin(x)`.
    pub fn sin(&mut self, x: ExprId) -> Res {
        self.func(Func::Sin, x)
    }

    /// `cos(x)`.
    pub fn cos(&mut self, x: ExprId) -> Res {
        self.func(Func::Cos, x)
    }

    /// `atan2(y, x)`.
    pub fn atan2(&mut self, y: ExprId, x: ExprId) -> Res {
        if let (Some(a), Some(b)) = (self.as_number(y), self.as_number(x)) {
            if a.is_zero() && !b.is_negative() && !b.is_zero() {
                return Ok(self.zero());
            }
            let v = a.to_f64().atan2(b.to_f64());
            if matches!(a, Number::Float(_)) || matches!(b, Number::Float(_)) {
                return Ok(self.number(float(v)?));
            }
        }
        Ok(self.intern(Node::Atan2([y, x])))
    }

    /// True when `x` carries a leading minus sign in canonical form.
    pub(crate) fn is_negated(&self, x: ExprId) -> bool {
        match self.node(x) {
            Node::Rational(r) => r.is_negative(),
            Node::Float(b) => f64::from_bits(*b) < 0.0,
            Node::Product(f) => self.as_number(f[0]).is_some_and(Number::is_negative),
            Node::Sum(t) => {
                let first = if self.as_number(t[0]).is_some() { t[1] } else { t[0] };
                self.is_negated(first)
            }
            _ => false,
        }
    }
}

/// Exact values of functions at exact arguments (`sin(0) = 0`, `cos(0) = 1`, ...).
fn exact_value(f: Func, n: Number) -> Option<Rational> {
    let Number::Rational(r) = n else { return None };
    if r.is_zero() {
        return match f {
            Func::Sin | Func::Tan | Func::Asin | Func::Atan | Func::Sinh | Func::Tanh => Some(Rational::ZERO),
            Func::Abs | Func::Sign => Some(Rational::ZERO),
            Func::Cos | Func::Cosh | Func::Exp => Some(Rational::ONE),
            Func::Acos | Func::Ln => None,
        };
    }
    match f {
        Func::Ln if r.is_one() => Some(Rational::ZERO),
        Func::Abs => Some(if r.is_negative() { r.checked_neg().ok()? } else { r }),
        Func::Sign => Some(if r.is_negative() { Rational::MINUS_ONE } else { Rational::ONE }),
        _ => None,
    }
}

/// `b^e` when it is an exact rational (integer powers, perfect roots); `None` otherwise.
fn fold_rational_power(b: Rational, e: Rational) -> Result<Option<Rational>, ExprError> {
    if e.is_integer() {
        let k = e.as_i64().ok_or(ExprError::RationalOverflow)?;
        if b == Rational::MINUS_ONE {
            return Ok(Some(if k % 2 == 0 { Rational::ONE } else { b }));
        }
        return b.powi(k).map(Some);
    }
    if b.is_negative() {
        return Ok(None);
    }
    let (Ok(q), Some(p)) = (u32::try_from(e.denom()), e.as_i64().or(i64::try_from(e.numer()).ok())) else {
        return Ok(None);
    };
    match (integer_root(b.numer(), q), integer_root(b.denom(), q)) {
        (Some(n), Some(d)) => Ok(Some(Rational::new(n, d)?.powi(p)?)),
        _ => Ok(None),
    }
}

/// The exact `q`-th root of a non-negative integer, if it is one.
fn integer_root(n: i128, q: u32) -> Option<i128> {
    if n < 0 || q == 0 {
        return None;
    }
    let guess = (n as f64).powf(1.0 / q as f64).round() as i128;
    (guess.saturating_sub(1)..=guess + 1).find(|&g| g >= 0 && g.checked_pow(q).is_some_and(|v| v == n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::arena::Arena;

    fn xy(ar: &mut Arena) -> (ExprId, ExprId) {
        (ar.constant("x").unwrap(), ar.constant("y").unwrap())
    }

    #[test]
    fn like_terms_collect() {
        let mut ar = Arena::new();
        let (x, y) = xy(&mut ar);
        let two = ar.integer(2);
        let tx = ar.mul(&[two, x]).unwrap();
        let s = ar.add(&[x, y, tx]).unwrap();
        let three = ar.integer(3);
        let t3 = ar.mul(&[three, x]).unwrap();
        let expected = ar.add(&[t3, y]).unwrap();
        assert_eq!(s, expected);
        let back = ar.sub(s, t3).unwrap();
        assert_eq!(back, y);
    }

    #[test]
    fn x_times_x_is_a_square() {
        let mut ar = Arena::new();
        let (x, _) = xy(&mut ar);
        let p = ar.mul(&[x, x]).unwrap();
        assert_eq!(p, ar.powi(x, 2).unwrap());
        let q = ar.div(p, x).unwrap();
        assert_eq!(q, x);
    }

    #[test]
    fn identities_with_zero_and_one() {
        let mut ar = Arena::new();
        let (x, _) = xy(&mut ar);
        let (z, o) = (ar.zero(), ar.one());
        assert_eq!(ar.add(&[x, z]).unwrap(), x);
        assert_eq!(ar.mul(&[x, o]).unwrap(), x);
        assert_eq!(ar.mul(&[x, z]).unwrap(), z);
        assert_eq!(ar.pow(x, z).unwrap(), o);
        assert_eq!(ar.div(x, z), Err(ExprError::DivisionByZero));
        assert_eq!(ar.pow(z, ar.minus_one()), Err(ExprError::DivisionByZero));
    }

    #[test]
    fn numbers_fold_exactly() {
        let mut ar = Arena::new();
        let a = ar.rational(1, 3).unwrap();
        let b = ar.rational(1, 6).unwrap();
        let s = ar.add(&[a, b]).unwrap();
        assert_eq!(ar.as_rational(s), Some(Rational::new(1, 2).unwrap()));
        let four = ar.integer(4);
        let r = ar.sqrt(four).unwrap();
        assert_eq!(r, ar.integer(2));
        let two = ar.integer(2);
        let s2 = ar.sqrt(two).unwrap();
        assert!(matches!(ar.node(s2), Node::Pow(_)));
        assert_eq!(ar.mul(&[s2, s2]).unwrap(), two);
    }

    #[test]
    fn parity_of_trig_functions() {
        let mut ar = Arena::new();
        let (x, y) = xy(&mut ar);
        let nx = ar.neg(x).unwrap();
        let sx = ar.sin(x).unwrap();
        assert_eq!(ar.sin(nx).unwrap(), ar.neg(sx).unwrap());
        assert_eq!(ar.cos(nx).unwrap(), ar.cos(x).unwrap());
        let d = ar.sub(y, x).unwrap();
        let e = ar.sub(x, y).unwrap();
        let cd = ar.cos(d).unwrap();
        assert_eq!(cd, ar.cos(e).unwrap());
    }

    #[test]
    fn number_times_sum_distributes() {
        let mut ar = Arena::new();
        let (x, y) = xy(&mut ar);
        let s = ar.add(&[x, y]).unwrap();
        let two = ar.integer(2);
        let d = ar.mul(&[two, s]).unwrap();
        let tx = ar.mul(&[two, x]).unwrap();
        let ty = ar.mul(&[two, y]).unwrap();
        let r = ar.sub(d, tx).unwrap();
        assert_eq!(ar.sub(r, ty).unwrap(), ar.zero());
    }

    #[test]
    fn rational_overflow_is_an_error() {
        let mut ar = Arena::new();
        let big = ar.integer(10);
        let e = ar.integer(60);
        assert_eq!(ar.pow(big, e), Err(ExprError::RationalOverflow));
    }
}
