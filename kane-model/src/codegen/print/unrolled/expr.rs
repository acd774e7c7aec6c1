//! Arithmetic on known coefficients, printed with the fewest parentheses that keep its order of
//! operations: in come zeros, ones and atoms (locals, literals); out goes a Rust expression.
//! Zeros and ones fold away (`0 + x = x`, `0 x = 0`, `1 x = x`, `x / 1 = x`), exact but for
//! the sign of a zero, so a folded sum rounds as the unfolded one.

use proc_macro2::TokenStream;
use quote::quote;

/// A coefficient expression.
#[derive(Clone, Debug)]
pub enum X {
    /// Exactly zero.
    Zero,
    /// Exactly one.
    One,
    /// A local or a literal.
    Atom(TokenStream),
    /// `a + b`.
    Add(Box<X>, Box<X>),
    /// `a - b`.
    Sub(Box<X>, Box<X>),
    /// `a * b`.
    Mul(Box<X>, Box<X>),
    /// `a * b + c` with one rounding (`mul_add`).
    MulAdd(Box<X>, Box<X>, Box<X>),
    /// `a / b`.
    Div(Box<X>, Box<X>),
    /// `-a`.
    Neg(Box<X>),
    /// `if c < 0 { -a } else { a }` (`c` the sign, `a` the value).
    SignOf(Box<X>, Box<X>),
}

impl X {
    /// An atom.
    pub fn atom(tokens: TokenStream) -> X {
        X::Atom(tokens)
    }

    /// Is exactly zero.
    fn is_zero(&self) -> bool {
        matches!(self, X::Zero)
    }

    /// `self + b`.
    pub fn plus(self, b: X) -> X {
        match (self, b) {
            (X::Zero, b) => b,
            (a, X::Zero) => a,
            (a, b) => X::Add(Box::new(a), Box::new(b)),
        }
    }

    /// `self + t`, fused into one `mul_add` when `t` is a product.
    pub fn plus_fused(self, t: X) -> X {
        match (self, t) {
            (X::Zero, t) => t,
            (a, X::Mul(x, y)) => X::MulAdd(x, y, Box::new(a)),
            (a, t) => a.plus(t),
        }
    }

    /// `self - b`.
    pub fn minus(self, b: X) -> X {
        match (self, b) {
            (a, X::Zero) => a,
            (X::Zero, b) => b.negated(),
            (a, b) => X::Sub(Box::new(a), Box::new(b)),
        }
    }

    /// `self * b`.
    pub fn times(self, b: X) -> X {
        match (self, b) {
            (a, b) if a.is_zero() || b.is_zero() => X::Zero,
            (X::One, b) => b,
            (a, X::One) => a,
            (a, b) => X::Mul(Box::new(a), Box::new(b)),
        }
    }

    /// `self / b`.
    pub fn over(self, b: X) -> X {
        match (self, b) {
            (X::Zero, _) => X::Zero,
            (a, X::One) => a,
            (a, b) => X::Div(Box::new(a), Box::new(b)),
        }
    }

    /// `-self`.
    pub fn negated(self) -> X {
        match self {
            X::Zero => X::Zero,
            X::Neg(a) => *a,
            a => X::Neg(Box::new(a)),
        }
    }

    /// `self` with the sign flipped where `sign` is negative.
    pub fn sign_of(self, sign: X) -> X {
        match self {
            X::Zero => X::Zero,
            a => X::SignOf(Box::new(a), Box::new(sign)),
        }
    }

    /// Binding strength: sums 1, products 2, negation 3, atoms 4.
    fn precedence(&self) -> u8 {
        match self {
            X::Add(..) | X::Sub(..) => 1,
            X::Mul(..) | X::Div(..) => 2,
            X::Neg(_) => 3,
            X::Zero | X::One | X::Atom(_) | X::SignOf(..) | X::MulAdd(..) => 4,
        }
    }

    /// The expression as Rust in the number type `T` (`Zero`, `One` as `T::zero()`, `T::one()`).
    pub fn tokens(&self) -> TokenStream {
        match self {
            X::Zero => quote!(T::zero()),
            X::One => quote!(T::one()),
            X::Atom(t) => t.clone(),
            X::Add(a, b) => self.binary(a, quote!(+), b),
            X::Sub(a, b) => self.binary(a, quote!(-), b),
            X::Mul(a, b) => self.binary(a, quote!(*), b),
            X::Div(a, b) => self.binary(a, quote!(/), b),
            X::Neg(a) => {
                let a = a.operand(3, false);
                quote!(-#a)
            }
            X::MulAdd(..) => self.chain_tokens(),
            X::SignOf(a, s) => {
                let (a, s) = (a.tokens(), s.tokens());
                quote!((if #s < T::zero() { -(#a) } else { #a }))
            }
        }
    }

    /// A chain of `mul_add`s (each the addend of the next) as one statement per link,
    /// `{ let mut __s: T = base; __s = x.mul_add(y, __s); ... __s }`: flat, where nested calls
    /// would indent once per term.
    fn chain_tokens(&self) -> TokenStream {
        let mut links = Vec::new();
        let mut at = self;
        while let X::MulAdd(x, y, rest) = at {
            links.push((x.operand(4, false), y.tokens()));
            at = rest;
        }
        let base = at.tokens();
        if let [(x, y)] = &links[..] {
            return quote!(#x.mul_add(#y, #base));
        }
        let steps = links.iter().rev().map(|(x, y)| quote!(__s = #x.mul_add(#y, __s);));
        quote!({
            let mut __s: T = #base;
            #(#steps)*
            __s
        })
    }

    /// `a op b`, both sides parenthesised where the order of operations needs it (operators
    /// associate to the left, so a right operand of equal strength is parenthesised).
    fn binary(&self, a: &X, op: TokenStream, b: &X) -> TokenStream {
        let p = self.precedence();
        let (a, b) = (a.operand(p, false), b.operand(p, true));
        quote!(#a #op #b)
    }

    /// `self` as an operand of an operator of strength `outer` (on its right side if `right`).
    fn operand(&self, outer: u8, right: bool) -> TokenStream {
        let p = self.precedence();
        let t = self.tokens();
        if p < outer || (p == outer && right) {
            quote!((#t))
        } else {
            t
        }
    }
}
