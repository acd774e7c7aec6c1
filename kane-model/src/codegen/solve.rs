//! `M u' = f` unrolled at generation time: `M` is split into the independent blocks of its
//! structural nonzeros; a 1x1 block is one multiplication by its reciprocal, a 2x2 block is
//! solved with its adjugate (one reciprocal of the determinant instead of two chained pivots),
//! a larger block by `LDL^T`.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::ldlt;

/// Statements computing `x` from the named entries of `m` (None: structurally zero) and `f`;
/// `recips[j]`, when given, names `1 / m[j][j]`. Returns the statements, the names of `x`, and
/// their arithmetic-operation count.
/// `dets` names the determinants of 2x2 blocks computed elsewhere, by the block's indices.
pub fn emit(
    m: &[Vec<Option<TokenStream>>],
    f: &[TokenStream],
    recips: &[Option<TokenStream>],
    dets: &[((usize, usize), TokenStream)],
    t: &Ident,
) -> (TokenStream, Vec<TokenStream>, usize) {
    let n = f.len();
    let mut out = TokenStream::new();
    let mut ops = 0;
    let mut x: Vec<TokenStream> = vec![TokenStream::new(); n];
    for block in blocks(n, |i, j| m[i][j].is_some()) {
        match block[..] {
            [a] => {
                let (fa, id) = (&f[a], format_ident!("__udot{}", a));
                let recip = match &recips[a] {
                    Some(r) => r.clone(),
                    None => {
                        let ma = m[a][a].clone().unwrap_or_else(|| quote!(#t::zero()));
                        ops += 1;
                        quote!((#t::one() / #ma))
                    }
                };
                out.extend(quote!(let #id: #t = #fa * #recip;));
                ops += 1;
                x[a] = quote!(#id);
            }
            [a, b] => {
                let zero = quote!(#t::zero());
                let (maa, mbb) = (m[a][a].clone().unwrap_or(zero.clone()), m[b][b].clone().unwrap_or(zero));
                let mab = m[a][b].clone().unwrap_or_default();
                let (fa, fb) = (&f[a], &f[b]);
                let rdet = format_ident!("__rdet{}_{}", a, b);
                let (xa, xb) = (format_ident!("__udot{}", a), format_ident!("__udot{}", b));
                let det = match dets.iter().find(|d| d.0 == (a, b)) {
                    Some((_, given)) => given.clone(),
                    None => {
                        ops += 3;
                        quote!((#maa * #mbb - #mab * #mab))
                    }
                };
                out.extend(quote! {
                    let #rdet: #t = #t::one() / #det;
                    let #xa: #t = (#mbb * #fa - #mab * #fb) * #rdet;
                    let #xb: #t = (#maa * #fb - #mab * #fa) * #rdet;
                });
                ops += 9;
                x[a] = quote!(#xa);
                x[b] = quote!(#xb);
            }
            _ => {
                let (stmts, block_ops) = ldlt::emit(m, f, recips, &block, t, &mut x);
                out.extend(stmts);
                ops += block_ops;
            }
        }
    }
    (out, x, ops)
}

/// The connected components of the structural nonzeros of an `n x n` matrix, each in
/// increasing order, ordered by their first index.
pub fn blocks(n: usize, nonzero: impl Fn(usize, usize) -> bool) -> Vec<Vec<usize>> {
    let mut component: Vec<Option<usize>> = vec![None; n];
    let mut out: Vec<Vec<usize>> = Vec::new();
    for start in 0..n {
        if component[start].is_some() {
            continue;
        }
        let id = out.len();
        let mut members = vec![start];
        component[start] = Some(id);
        let mut next = 0;
        while next < members.len() {
            let i = members[next];
            next += 1;
            for j in 0..n {
                if j != i && component[j].is_none() && nonzero(i, j) {
                    component[j] = Some(id);
                    members.push(j);
                }
            }
        }
        members.sort_unstable();
        out.push(members);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_follow_the_structural_nonzeros() {
        let some = || Some(quote!(a));
        // 0-2 coupled, 1 alone, 3-4 coupled through 4-3.
        let mut m: Vec<Vec<Option<TokenStream>>> = vec![vec![None; 5]; 5];
        for i in 0..5 {
            m[i][i] = some();
        }
        m[0][2] = some();
        m[2][0] = some();
        m[3][4] = some();
        m[4][3] = some();
        assert_eq!(blocks(5, |i, j| m[i][j].is_some()), vec![vec![0, 2], vec![1], vec![3, 4]]);
    }
}
