//! `M x = f` for a symmetric positive-definite `M`, unrolled: `M = L D L^T` with the structural
//! zeros of `M` (and of the fill-in) known at generation time, so their terms are never emitted.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

/// Statements computing `x` from the named entries of `m` (None: structurally zero) and `f`;
/// returns the statements, the names of `x`, and their arithmetic-operation count.
pub fn emit(
    m: &[Vec<Option<TokenStream>>],
    f: &[TokenStream],
    t: &Ident,
) -> (TokenStream, Vec<TokenStream>, usize) {
    let n = f.len();
    let mut out = TokenStream::new();
    let mut ops = 0;
    let mut l: Vec<Vec<Option<TokenStream>>> = vec![vec![None; n]; n];
    let mut d: Vec<TokenStream> = Vec::with_capacity(n);
    for j in 0..n {
        // d_j = M_jj - sum_k L_jk^2 d_k
        let dj = format_ident!("__d{}", j);
        let mjj = m[j][j].clone().unwrap_or_else(|| quote!(#t::zero()));
        let mut expr = quote!(#mjj);
        for k in 0..j {
            if let Some(ljk) = &l[j][k] {
                let dk = &d[k];
                expr = quote!(#expr - #ljk * #ljk * #dk);
                ops += 3;
            }
        }
        out.extend(quote!(let #dj: #t = #expr;));
        d.push(quote!(#dj));
        for i in j + 1..n {
            // L_ij = (M_ij - sum_k L_ik L_jk d_k) / d_j
            let mut terms: Vec<TokenStream> = Vec::new();
            for k in 0..j {
                if let (Some(lik), Some(ljk)) = (&l[i][k], &l[j][k]) {
                    let dk = &d[k];
                    terms.push(quote!(#lik * #ljk * #dk));
                }
            }
            if m[i][j].is_none() && terms.is_empty() {
                continue;
            }
            let mij = m[i][j].clone().unwrap_or_else(|| quote!(#t::zero()));
            let mut expr = quote!(#mij);
            for term in terms {
                expr = quote!(#expr - #term);
                ops += 3;
            }
            let id = format_ident!("__l{}_{}", i, j);
            out.extend(quote!(let #id: #t = (#expr) / #dj;));
            ops += 1;
            l[i][j] = Some(quote!(#id));
        }
    }
    // L z = f, then D w = z, then L^T x = w.
    let mut z: Vec<TokenStream> = Vec::with_capacity(n);
    for i in 0..n {
        let fi = &f[i];
        let mut expr = quote!(#fi);
        for k in 0..i {
            if let Some(lik) = &l[i][k] {
                let zk = &z[k];
                expr = quote!(#expr - #lik * #zk);
                ops += 2;
            }
        }
        let id = format_ident!("__z{}", i);
        out.extend(quote!(let #id: #t = #expr;));
        z.push(quote!(#id));
    }
    let mut x: Vec<TokenStream> = vec![TokenStream::new(); n];
    for i in (0..n).rev() {
        let (zi, di) = (&z[i], &d[i]);
        let mut expr = quote!(#zi / #di);
        ops += 1;
        for k in i + 1..n {
            if let Some(lki) = &l[k][i] {
                let xk = &x[k];
                expr = quote!(#expr - #lki * #xk);
                ops += 2;
            }
        }
        let id = format_ident!("__udot{}", i);
        out.extend(quote!(let #id: #t = #expr;));
        x[i] = quote!(#id);
    }
    (out, x, ops)
}
