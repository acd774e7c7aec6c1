//! Rust expressions as tokens, generic over the float type or in plain `f64`.

use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;
use rustc_hash::FxHashMap;

use super::super::arena::Arena;
use super::super::node::{ExprId, Func, SymbolId};
use super::super::number::Number;
use super::layout::{layout, Prec, Syntax};

/// The number type emitted code computes in.
#[derive(Clone, Debug)]
pub enum Scalar {
    /// Plain `f64`, with literal constants.
    F64,
    /// A type parameter bounded by `num_traits::Float`; constants via `T::from(..)`.
    Generic(Ident),
}

/// How to spell symbols and named subexpressions in emitted Rust.
pub struct RustStyle<'a> {
    /// The number type.
    pub scalar: Scalar,
    /// Tokens that read a symbol's value, for example `p.m` or `y[0]`.
    pub symbol: &'a dyn Fn(SymbolId) -> TokenStream,
    /// Subexpressions already bound to local names (from CSE).
    pub names: Option<&'a FxHashMap<ExprId, TokenStream>>,
    /// Factors whose values arrive late (for example the speeds a stage has just computed):
    /// products multiply the others first, so the late ones pass through fewer multiplications.
    pub late: Option<&'a dyn Fn(ExprId) -> bool>,
}

struct Rust<'a, 'b> {
    style: &'b RustStyle<'a>,
}

fn wrap(x: (TokenStream, Prec), min: Prec) -> TokenStream {
    let t = x.0;
    if x.1 < min {
        quote!((#t))
    } else {
        t
    }
}

impl Syntax for Rust<'_, '_> {
    type Out = TokenStream;
    fn number(&mut self, n: Number) -> TokenStream {
        let lit = Literal::f64_suffixed(n.to_f64());
        match &self.style.scalar {
            Scalar::F64 => quote!(#lit),
            Scalar::Generic(t) => quote!(::kane_model::__private::cast::<#t>(#lit)),
        }
    }
    fn symbol(&mut self, s: SymbolId) -> TokenStream {
        (self.style.symbol)(s)
    }
    fn named(&mut self, id: ExprId) -> Option<TokenStream> {
        self.style.names.and_then(|n| n.get(&id).cloned())
    }
    fn paren(&mut self, x: TokenStream) -> TokenStream {
        quote!((#x))
    }
    fn sum(&mut self, terms: Vec<(bool, TokenStream)>) -> TokenStream {
        let mut out = TokenStream::new();
        for (i, (neg, t)) in terms.into_iter().enumerate() {
            out.extend(match (i, neg) {
                (0, true) => quote!(-#t),
                (0, false) => t,
                (_, true) => quote!(- #t),
                (_, false) => quote!(+ #t),
            });
        }
        out
    }
    fn neg(&mut self, x: (TokenStream, Prec)) -> TokenStream {
        let t = wrap(x, Prec::Product);
        quote!(-#t)
    }
    fn product(&mut self, factors: Vec<(TokenStream, Prec)>) -> TokenStream {
        strip_parens(balanced(factors))
    }
    fn late(&mut self, id: ExprId) -> bool {
        self.style.late.is_some_and(|late| late(id))
    }
    fn product_grouped(
        &mut self,
        early: Vec<(TokenStream, Prec)>,
        late: Vec<(TokenStream, Prec)>,
    ) -> TokenStream {
        match (early.is_empty(), late.is_empty()) {
            (true, _) => self.product(late),
            (_, true) => self.product(early),
            _ => {
                let (e, l) = (balanced(early), balanced(late));
                quote!(#e * #l)
            }
        }
    }
    fn quotient(&mut self, num: (TokenStream, Prec), den: (TokenStream, Prec)) -> TokenStream {
        let n = wrap(num, Prec::Product);
        let d = wrap(den, Prec::Neg);
        quote!(#n / #d)
    }
    fn pow_int(&mut self, base: (TokenStream, Prec), k: i64) -> TokenStream {
        let b = wrap(base, Prec::Atom);
        let k = Literal::i32_unsuffixed(i32::try_from(k).unwrap_or(i32::MAX));
        quote!(#b.powi(#k))
    }
    fn pow(&mut self, base: (TokenStream, Prec), exp: (TokenStream, Prec)) -> TokenStream {
        let b = wrap(base, Prec::Atom);
        let e = exp.0;
        quote!(#b.powf(#e))
    }
    fn sqrt(&mut self, x: (TokenStream, Prec)) -> TokenStream {
        let b = wrap(x, Prec::Atom);
        quote!(#b.sqrt())
    }
    fn func(&mut self, f: Func, x: (TokenStream, Prec)) -> TokenStream {
        if f == Func::Sign {
            let a = x.0;
            return quote!(::kane_model::__private::sign(#a));
        }
        let b = wrap(x, Prec::Atom);
        let m = Ident::new(f.name(), proc_macro2::Span::call_site());
        quote!(#b.#m())
    }
    fn atan2(&mut self, y: TokenStream, x: TokenStream) -> TokenStream {
        quote!((#y).atan2(#x))
    }
}

/// The factors multiplied as a balanced tree, not a left-to-right chain: the partial products
/// run in parallel, so the latency is log2 of the factor count multiplications. Parenthesised
/// when more than one factor.
fn balanced(factors: Vec<(TokenStream, Prec)>) -> TokenStream {
    let mut level: Vec<TokenStream> = factors.into_iter().map(|f| wrap(f, Prec::Neg)).collect();
    while level.len() > 1 {
        let mut next = Vec::with_capacity(level.len().div_ceil(2));
        let mut it = level.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) => quote!((#a * #b)),
                None => a,
            });
        }
        level = next;
    }
    level.pop().unwrap_or_default()
}

/// `x` without one pair of enclosing parentheses (a product's outermost grouping needs none).
fn strip_parens(x: TokenStream) -> TokenStream {
    let mut it = x.clone().into_iter();
    match (it.next(), it.next()) {
        (Some(proc_macro2::TokenTree::Group(g)), None)
            if g.delimiter() == proc_macro2::Delimiter::Parenthesis =>
        {
            g.stream()
        }
        _ => x,
    }
}

impl Arena {
    /// The Rust expression computing `e`, as tokens.
    pub fn to_rust(&self, e: ExprId, style: &RustStyle<'_>) -> TokenStream {
        layout(self, e, &mut Rust { style }, true).0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym_tokens(ar: &Arena) -> impl Fn(SymbolId) -> TokenStream + '_ {
        |s| {
            let name = ar.symbol_info(s).name.replace('\'', "_d");
            let id = Ident::new(&name, proc_macro2::Span::call_site());
            quote!(#id)
        }
    }

    #[test]
    fn emits_method_calls_and_operators() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let s = ar.add(&[x, y]).unwrap();
        let c = ar.cos(s).unwrap();
        let x2 = ar.powi(x, 2).unwrap();
        let q = ar.div(c, x2).unwrap();
        let m = ar.neg(q).unwrap();
        let half = ar.rational(1, 2).unwrap();
        let h = ar.mul(&[half, y]).unwrap();
        let f = sym_tokens(&ar);
        let style = RustStyle { scalar: Scalar::F64, symbol: &f, names: None, late: None };
        assert_eq!(ar.to_rust(m, &style).to_string(), "- (x + y) . cos () / x . powi (2)");
        let g = RustStyle {
            scalar: Scalar::Generic(Ident::new("T", proc_macro2::Span::call_site())),
            symbol: &f,
            names: None,
            late: None,
        };
        assert_eq!(ar.to_rust(h, &g).to_string(), "y / :: kane_model :: __private :: cast :: < T > (2f64)");
    }
}
