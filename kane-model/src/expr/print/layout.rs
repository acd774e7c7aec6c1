//! The printed structure of an expression, shared by every printer.
//!
//! The walker turns canonical nodes into what a reader expects (subtraction, quotients,
//! square roots, coefficients in front) and asks a [`Syntax`] to spell each piece.

use super::super::arena::Arena;
use super::super::node::{ExprId, Func, Node, SymbolId};
use super::super::number::{Number, Rational};

/// Binding strength of a printed piece; higher binds tighter.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
pub(crate) enum Prec {
    Sum,
    Product,
    Neg,
    Pow,
    Atom,
}

/// How a printer spells each construct; every method receives pieces with their precedence.
pub(crate) trait Syntax {
    type Out: Clone;
    fn number(&mut self, n: Number) -> Self::Out;
    fn symbol(&mut self, s: SymbolId) -> Self::Out;
    fn named(&mut self, id: ExprId) -> Option<Self::Out>;
    fn paren(&mut self, x: Self::Out) -> Self::Out;
    /// `first (+|-) rest...`; `negative[i]` says whether term i is subtracted.
    fn sum(&mut self, terms: Vec<(bool, Self::Out)>) -> Self::Out;
    fn neg(&mut self, x: (Self::Out, Prec)) -> Self::Out;
    fn product(&mut self, factors: Vec<(Self::Out, Prec)>) -> Self::Out;
    /// True for a factor whose value arrives late (generated code multiplies those last).
    fn late(&mut self, _id: ExprId) -> bool {
        false
    }
    /// A product of `early` factors and then `late` ones.
    fn product_grouped(
        &mut self,
        mut early: Vec<(Self::Out, Prec)>,
        late: Vec<(Self::Out, Prec)>,
    ) -> Self::Out {
        early.extend(late);
        self.product(early)
    }
    fn quotient(&mut self, num: (Self::Out, Prec), den: (Self::Out, Prec)) -> Self::Out;
    fn pow_int(&mut self, base: (Self::Out, Prec), k: i64) -> Self::Out;
    fn pow(&mut self, base: (Self::Out, Prec), exp: (Self::Out, Prec)) -> Self::Out;
    fn sqrt(&mut self, x: (Self::Out, Prec)) -> Self::Out;
    fn func(&mut self, f: Func, x: (Self::Out, Prec)) -> Self::Out;
    fn atan2(&mut self, y: Self::Out, x: Self::Out) -> Self::Out;
}

/// Lays out `e` with `syntax`; `top` is true for the root (a CSE name is not used for it).
pub(crate) fn layout<S: Syntax>(ar: &Arena, e: ExprId, syntax: &mut S, top: bool) -> (S::Out, Prec) {
    if !top {
        if let Some(n) = syntax.named(e) {
            return (n, Prec::Atom);
        }
    }
    match ar.node(e) {
        Node::Rational(_) | Node::Float(_) => {
            let n = ar.as_number(e).unwrap_or(Number::ZERO);
            number(n, syntax)
        }
        Node::Symbol(s) => (syntax.symbol(*s), Prec::Atom),
        Node::Sum(terms) => {
            // Print the numeric term last, as people write `x + 1`.
            let mut ordered: Vec<ExprId> =
                terms.iter().copied().filter(|t| ar.as_number(*t).is_none()).collect();
            ordered.extend(terms.iter().copied().filter(|t| ar.as_number(*t).is_some()));
            let parts = ordered
                .into_iter()
                .map(|t| {
                    let neg = ar.is_negated(t) && syntax.named(t).is_none();
                    let (out, prec) =
                        if neg { magnitude(ar, t, syntax) } else { layout(ar, t, syntax, false) };
                    let out = if prec <= Prec::Sum { syntax.paren(out) } else { out };
                    (neg, out)
                })
                .collect();
            (syntax.sum(parts), Prec::Sum)
        }
        Node::Product(_) | Node::Pow(_) if ar.is_negated(e) => {
            let m = magnitude(ar, e, syntax);
            (syntax.neg(m), Prec::Neg)
        }
        Node::Product(_) | Node::Pow(_) => product(ar, e, syntax),
        Node::Func(f, x) => {
            let a = layout(ar, *x, syntax, false);
            (syntax.func(*f, a), Prec::Atom)
        }
        Node::Atan2([y, x]) => {
            let (a, _) = layout(ar, *y, syntax, false);
            let (b, _) = layout(ar, *x, syntax, false);
            (syntax.atan2(a, b), Prec::Atom)
        }
    }
}

fn number<S: Syntax>(n: Number, syntax: &mut S) -> (S::Out, Prec) {
    let mag = match n {
        Number::Rational(r) => Number::Rational(r.checked_neg().unwrap_or(r)),
        Number::Float(x) => Number::Float(-x),
    };
    if n.is_negative() {
        let inner = number(mag, syntax);
        return (syntax.neg(inner), Prec::Neg);
    }
    match n {
        Number::Rational(r) if !r.is_integer() => {
            let p = syntax.number(Number::Rational(Rational::integer(r.numer())));
            let q = syntax.number(Number::Rational(Rational::integer(r.denom())));
            (syntax.quotient((p, Prec::Atom), (q, Prec::Atom)), Prec::Product)
        }
        _ => (syntax.number(n), Prec::Atom),
    }
}

