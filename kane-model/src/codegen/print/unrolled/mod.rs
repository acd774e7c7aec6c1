//! Straight-line Taylor coefficients for one order: in comes a [`TaylorProgram`] and an order
//! `p`; out goes `taylor_order_p`, which computes what `taylor_with_constants_loop` computes at order `p`
//! with every pass written out: coefficient `k` of value `v` is the local `__c{v}_{k}`, every
//! index a constant, every Cauchy sum term by term (no loop, no work array, no bounds checks but
//! one on `out`). Products are added by fused multiply-adds (the function is compiled for CPUs
//! that have them), so the numbers agree with the loop's to rounding.

mod expr;
mod recur;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote, ToTokens};

use super::section::{constant, Scalar};
use crate::program::ir::Input;
use crate::program::taylor::{TKind, TaylorProgram};
use expr::X;

/// The name of the straight-line function of order `order`.
pub fn order_fn_name(order: usize) -> proc_macro2::Ident {
    format_ident!("taylor_order_{}", order)
}

/// The local holding coefficient `k` of value `v`.
fn local(v: u32, k: usize) -> TokenStream {
    format_ident!("__c{}_{}", v, k).into_token_stream()
}

/// Coefficient `k` of value `v`: zero past order 0 for constants, `t, 1, 0, ...` for time, else
/// its local.
fn coef(program: &TaylorProgram, v: u32, k: usize) -> X {
    let op = program.ops[v as usize];
    match op.kind {
        _ if k == 0 => X::atom(local(v, 0)),
        TKind::Time if k == 1 => X::One,
        TKind::Time => X::Zero,
        _ if !op.series => X::Zero,
        _ => X::atom(local(v, k)),
    }
}

/// `1 / k` as the loop computes it (`T::one() / k`), a local.
fn inverse(k: usize) -> X {
    if k == 1 {
        X::One
    } else {
        X::atom(format_ident!("__i{}", k).into_token_stream())
    }
}

/// Coefficient `k` of value `v` (an arithmetic operation); a division by a constant power of
/// two is a multiplication by its reciprocal (exact).
fn operation(program: &TaylorProgram, v: usize, k: usize) -> X {
    let c = |v: u32, k: usize| coef(program, v, k);
    let kind = program.ops[v].kind;
    if let TKind::DivConst(a, s) = kind {
        if let TKind::Const(value) = program.ops[s as usize].kind {
            if let Some(inverse) = recur::exact_inverse(value) {
                return c(a, k).times(X::atom(inverse));
            }
        }
    }
    recur::coefficient(kind, &c, v as u32, k)
}

/// `let __c{v}_{k}: T = x;`.
fn define(v: usize, k: usize, x: &X) -> TokenStream {
    let name = local(v as u32, k);
    let x = x.tokens();
    quote!(let #name: T = #x;)
}

/// Order 0 of every value.
fn order_zero(program: &TaylorProgram, input: &dyn Fn(Input) -> TokenStream) -> TokenStream {
    let scalar = Scalar::Generic(format_ident!("T"));
    let mut body = TokenStream::new();
    for (v, op) in program.ops.iter().enumerate() {
        let name = local(v as u32, 0);
        body.extend(match op.kind {
            TKind::Time => quote!(let #name: T = t;),
            TKind::State(i) => {
                let i = Literal::usize_unsuffixed(i as usize);
                quote!(let #name: T = y[#i];)
            }
            TKind::Const(c) => {
                let c = constant(c, &scalar);
                quote!(let #name: T = #c;)
            }
            TKind::Input(k) => {
                let value = input(program.inputs[k as usize]);
                quote!(let #name: T = #value;)
            }
            _ => define(v, 0, &operation(program, v, 0)),
        });
    }
    body
}

/// Pass `k >= 1`: the states' coefficient `k`, then every varying value's.
fn pass(program: &TaylorProgram, k: usize) -> TokenStream {
    let mut body = TokenStream::new();
    for &(row, result) in &program.states {
        body.extend(define(row, k, &coef(program, result as u32, k - 1).times(inverse(k))));
    }
    for (v, op) in program.ops.iter().enumerate() {
        if op.series && !matches!(op.kind, TKind::Time | TKind::State(_)) {
            body.extend(define(v, k, &operation(program, v, k)));
        }
    }
    body
}

/// `out`: each state's `y`, then its coefficients `f_{k-1} / k`.
fn finish(program: &TaylorProgram, order: usize) -> TokenStream {
    let n1 = order + 1;
    let mut body = TokenStream::new();
    for (i, &r) in program.results.iter().enumerate() {
        let (at, yi) = (Literal::usize_unsuffixed(i * n1), Literal::usize_unsuffixed(i));
        body.extend(quote!(out[#at] = y[#yi];));
        for k in 1..n1 {
            let at = Literal::usize_unsuffixed(i * n1 + k);
            let x = coef(program, r as u32, k - 1).times(inverse(k)).tokens();
            body.extend(quote!(out[#at] = #x;));
        }
    }
    body
}

/// `taylor_order_{order}`: the coefficients of orders `0..=order` into `out`, straight-line.
pub fn order_fn(program: &TaylorProgram, input: &dyn Fn(Input) -> TokenStream, order: usize) -> TokenStream {
    let name = order_fn_name(order);
    let counts = (2..=order).map(|k| {
        let (c, i, k) = (format_ident!("__k{}", k), format_ident!("__i{}", k), Literal::usize_unsuffixed(k));
        quote!(let #c: T = __t::count::<T>(#k); let #i: T = T::one() / #c;)
    });
    let first = order_zero(program, input);
    let passes = (1..order).map(|k| pass(program, k));
    let finish = finish(program, order);
    let n_out = Literal::usize_unsuffixed(program.results.len() * (order + 1));
    let doc = format!(
        " `taylor_with_constants` at order {order}, straight-line with fused multiply-adds (the numbers of `taylor_with_constants_loop` to rounding)."
    );
    quote! {
        #[doc = #doc]
        /// # Safety
        /// Only on a CPU with fused multiply-add (`__t::fused_multiply_add()`).
        #[allow(unused_variables, clippy::all)]
        #[cfg_attr(any(target_arch = "x86", target_arch = "x86_64"), target_feature(enable = "fma"))]
        unsafe fn #name<T: ::kane_model::__private::num_traits::Float>(
            t: T, y: &[T], p: &Params, __constants: &ParamConstants, out: &mut [T],
        ) -> bool {
            use ::kane_model::__private::taylor as __t;
            let Ok(out) = <&mut [T; #n_out]>::try_from(&mut out[..#n_out]) else {
                return false;
            };
            #(#counts)*
            #first
            #(#passes)*
            #finish
            true
        }
    }
}
