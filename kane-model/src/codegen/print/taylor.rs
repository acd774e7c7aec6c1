//! The Taylor coefficients printed: in comes a [`TaylorProgram`] and how its inputs are read;
//! out goes `taylor_with_constants_loop`, straight-line in the operations (one call of a recurrence of
//! `kane_model::__private::taylor` per operation) with a loop over the order; one straight-line
//! function per order asked ([`super::unrolled`]); and `taylor_with_constants`, which
//! takes the straight-line function of the order asked where there is one and the CPU has fused
//! multiply-add, else the loop.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, ToTokens};

use super::section::{constant, Scalar};
use super::unrolled::{order_fn, order_fn_name};
use crate::program::ir::Input;
use crate::program::taylor::{TKind, TaylorProgram};

/// `taylor_with_constants` (the dispatch by order), the straight-line functions it calls and
/// `taylor_with_constants_loop`: the normalised Taylor coefficients of the solution through `(t, y)`;
/// straight-line code for `orders` only.
pub fn taylor_fn(
    program: &TaylorProgram,
    input: &dyn Fn(Input) -> TokenStream,
    orders: &[usize],
) -> TokenStream {
    let looped = loop_fn(program, input);
    let arms = orders.iter().map(|&o| {
        let (name, o) = (order_fn_name(o), Literal::usize_unsuffixed(o));
        // SAFETY: the CPU has fused multiply-add, which is all the function assumes.
        quote!(#o if __t::fused_multiply_add() => unsafe { #name(t, y, p, __constants, out) },)
    });
    let orders = orders.iter().map(|&o| order_fn(program, input, o));
    quote! {
        /// The normalised Taylor coefficients of the solution through `(t, y)`, orders
        /// `0..=order`, into `out` (state `i`'s coefficient `k` at `out[i * (order + 1) + k]`),
        /// with `d = param_constants(p)`; `work` is scratch. Straight-line code for the orders of
        /// `INFO.taylor_straight_line` on CPUs with fused multiply-add, `taylor_with_constants_loop`
        /// otherwise. False (nothing done) for an order above
        /// `kane_model::runtime::TAYLOR_MAX_ORDER`.
        #[allow(unused_variables, unused_imports, clippy::all)]
        pub fn taylor_with_constants<T: ::kane_model::__private::num_traits::Float>(
            t: T, y: &[T], p: &Params, __constants: &ParamConstants, order: usize, out: &mut [T],
            work: &mut Vec<::kane_model::__private::taylor::Row<T>>,
        ) -> bool {
            use ::kane_model::__private::taylor as __t;
            match order {
                #(#arms)*
                _ => taylor_with_constants_loop(t, y, p, __constants, order, out, work),
            }
        }
        #looped
        #(#orders)*
    }
}

/// `taylor_with_constants_loop`: the coefficients by a loop over the order.
fn loop_fn(program: &TaylorProgram, input: &dyn Fn(Input) -> TokenStream) -> TokenStream {
    let scalar = Scalar::Generic(format_ident!("T"));
    let lit = Literal::usize_unsuffixed;
    let mut first = TokenStream::new();
    let mut rest = TokenStream::new();
    for (v, op) in program.ops.iter().enumerate() {
        let d = lit(v);
        match op.kind {
            TKind::Time => {}
            TKind::State(i) => {
                let i = lit(i as usize);
                first.extend(quote!(__w[#d][0] = y[#i];));
            }
            TKind::Const(c) => {
                let c = constant(c, &scalar);
                first.extend(quote!(__w[#d][0] = #c;));
            }
            TKind::Input(k) => {
                let value = input(program.inputs[k as usize]);
                first.extend(quote!(__w[#d][0] = #value;));
            }
            kind => {
                first.extend(call(kind, v, quote!(0)));
                if op.series {
                    rest.extend(call(kind, v, quote!(__k)));
                }
            }
        }
    }
    let nv = program.ops.len();
    let ns = program.results.len();
    let n_pairs = program.states.len();
    let pairs = program.states.iter().map(|(s, r)| {
        let (s, r) = (lit(*s), lit(*r));
        quote!((#s, #r))
    });
    let results = program.results.iter().map(|r| lit(*r));
    let n_constants = program.constants.len();
    let constants = program.constants.iter().map(|c| lit(*c));
    let time = match program.time {
        Some(v) => {
            let v = lit(v);
            quote!(Some((#v, t)))
        }
        None => quote!(None),
    };
    quote! {
        /// `taylor_with_constants` by a loop over the order (any order): one call of a recurrence per
        /// operation and order.
        #[allow(unused_variables, clippy::all)]
        pub fn taylor_with_constants_loop<T: ::kane_model::__private::num_traits::Float>(
            t: T, y: &[T], p: &Params, __constants: &ParamConstants, order: usize, out: &mut [T],
            work: &mut Vec<::kane_model::__private::taylor::Row<T>>,
        ) -> bool {
            use ::kane_model::__private::taylor as __t;
            const STATES: [(usize, usize); #n_pairs] = [#(#pairs),*];
            const RESULTS: [usize; #ns] = [#(#results),*];
            const CONSTANTS: [usize; #n_constants] = [#(#constants),*];
            if !__t::start(work, #nv, order, &CONSTANTS, #time) {
                return false;
            }
            let __w = &mut work[..#nv];
            #first
            for __k in 1..order {
                __t::states(__w, __k, &STATES);
                #rest
            }
            __t::finish(__w, order, y, &RESULTS, out);
            true
        }
    }
}

/// The call computing coefficient `k` of value `d` by `kind`.
fn call(kind: TKind, d: usize, k: TokenStream) -> TokenStream {
    let lit = |v: u32| -> TokenStream { Literal::usize_unsuffixed(v as usize).into_token_stream() };
    let (name, args): (&str, Vec<TokenStream>) = match kind {
        TKind::Add(a, b) => ("add", vec![lit(a), lit(b)]),
        TKind::Sub(a, b) => ("sub", vec![lit(a), lit(b)]),
        TKind::Neg(a) => ("neg", vec![lit(a)]),
        TKind::Mul(a, b) => ("mul", vec![lit(a), lit(b)]),
        TKind::Sqr(a) => ("sqr", vec![lit(a)]),
        TKind::Scale(a, s) => ("scale", vec![lit(a), lit(s)]),
        TKind::Div(a, b) => ("div", vec![lit(a), lit(b)]),
        TKind::DivConst(a, s) => ("div_const", vec![lit(a), lit(s)]),
        TKind::Sqrt(a) => ("sqrt", vec![lit(a)]),
        TKind::Exp(a) => ("exp", vec![lit(a)]),
        TKind::Ln(a) => ("ln", vec![lit(a)]),
        TKind::Sin(a, c) => ("sin", vec![lit(a), lit(c)]),
        TKind::Cos(a, s) => ("cos", vec![lit(a), lit(s)]),
        TKind::Sinh(a, c) => ("sinh", vec![lit(a), lit(c)]),
        TKind::Cosh(a, s) => ("cosh", vec![lit(a), lit(s)]),
        TKind::Integral(f, a, q) => {
            let f = format_ident!("{}", format!("{f:?}"));
            ("integral", vec![lit(a), lit(q), quote!(__t::Inverse::#f)])
        }
        TKind::Atan2(y, x, r) => ("atan2", vec![lit(y), lit(x), lit(r)]),
        TKind::Abs(a) => ("abs", vec![lit(a)]),
        TKind::Sign(a) => ("sign", vec![lit(a)]),
        TKind::Time | TKind::State(_) | TKind::Const(_) | TKind::Input(_) => return TokenStream::new(),
    };
    let name = format_ident!("{}", name);
    let d = Literal::usize_unsuffixed(d);
    quote!(__t::#name(__w, #k, #d, #(#args),*);)
}
