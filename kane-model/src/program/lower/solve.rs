//! `M u' = f` lowered at generation time: in come the values of `M`'s structural nonzeros and
//! of `f`; out go the values of `u'`. `M` is split into the independent blocks of its nonzeros;
//! a 1x1 block is one multiplication by its reciprocal, a 2x2 block is solved with its adjugate
//! (one reciprocal of the determinant instead of two chained pivots), a larger block by `LDL^T`.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

use super::super::ir::SectionBuilder;
use super::ldlt;
pub use super::ldlt::System;

/// The upper triangle of the symmetric `m`, row by row (the entries a section lowers).
pub fn upper_triangle<T: Copy>(m: &[Vec<T>]) -> Vec<T> {
    m.iter().enumerate().flat_map(|(i, row)| row[i..].iter().copied()).collect()
}

/// The `n x n` symmetric matrix whose upper triangle, row by row, starts `values`.
pub fn symmetric(values: &[u32], n: usize) -> Vec<Vec<u32>> {
    let mut m = vec![vec![0; n]; n];
    let mut at = 0;
    for i in 0..n {
        for j in i..n {
            (m[i][j], m[j][i]) = (values[at], values[at]);
            at += 1;
        }
    }
    m
}

/// The values of `u'`.
pub fn lower(b: &mut SectionBuilder, sys: &System<'_>) -> Vec<u32> {
    let n = sys.f.len();
    let zero = b.constant(0.0);
    let mut x: Vec<u32> = vec![zero; n];
    for block in blocks(n, |i, j| sys.m[i][j].is_some()) {
        match block[..] {
            [a] => {
                let recip = match sys.recips[a] {
                    Some(r) => r,
                    None => {
                        let one = b.constant(1.0);
                        let ma = sys.m[a][a].unwrap_or(zero);
                        b.div(one, ma)
                    }
                };
                x[a] = b.mul(sys.f[a], recip);
            }
            [a, c] => (x[a], x[c]) = two_by_two(b, sys, a, c, zero),
            _ => ldlt::lower(b, sys, &block, &mut x),
        }
    }
    x
}

/// The 2x2 block `(a, c)` by its adjugate.
fn two_by_two(b: &mut SectionBuilder, sys: &System<'_>, a: usize, c: usize, zero: u32) -> (u32, u32) {
    let (maa, mcc) = (sys.m[a][a].unwrap_or(zero), sys.m[c][c].unwrap_or(zero));
    let mac = sys.m[a][c].unwrap_or(zero);
    let (fa, fc) = (sys.f[a], sys.f[c]);
    let det = match sys.dets.iter().find(|d| d.0 == (a, c)) {
        Some((_, given)) => *given,
        None => {
            let diag = b.mul(maa, mcc);
            let off = b.mul(mac, mac);
            b.sub(diag, off)
        }
    };
    let one = b.constant(1.0);
    let rdet = b.div(one, det);
    let (p, q) = (b.mul(mcc, fa), b.mul(mac, fc));
    let num_a = b.sub(p, q);
    let xa = b.mul(num_a, rdet);
    let (p, q) = (b.mul(maa, fc), b.mul(mac, fa));
    let num_c = b.sub(p, q);
    let xc = b.mul(num_c, rdet);
    (xa, xc)
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
        // 0-2 coupled, 1 alone, 3-4 coupled through 4-3.
        let mut m = [[false; 5]; 5];
        for (i, row) in m.iter_mut().enumerate() {
            row[i] = true;
        }
        m[0][2] = true;
        m[2][0] = true;
        m[3][4] = true;
        m[4][3] = true;
        assert_eq!(blocks(5, |i, j| m[i][j]), vec![vec![0, 2], vec![1], vec![3, 4]]);
    }
}
