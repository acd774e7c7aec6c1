//! `M x = f` for a symmetric positive-definite block of `M`, unrolled: `M = L D L^T` with the
//! structural zeros of `M` (and of the fill-in) known at generation time, so their terms are
//! never emitted.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

/// Statements solving the block `idx` of `M x = f` (entries named in `m`, None: structurally
/// zero); writes the names of the solution into `x` and returns the statements and their
/// operation count. Each pivot is inverted once and multiplied; `recips[j]`, when given, is
/// `1 / m[j][j]` computed elsewhere (used when the pivot has no fill-in, so equals `m[j][j]`).
pub fn emit(
    m: &[Vec<Option<TokenStream>>],
    f: &[TokenStream],
    recips: &[Option<TokenStream>],
    idx: &[usize],
    t: &Ident,
    x: &mut [TokenStream],
) -> (TokenStream, usize) {
    let n = idx.len();
    let mut out = TokenStream::new();
    let mut ops = 0;
    let entry = |a: usize, b: usize| m[idx[a]][idx[b]].clone();
    let mut l: Vec<Vec<Option<TokenStream>>> = vec![vec![None; n]; n];
    let mut d: Vec<TokenStream> = Vec::with_capacity(n);
    let mut r: Vec<TokenStream> = Vec::with_capacity(n);
    for j in 0..n {
        // d_j = M_jj - sum_k L_jk^2 d_k, and r_j = 1 / d_j
        let (dj, rj) = (format_ident!("__d{}", idx[j]), format_ident!("__r{}", idx[j]));
        let mjj = entry(j, j).unwrap_or_else(|| quote!(#t::zero()));
        let mut expr = quote!(#mjj);
        let mut fill_in = false;
        for k in 0..j {
            if let Some(ljk) = &l[j][k] {
                let dk = &d[k];
                expr = quote!(#expr - #ljk * #ljk * #dk);
                ops += 3;
                fill_in = true;
            }
        }
        out.extend(quote!(let #dj: #t = #expr;));
        match (recips[idx[j]].as_ref(), fill_in) {
            (Some(given), false) => out.extend(quote!(let #rj: #t = #given;)),
            _ => {
                out.extend(quote!(let #rj: #t = #t::one() / #dj;));
                ops += 1;
            }
        }
        d.push(quote!(#dj));
        r.push(quote!(#rj));
        for i in j + 1..n {
            // L_ij = (M_ij - sum_k L_ik L_jk d_k) / d_j
            let mut terms: Vec<TokenStream> = Vec::new();
            for k in 0..j {
                if let (Some(lik), Some(ljk)) = (&l[i][k], &l[j][k]) {
                    let dk = &d[k];
                    terms.push(quote!(#lik * #ljk * #dk));
                }
            }
            let mij = entry(i, j);
            if mij.is_none() && terms.is_empty() {
                continue;
            }
            let mut expr = mij.unwrap_or_else(|| quote!(#t::zero()));
            for term in terms {
                expr = quote!(#expr - #term);
                ops += 3;
            }
            let id = format_ident!("__l{}_{}", idx[i], idx[j]);
            out.extend(quote!(let #id: #t = (#expr) * #rj;));
            ops += 1;
            l[i][j] = Some(quote!(#id));
        }
    }
    // L z = f, then D w = z, then L^T x = w.
    let mut z: Vec<TokenStream> = Vec::with_capacity(n);
    for i in 0..n {
        let fi = &f[idx[i]];
        let mut expr = quote!(#fi);
        for k in 0..i {
            if let Some(lik) = &l[i][k] {
                let zk = &z[k];
                expr = quote!(#expr - #lik * #zk);
                ops += 2;
            }
        }
        let id = format_ident!("__z{}", idx[i]);
        out.extend(quote!(let #id: #t = #expr;));
        z.push(quote!(#id));
    }
    for i in (0..n).rev() {
        let (zi, ri) = (&z[i], &r[i]);
        let mut expr = quote!(#zi * #ri);
        ops += 1;
        for k in i + 1..n {
            if let Some(lki) = &l[k][i] {
                let xk = &x[idx[k]];
                expr = quote!(#expr - #lki * #xk);
                ops += 2;
            }
        }
        let id = format_ident!("__udot{}", idx[i]);
        out.extend(quote!(let #id: #t = #expr;));
        x[idx[i]] = quote!(#id);
    }
    (out, ops)
}
