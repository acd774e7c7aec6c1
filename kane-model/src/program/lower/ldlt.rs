//! A symmetric positive-definite block of `M x = f` lowered as `M = L D L^T`: in come the
//! block's indices and the values of `M` and `f`; out go the values of `x`. The structural zeros
//! of `M` (and of the fill-in) are known at generation time, so their terms are never emitted.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use super::super::ir::SectionBuilder;

/// The values of `M` (None: structurally zero) and `f`, and quantities computed elsewhere.
pub struct System<'a> {
    /// `M`, symmetric.
    pub m: &'a [Vec<Option<u32>>],
    /// `f`.
    pub f: &'a [u32],
    /// `recips[j]`, when given, is `1 / m[j][j]`.
    pub recips: &'a [Option<u32>],
    /// The determinants of 2x2 blocks, by the block's indices.
    pub dets: &'a [((usize, usize), u32)],
}

/// Solves the block `idx` of `M x = f`, writing the values of the solution into `x`. Each pivot
/// is inverted once; `recips[j]`, when given, is `1 / m[j][j]` computed elsewhere (used when the
/// pivot has no fill-in, so equals `m[j][j]`).
pub fn lower(b: &mut SectionBuilder, sys: &System<'_>, idx: &[usize], x: &mut [u32]) {
    let (l, r) = factor(b, sys, idx);
    let n = idx.len();
    // L z = f, then D w = z, then L^T x = w.
    let mut z: Vec<u32> = Vec::with_capacity(n);
    for i in 0..n {
        let mut acc = sys.f[idx[i]];
        for k in 0..i {
            if let Some(lik) = l[i][k] {
                let t = b.mul(lik, z[k]);
                acc = b.sub(acc, t);
            }
        }
        z.push(acc);
    }
    for i in (0..n).rev() {
        let mut acc = b.mul(z[i], r[i]);
        for k in i + 1..n {
            if let Some(lki) = l[k][i] {
                let t = b.mul(lki, x[idx[k]]);
                acc = b.sub(acc, t);
            }
        }
        x[idx[i]] = acc;
    }
}

/// `L` (strictly lower, None: structurally zero) and the reciprocals of `D`.
fn factor(b: &mut SectionBuilder, sys: &System<'_>, idx: &[usize]) -> (Vec<Vec<Option<u32>>>, Vec<u32>) {
    let n = idx.len();
    let zero = b.constant(0.0);
    let entry = |a: usize, c: usize| sys.m[idx[a]][idx[c]];
    let mut l: Vec<Vec<Option<u32>>> = vec![vec![None; n]; n];
    let mut d: Vec<u32> = Vec::with_capacity(n);
    let mut r: Vec<u32> = Vec::with_capacity(n);
    for j in 0..n {
        // d_j = M_jj - sum_k L_jk^2 d_k, and r_j = 1 / d_j
        let mut dj = entry(j, j).unwrap_or(zero);
        let mut fill_in = false;
        for k in 0..j {
            if let Some(ljk) = l[j][k] {
                let sq = b.mul(ljk, ljk);
                let t = b.mul(sq, d[k]);
                dj = b.sub(dj, t);
                fill_in = true;
            }
        }
        let rj = match (sys.recips[idx[j]], fill_in) {
            (Some(given), false) => given,
            _ => {
                let one = b.constant(1.0);
                b.div(one, dj)
            }
        };
        d.push(dj);
        r.push(rj);
        for i in j + 1..n {
            // L_ij = (M_ij - sum_k L_ik L_jk d_k) / d_j
            let terms: Vec<(u32, u32, u32)> = (0..j)
                .filter_map(|k| match (l[i][k], l[j][k]) {
                    (Some(lik), Some(ljk)) => Some((lik, ljk, d[k])),
                    _ => None,
                })
                .collect();
            let mij = entry(i, j);
            if mij.is_none() && terms.is_empty() {
                continue;
            }
            let mut acc = mij.unwrap_or(zero);
            for (lik, ljk, dk) in terms {
                let p = b.mul(lik, ljk);
                let t = b.mul(p, dk);
                acc = b.sub(acc, t);
            }
            l[i][j] = Some(b.mul(acc, rj));
        }
    }
    (l, r)
}