/// Lays out `-t` for a term `t` that carries a leading minus sign.
fn magnitude<S: Syntax>(ar: &Arena, t: ExprId, syntax: &mut S) -> (S::Out, Prec) {
    match ar.node(t) {
        Node::Rational(r) => number(Number::Rational(r.checked_neg().unwrap_or(*r)), syntax),
        Node::Float(b) => number(Number::Float(-f64::from_bits(*b)), syntax),
        Node::Product(_) => product(ar, t, syntax),
        _ => {
            let (x, p) = layout(ar, t, syntax, false);
            (syntax.neg((x, p)), Prec::Neg)
        }
    }
}

/// Lays out a product (or power) as `coefficient * numerator / denominator`, ignoring its sign.
fn product<S: Syntax>(ar: &Arena, e: ExprId, syntax: &mut S) -> (S::Out, Prec) {
    let factors: Vec<ExprId> = match ar.node(e) {
        Node::Product(f) => f.to_vec(),
        _ => vec![e],
    };
    let mut coeff = Rational::ONE;
    let mut num: Vec<(S::Out, Prec)> = Vec::new();
    let mut late_num: Vec<(S::Out, Prec)> = Vec::new();
    let mut den: Vec<(S::Out, Prec)> = Vec::new();
    for f in factors {
        if f != e
            && syntax.late(f)
            && !matches!(ar.node(f), Node::Pow([_, x]) if ar.as_rational(*x).is_some_and(|r| r.is_negative()))
        {
            late_num.push(layout(ar, f, syntax, false));
            continue;
        }
        // The power being laid out is not replaced by its own name.
        let named_elsewhere = f != e && syntax.named(f).is_some();
        match ar.node(f) {
            Node::Rational(r) => coeff = if r.is_negative() { r.checked_neg().unwrap_or(*r) } else { *r },
            Node::Float(b) => num.push((syntax.number(Number::Float(f64::from_bits(*b).abs())), Prec::Atom)),
            Node::Pow([b, x]) if !named_elsewhere => match ar.as_rational(*x) {
                Some(r) if r.is_negative() => {
                    let pos = r.checked_neg().unwrap_or(r);
                    den.push(power(ar, *b, pos, syntax));
                }
                Some(r) => num.push(power(ar, *b, r, syntax)),
                None => {
                    let base = layout(ar, *b, syntax, false);
                    let exp = layout(ar, *x, syntax, false);
                    num.push((syntax.pow(base, exp), Prec::Pow));
                }
            },
            _ => num.push(layout(ar, f, syntax, false)),
        }
    }
    if coeff.numer() != 1 {
        let c = syntax.number(Number::Rational(Rational::integer(coeff.numer())));
        num.insert(0, (c, Prec::Atom));
    }
    if coeff.denom() != 1 {
        let c = syntax.number(Number::Rational(Rational::integer(coeff.denom())));
        den.insert(0, (c, Prec::Atom));
    }
    let numerator = match (num.len(), late_num.len()) {
        (0, 0) => (syntax.number(Number::ONE), Prec::Atom),
        (1, 0) => num.pop().unwrap_or_else(|| unreachable_piece(syntax)),
        (0, 1) => late_num.pop().unwrap_or_else(|| unreachable_piece(syntax)),
        _ => (syntax.product_grouped(num, late_num), Prec::Product),
    };
    match den.len() {
        0 => numerator,
        1 => {
            let d = den.pop().unwrap_or_else(|| unreachable_piece(syntax));
            (syntax.quotient(numerator, d), Prec::Product)
        }
        _ => {
            let d = (syntax.product(den), Prec::Product);
            (syntax.quotient(numerator, d), Prec::Product)
        }
    }
}

fn unreachable_piece<S: Syntax>(syntax: &mut S) -> (S::Out, Prec) {
    (syntax.number(Number::ONE), Prec::Atom)
}

/// `b ^ r` for a positive rational `r`: plain for 1, `sqrt` for 1/2, integer powers, or general.
fn power<S: Syntax>(ar: &Arena, b: ExprId, r: Rational, syntax: &mut S) -> (S::Out, Prec) {
    let base = layout(ar, b, syntax, false);
    if r.is_one() {
        return base;
    }
    if r.numer() == 1 && r.denom() == 2 {
        return (syntax.sqrt(base), Prec::Atom);
    }
    match r.as_i64() {
        Some(k) => (syntax.pow_int(base, k), Prec::Pow),
        None => {
            let exp = number(Number::Rational(r), syntax);
            (syntax.pow(base, exp), Prec::Pow)
        }
    }
}
