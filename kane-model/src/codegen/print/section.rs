//! One section printed: in comes a [`Section`] and how its inputs are read; out go Rust
//! statements (`let __v7: T = __v3 * __v5;`) and the tokens of its results. Constants are
//! written in place; `sin` and `cos` of one argument come from one `sin_cos` call.

use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote, ToTokens};
use rustc_hash::FxHashMap;

use crate::expr::Func;

use crate::program::ir::{Input, Op, Section};

/// How a section is spelled.
pub struct SectionStyle<'a> {
    /// The number type: `f64`, or a type parameter bounded by `num_traits::Float`.
    pub scalar: Scalar,
    /// Tokens reading an input.
    pub input: &'a dyn Fn(Input) -> TokenStream,
    /// Prefix of the value names (sections printed into one function need distinct ones).
    pub prefix: &'a str,
}

/// The number type of printed code.
#[derive(Clone, Debug)]
pub enum Scalar {
    /// Plain `f64`, with literal constants.
    F64,
    /// A type parameter; constants via `cast::<T>(..)`.
    Generic(Ident),
}

impl Scalar {
    fn tokens(&self) -> TokenStream {
        match self {
            Scalar::F64 => quote!(f64),
            Scalar::Generic(t) => quote!(#t),
        }
    }
}

/// The section's statements and the tokens of its results.
pub fn print(section: &Section, style: &SectionStyle<'_>) -> (TokenStream, Vec<TokenStream>) {
    let ty = style.scalar.tokens();
    let operand = |v: u32| -> TokenStream {
        match section.ops[v as usize] {
            Op::Const(c) => constant(c, &style.scalar),
            _ => {
                let id = format_ident!("{}{}", style.prefix, v);
                quote!(#id)
            }
        }
    };
    let partners = sin_cos_partners(section);
    let mut body = TokenStream::new();
    for (i, op) in section.ops.iter().enumerate() {
        let id = format_ident!("{}{}", style.prefix, i);
        let value = match *op {
            Op::Const(_) => continue,
            Op::Input(k) => (style.input)(section.inputs[k as usize]),
            Op::Func(f @ (Func::Sin | Func::Cos), a) if partners.contains_key(&(i as u32)) => {
                let j = partners[&(i as u32)];
                if j < i as u32 {
                    continue;
                }
                let other = format_ident!("{}{}", style.prefix, j);
                let (s, c) = if f == Func::Sin { (&id, &other) } else { (&other, &id) };
                let x = operand(a);
                body.extend(quote!(let (#s, #c): (#ty, #ty) = #x.sin_cos();));
                continue;
            }
            _ => expression(*op, &operand),
        };
        body.extend(quote!(let #id: #ty = #value;));
    }
    let results = section.results.iter().map(|v| operand(*v)).collect();
    (body, results)
}

/// The right-hand side of one instruction (not an input or constant).
fn expression(op: Op, operand: &dyn Fn(u32) -> TokenStream) -> TokenStream {
    match op {
        Op::Add(a, b) => binary(operand(a), quote!(+), operand(b)),
        Op::Sub(a, b) => binary(operand(a), quote!(-), operand(b)),
        Op::Mul(a, b) => binary(operand(a), quote!(*), operand(b)),
        Op::Div(a, b) => binary(operand(a), quote!(/), operand(b)),
        Op::Neg(a) => {
            let a = operand(a);
            quote!(-#a)
        }
        Op::Powi(a, k) => {
            let (a, k) = (operand(a), Literal::i32_unsuffixed(k));
            quote!(#a.powi(#k))
        }
        Op::Sqrt(a) => {
            let a = operand(a);
            quote!(#a.sqrt())
        }
        Op::Powf(a, b) => {
            let (a, b) = (operand(a), operand(b));
            quote!(#a.powf(#b))
        }
        Op::Func(Func::Sign, a) => {
            let a = operand(a);
            quote!(::kane_model::__private::sign(#a))
        }
        Op::Func(f, a) => {
            let (a, m) = (operand(a), Ident::new(f.name(), proc_macro2::Span::call_site()));
            quote!(#a.#m())
        }
        Op::Atan2(a, b) => {
            let (a, b) = (operand(a), operand(b));
            quote!(#a.atan2(#b))
        }
        Op::Input(_) | Op::Const(_) => TokenStream::new(),
    }
}

fn binary(a: TokenStream, op: TokenStream, b: TokenStream) -> TokenStream {
    quote!(#a #op #b)
}

/// A constant in the section's number type.
pub(super) fn constant(c: f64, scalar: &Scalar) -> TokenStream {
    let lit = if c.is_nan() {
        quote!(f64::NAN)
    } else if c < 0.0 {
        let l = Literal::f64_suffixed(c);
        quote!((#l))
    } else {
        Literal::f64_suffixed(c).into_token_stream()
    };
    match scalar {
        Scalar::F64 => lit,
        Scalar::Generic(t) => quote!(::kane_model::__private::cast::<#t>(#lit)),
    }
}

/// Pairs of `sin(a)` and `cos(a)` instructions on the same operand, both ways.
fn sin_cos_partners(section: &Section) -> FxHashMap<u32, u32> {
    let mut first: FxHashMap<(u32, bool), u32> = FxHashMap::default();
    let mut pairs = FxHashMap::default();
    for (i, op) in section.ops.iter().enumerate() {
        if let Op::Func(f @ (Func::Sin | Func::Cos), a) = *op {
            let is_sin = f == Func::Sin;
            if let Some(&j) = first.get(&(a, !is_sin)) {
                if !pairs.contains_key(&j) {
                    pairs.insert(j, i as u32);
                    pairs.insert(i as u32, j);
                }
            }
            first.entry((a, is_sin)).or_insert(i as u32);
        }
    }
    pairs
}
