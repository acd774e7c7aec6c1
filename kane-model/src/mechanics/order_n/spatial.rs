//! Spatial (6D) algebra on expressions: 3-vectors, 6-vectors (angular part first, then linear)
//! and 6x6 matrices, with the arena's folding of zeros doing the sparsity work (a planar chain's
//! out-of-plane entries fold to zero and are never computed).
// Matrix code reads clearest with indices (a[i][j] beside a[j][i]).
#![allow(clippy::needless_range_loop)]

use crate::expr::{Arena, ExprError, ExprId};
use crate::mechanics::Mat3;

/// Three measure numbers.
pub(crate) type V3 = [ExprId; 3];
/// A spatial vector: angular part (0..3), then linear part (3..6).
pub(crate) type V6 = [ExprId; 6];
/// A 6x6 matrix, row by row.
pub(crate) type M6 = [[ExprId; 6]; 6];

type Res<T> = Result<T, ExprError>;

/// The sum of the products `a_i b_i`.
pub(crate) fn dot(ar: &mut Arena, a: &[ExprId], b: &[ExprId]) -> Res<ExprId> {
    let mut terms = Vec::with_capacity(a.len());
    for (x, y) in a.iter().zip(b) {
        if !ar.is_zero(*x) && !ar.is_zero(*y) {
            terms.push(ar.mul(&[*x, *y])?);
        }
    }
    ar.add(&terms)
}

/// `a + b`, entry by entry.
pub(crate) fn add<const N: usize>(ar: &mut Arena, a: &[ExprId; N], b: &[ExprId; N]) -> Res<[ExprId; N]> {
    let mut out = *a;
    for (o, y) in out.iter_mut().zip(b) {
        *o = ar.add(&[*o, *y])?;
    }
    Ok(out)
}

/// `k a`, entry by entry.
pub(crate) fn scale<const N: usize>(ar: &mut Arena, k: ExprId, a: &[ExprId; N]) -> Res<[ExprId; N]> {
    let mut out = *a;
    for o in out.iter_mut() {
        *o = ar.mul(&[k, *o])?;
    }
    Ok(out)
}

/// `a x b`.
pub(crate) fn cross(ar: &mut Arena, a: &V3, b: &V3) -> Res<V3> {
    let mut out = [ar.zero(); 3];
    for (i, o) in out.iter_mut().enumerate() {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let p = dot(ar, &[a[j]], &[b[k]])?;
        let m = dot(ar, &[a[k]], &[b[j]])?;
        *o = ar.sub(p, m)?;
    }
    Ok(out)
}

/// `R v` (`transpose` false) or `R^T v`.
pub(crate) fn rotate(ar: &mut Arena, r: &Mat3, v: &V3, transpose: bool) -> Res<V3> {
    let mut out = [ar.zero(); 3];
    for (i, o) in out.iter_mut().enumerate() {
        let row: V3 = if transpose { [r[0][i], r[1][i], r[2][i]] } else { r[i] };
        *o = dot(ar, &row, v)?;
    }
    Ok(out)
}

/// The spatial inertia about a point of a mass `m` with first moment `h` (mass times the
/// position of its centre) and rotational inertia `j` about that point:
/// `[[j, h x], [-(h x), m 1]]`.
pub(crate) fn inertia(ar: &mut Arena, j: &Mat3, h: &V3, m: ExprId) -> Res<M6> {
    let z = ar.zero();
    let mut out = [[z; 6]; 6];
    for a in 0..3 {
        for b in 0..3 {
            out[a][b] = j[a][b];
        }
        out[a + 3][a + 3] = m;
    }
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        // (h x)[a][c] = h[b], (h x)[a][b] = -h[c].
        let minus_hc = ar.neg(h[c])?;
        out[a][c + 3] = h[b];
        out[a][b + 3] = minus_hc;
        out[c + 3][a] = h[b];
        out[b + 3][a] = minus_hc;
    }
    Ok(out)
}

/// The motion transform from a parent to a child frame: `R` maps child to parent components and
/// `d` locates the child's origin from the parent's in parent components;
/// `[[R^T, 0], [-R^T (d x), R^T]]`.
pub(crate) fn motion_transform(ar: &mut Arena, r: &Mat3, d: &V3) -> Res<M6> {
    let z = ar.zero();
    let mut x = [[z; 6]; 6];
    for i in 0..3 {
        for j in 0..3 {
            x[i][j] = r[j][i];
            x[i + 3][j + 3] = r[j][i];
        }
    }
    // Column j of -(R^T (d x)) is -R^T (d x e_j) = R^T (e_j x d).
    for j in 0..3 {
        let mut e = [z; 3];
        e[j] = ar.one();
        let ed = cross(ar, &e, d)?;
        let col = rotate(ar, r, &ed, true)?;
        for i in 0..3 {
            x[i + 3][j] = col[i];
        }
    }
    Ok(x)
}

/// `X v`.
pub(crate) fn apply(ar: &mut Arena, x: &M6, v: &V6) -> Res<V6> {
    let mut out = [ar.zero(); 6];
    for (i, o) in out.iter_mut().enumerate() {
        *o = dot(ar, &x[i], v)?;
    }
    Ok(out)
}

/// `X^T f`.
pub(crate) fn apply_transpose(ar: &mut Arena, x: &M6, f: &V6) -> Res<V6> {
    let mut out = [ar.zero(); 6];
    for (i, o) in out.iter_mut().enumerate() {
        let col: V6 = std::array::from_fn(|k| x[k][i]);
        *o = dot(ar, &col, f)?;
    }
    Ok(out)
}

/// `X^T A X` for a symmetric `A`, upper triangle computed and mirrored.
pub(crate) fn congruence(ar: &mut Arena, x: &M6, a: &M6) -> Res<M6> {
    let z = ar.zero();
    let mut ax = [[z; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            let col: V6 = std::array::from_fn(|k| x[k][j]);
            ax[i][j] = dot(ar, &a[i], &col)?;
        }
    }
    let mut out = [[z; 6]; 6];
    for i in 0..6 {
        for j in i..6 {
            let xi: V6 = std::array::from_fn(|k| x[k][i]);
            let col: V6 = std::array::from_fn(|k| ax[k][j]);
            out[i][j] = dot(ar, &xi, &col)?;
            out[j][i] = out[i][j];
        }
    }
    Ok(out)
}
