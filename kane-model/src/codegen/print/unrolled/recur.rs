//! The recurrences of [`crate::runtime::taylor`] written out for one order `k` known when
//! printing: in come an operation and how to name any earlier coefficient; out goes coefficient
//! `k` as one expression, every sum term by term, each product added by a fused multiply-add:
//! the loop functions' numbers to rounding.

use proc_macro2::TokenStream;
use quote::{format_ident, quote, ToTokens};

use super::super::section::{constant, Scalar};
use super::expr::X;
use crate::program::taylor::TKind;

/// Names the coefficients: `coef(v, k)` is coefficient `k` of value `v`.
pub type Coef<'a> = &'a dyn Fn(u32, usize) -> X;

/// `k` in the number type.
pub fn count(k: usize) -> X {
    if k == 1 {
        X::One
    } else {
        X::atom(format_ident!("__k{}", k).into_token_stream())
    }
}

/// `x / k`: times `1 / k` where that is exact (a power of two).
fn div_count(x: X, k: usize) -> X {
    match exact_inverse(k as f64) {
        Some(inverse) if k > 1 => x.times(X::atom(inverse)),
        _ => x.over(count(k)),
    }
}

/// Partial sums a long sum is split into.
const LANES: usize = 3;
/// Terms from which a sum is split.
const SPLIT_FROM: usize = 4;

/// `sum_j terms[j]` by fused multiply-adds (the first product of a chain rounded alone), the
/// terms that read coefficient `k` (`late`, computed in this pass) added last, after the others
/// (known since the last pass): one chain, or from [`SPLIT_FROM`] terms [`LANES`] interleaved
/// chains. Passes run one after the other, each waiting on the last, so what counts is the
/// latency from a pass's new coefficients to its results: two fused multiply-adds here
/// (`cargo bench -p gyro-sim --bench taylor_coefficients`; figures in BENCHMARKS.md).
fn dot(terms: Vec<(X, bool)>) -> X {
    let (late, early): (Vec<_>, Vec<_>) = terms.into_iter().partition(|(_, late)| *late);
    let early: Vec<X> = early.into_iter().map(|(t, _)| t).collect();
    let sum = if early.len() < SPLIT_FROM {
        early.into_iter().fold(X::Zero, X::plus_fused)
    } else {
        let mut lanes = vec![X::Zero; LANES];
        for (j, t) in early.into_iter().enumerate() {
            let lane = &mut lanes[j % LANES];
            *lane = std::mem::replace(lane, X::Zero).plus_fused(t);
        }
        lanes.into_iter().fold(X::Zero, X::plus)
    };
    late.into_iter().fold(sum, |s, (t, _)| s.plus_fused(t))
}

/// `sum_{j=lo}^{hi} x_j y_{k-j}`.
fn cauchy(c: Coef, k: usize, x: u32, y: u32, lo: usize, hi: usize) -> X {
    if lo > hi {
        return X::Zero;
    }
    dot((lo..=hi).map(|j| (c(x, j).times(c(y, k - j)), j == 0 || j == k)).collect())
}

/// `sum_{j=1}^{hi} j x_j y_{k-j}`.
fn weighted(c: Coef, k: usize, x: u32, y: u32, hi: usize) -> X {
    dot((1..=hi).map(|j| (count(j).times(c(x, j)).times(c(y, k - j)), j == k)).collect())
}

/// A method of the number type on coefficient 0 of `a`.
fn method(c: Coef, a: u32, name: &str) -> X {
    let a = c(a, 0).tokens();
    let name = format_ident!("{}", name);
    X::atom(quote!(#a.#name()))
}

/// Coefficient `k` of value `d`, computed by `kind` (an arithmetic operation).
pub fn coefficient(kind: TKind, c: Coef, d: u32, k: usize) -> X {
    match (kind, k) {
        (TKind::Add(a, b), _) => c(a, k).plus(c(b, k)),
        (TKind::Sub(a, b), _) => c(a, k).minus(c(b, k)),
        (TKind::Neg(a), _) => c(a, k).negated(),
        (TKind::Mul(a, b), _) => cauchy(c, k, a, b, 0, k),
        (TKind::Sqr(a), _) => {
            let half = k.div_ceil(2);
            let cross = if half == 0 { X::Zero } else { cauchy(c, k, a, a, 0, half - 1) };
            let middle = if k.is_multiple_of(2) { c(a, k / 2).times(c(a, k / 2)) } else { X::Zero };
            cross.clone().plus(cross).plus(middle)
        }
        (TKind::Scale(a, s), _) => c(a, k).times(c(s, 0)),
        (TKind::Div(a, b), _) => c(a, k).minus(cauchy(c, k, b, d, 1, k)).over(c(b, 0)),
        (TKind::DivConst(a, s), _) => c(a, k).over(c(s, 0)),
        (TKind::Sqrt(a), 0) => method(c, a, "sqrt"),
        (TKind::Sqrt(a), _) => c(a, k).minus(cauchy(c, k, d, d, 1, k - 1)).over(c(d, 0).plus(c(d, 0))),
        (TKind::Exp(a), 0) => method(c, a, "exp"),
        (TKind::Exp(a), _) => div_count(weighted(c, k, a, d, k), k),
        (TKind::Ln(a), 0) => method(c, a, "ln"),
        (TKind::Ln(a), _) => c(a, k).minus(div_count(weighted(c, k, d, a, k - 1), k)).over(c(a, 0)),
        (TKind::Sin(a, _), 0) => method(c, a, "sin"),
        (TKind::Cos(a, _), 0) => method(c, a, "cos"),
        (TKind::Sinh(a, _), 0) => method(c, a, "sinh"),
        (TKind::Cosh(a, _), 0) => method(c, a, "cosh"),
        (TKind::Sin(a, p) | TKind::Sinh(a, p) | TKind::Cosh(a, p), _) => {
            div_count(weighted(c, k, a, p, k), k)
        }
        (TKind::Cos(a, s), _) => div_count(weighted(c, k, a, s, k).negated(), k),
        (TKind::Integral(f, a, _), 0) => {
            let (f, a) = (format_ident!("{}", format!("{f:?}")), c(a, 0).tokens());
            X::atom(quote!(__t::Inverse::#f.apply(#a)))
        }
        (TKind::Integral(_, a, q), _) => {
            let s = weighted(c, k, d, q, k - 1);
            count(k).times(c(a, k)).minus(s).over(count(k).times(c(q, 0)))
        }
        (TKind::Atan2(y, x, _), 0) => {
            let (y, x) = (c(y, 0).tokens(), c(x, 0).tokens());
            X::atom(quote!(#y.atan2(#x)))
        }
        (TKind::Atan2(y, x, r), _) => {
            let num = weighted(c, k, y, x, k).minus(weighted(c, k, x, y, k));
            num.minus(weighted(c, k, d, r, k - 1)).over(count(k).times(c(r, 0)))
        }
        (TKind::Abs(a), _) => c(a, k).sign_of(c(a, 0)),
        (TKind::Sign(a), 0) => {
            let a = c(a, 0).tokens();
            X::atom(quote!(::kane_model::__private::sign(#a)))
        }
        (TKind::Sign(_), _) => X::Zero,
        (TKind::Time | TKind::State(_) | TKind::Const(_) | TKind::Input(_), _) => X::Zero,
    }
}

/// `1 / c` in the number type where multiplying by it is dividing by `c` exactly: `c` a power of
/// two whose reciprocal is a normal number.
pub fn exact_inverse(c: f64) -> Option<TokenStream> {
    let inv = 1.0 / c;
    let power_of_two = c.is_normal() && c.to_bits() & ((1u64 << 52) - 1) == 0;
    (power_of_two && inv.is_normal()).then(|| constant(inv, &Scalar::Generic(format_ident!("T"))))
}
