//! Vector and dyadic algebra: sums, scaling, dot, cross, express, partial derivatives.
//!
//! In: [`Vector`]s and [`Dyadic`]s, and a [`FrameTree`] that owns the expression arena and knows
//! the direction cosines between frames. Out: new vectors, dyadics and scalar expressions.
//! Nothing here knows the [`super::Model`]: the model implements [`FrameTree`] and forwards its
//! public vector methods to these functions, so the dependency runs one way.
//!
//! Operations keep measure numbers in the frames they were written in and convert a term only
//! when it meets a term of another frame.

use crate::expr::{Arena, ExprId, SymbolId};

use super::error::Result;
use super::ids::{FrameId, Mat3};
use super::vector::{Dyadic, Vector};

/// What vector algebra needs to know of the frames.
pub(crate) trait FrameTree {
    /// The expression arena.
    fn arena(&self) -> &Arena;
    /// The expression arena, to build new expressions in.
    fn arena_mut(&mut self) -> &mut Arena;
    /// Direction cosines `a_i . b_j` between two connected frames.
    fn direction_cosines(&mut self, a: FrameId, b: FrameId) -> Result<Mat3>;
    /// The parent of `frame` and the axis (0, 1 or 2) of the simple rotation that orients
    /// `frame` in it, when `frame` is so oriented.
    fn simple_rotation(&self, frame: FrameId) -> Option<(FrameId, usize)>;
}

/// `a + b`, merging terms of the same frame.
pub(crate) fn add_vectors<T: FrameTree + ?Sized>(t: &mut T, a: &Vector, b: &Vector) -> Result<Vector> {
    let mut out = a.clone();
    for (f, m) in &b.terms {
        match out.terms.iter_mut().find(|(g, _)| g == f) {
            Some((_, acc)) => {
                for i in 0..3 {
                    acc[i] = t.arena_mut().add(&[acc[i], m[i]])?;
                }
            }
            None => out.terms.push((*f, *m)),
        }
    }
    prune(t, &mut out)?;
    Ok(out)
}

/// `a - b`.
pub(crate) fn sub_vectors<T: FrameTree + ?Sized>(t: &mut T, a: &Vector, b: &Vector) -> Result<Vector> {
    let minus_one = t.arena().minus_one();
    let nb = scale(t, b, minus_one)?;
    add_vectors(t, a, &nb)
}

/// `k * v`.
pub(crate) fn scale<T: FrameTree + ?Sized>(t: &mut T, v: &Vector, k: ExprId) -> Result<Vector> {
    let mut out = v.clone();
    for (_, m) in out.terms.iter_mut() {
        for x in m.iter_mut() {
            *x = t.arena_mut().mul(&[k, *x])?;
        }
    }
    prune(t, &mut out)?;
    Ok(out)
}

/// Drops zero terms, and moves a term lying along the axis of its frame's simple rotation to
/// the parent frame (where its measure numbers are the same), merging terms that meet.
fn prune<T: FrameTree + ?Sized>(t: &mut T, v: &mut Vector) -> Result<()> {
    v.terms.retain(|(_, m)| !m.iter().all(|x| t.arena().is_zero(*x)));
    let mut moved = false;
    for (f, m) in v.terms.iter_mut() {
        while let Some(parent) = axis_parent(t, *f, m) {
            *f = parent;
            moved = true;
        }
    }
    if moved {
        let mut merged: Vec<(FrameId, [ExprId; 3])> = Vec::with_capacity(v.terms.len());
        for (f, m) in std::mem::take(&mut v.terms) {
            match merged.iter_mut().find(|(g, _)| *g == f) {
                Some((_, acc)) => {
                    for i in 0..3 {
                        acc[i] = t.arena_mut().add(&[acc[i], m[i]])?;
                    }
                }
                None => merged.push((f, m)),
            }
        }
        merged.retain(|(_, m)| !m.iter().all(|x| t.arena().is_zero(*x)));
        v.terms = merged;
    }
    Ok(())
}

/// The parent of `frame` when `m` lies along the axis of `frame`'s simple rotation.
fn axis_parent<T: FrameTree + ?Sized>(t: &T, frame: FrameId, m: &[ExprId; 3]) -> Option<FrameId> {
    let (parent, k) = t.simple_rotation(frame)?;
    let off_axis_zero = (0..3).all(|i| i == k || t.arena().is_zero(m[i]));
    off_axis_zero.then_some(parent)
}

/// Measure numbers of `v` in `frame`.
pub(crate) fn express<T: FrameTree + ?Sized>(t: &mut T, v: &Vector, frame: FrameId) -> Result<[ExprId; 3]> {
    let mut parts: [Vec<ExprId>; 3] = Default::default();
    for (f, m) in &v.terms {
        let conv = convert(t, m, *f, frame)?;
        for i in 0..3 {
            parts[i].push(conv[i]);
        }
    }
    let ar = t.arena_mut();
    Ok([ar.add(&parts[0])?, ar.add(&parts[1])?, ar.add(&parts[2])?])
}

/// `v` rewritten as a single term in `frame`.
pub(crate) fn express_vector<T: FrameTree + ?Sized>(t: &mut T, v: &Vector, frame: FrameId) -> Result<Vector> {
    let m = express(t, v, frame)?;
    let mut out = Vector::new(frame, m);
    prune(t, &mut out)?;
    Ok(out)
}

/// Measure numbers `m` (in frame `from`) converted to frame `to`.
fn convert<T: FrameTree + ?Sized>(
    t: &mut T,
    m: &[ExprId; 3],
    from: FrameId,
    to: FrameId,
) -> Result<[ExprId; 3]> {
    if from == to {
        return Ok(*m);
    }
    let c = t.direction_cosines(to, from)?;
    let ar = t.arena_mut();
    let mut out = [ar.zero(); 3];
    for (i, slot) in out.iter_mut().enumerate() {
        let terms: Vec<ExprId> =
            (0..3).map(|j| ar.mul(&[c[i][j], m[j]])).collect::<std::result::Result<_, _>>()?;
        *slot = ar.add(&terms)?;
    }
    Ok(out)
}

/// `a . b`.
pub(crate) fn dot<T: FrameTree + ?Sized>(t: &mut T, a: &Vector, b: &Vector) -> Result<ExprId> {
    let mut terms = Vec::new();
    for (fa, ma) in &a.terms {
        for (fb, mb) in &b.terms {
            let mb = convert(t, mb, *fb, *fa)?;
            for i in 0..3 {
                terms.push(t.arena_mut().mul(&[ma[i], mb[i]])?);
            }
        }
    }
    Ok(t.arena_mut().add(&terms)?)
}

/// `a x b`, in the frames of `a`'s terms.
pub(crate) fn cross<T: FrameTree + ?Sized>(t: &mut T, a: &Vector, b: &Vector) -> Result<Vector> {
    let mut out = Vector::zero();
    for (fa, ma) in &a.terms {
        for (fb, mb) in &b.terms {
            let mb = convert(t, mb, *fb, *fa)?;
            let ar = t.arena_mut();
            let mut c = [ar.zero(); 3];
            for (i, slot) in c.iter_mut().enumerate() {
                let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                let p = ar.mul(&[ma[j], mb[k]])?;
                let q = ar.mul(&[ma[k], mb[j]])?;
                *slot = ar.sub(p, q)?;
            }
            out = add_vectors(t, &out, &Vector::new(*fa, c))?;
        }
    }
    Ok(out)
}

/// `|v|`.
pub(crate) fn magnitude<T: FrameTree + ?Sized>(t: &mut T, v: &Vector) -> Result<ExprId> {
    let d = dot(t, v, v)?;
    Ok(t.arena_mut().sqrt(d)?)
}

/// The partial derivative of `v`'s measure numbers with respect to a symbol (frames held fixed).
pub(crate) fn partial<T: FrameTree + ?Sized>(t: &mut T, v: &Vector, s: SymbolId) -> Result<Vector> {
    let mut out = Vector::zero();
    for (f, m) in &v.terms {
        let ar = t.arena_mut();
        let mut d = [ar.zero(); 3];
        for i in 0..3 {
            d[i] = ar.diff(m[i], s)?;
        }
        out.terms.push((*f, d));
    }
    prune(t, &mut out)?;
    Ok(out)
}

/// The outer product `a b`.
pub(crate) fn outer<T: FrameTree + ?Sized>(t: &mut T, a: &Vector, b: &Vector) -> Result<Dyadic> {
    let mut out = Dyadic::zero();
    for (fa, ma) in &a.terms {
        for (fb, mb) in &b.terms {
            let ar = t.arena_mut();
            let mut m = [[ar.zero(); 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    m[i][j] = ar.mul(&[ma[i], mb[j]])?;
                }
            }
            out = add_dyadics(t, &out, &Dyadic { terms: vec![(*fa, *fb, m)] })?;
        }
    }
    Ok(out)
}

/// `a + b` for dyadics.
pub(crate) fn add_dyadics<T: FrameTree + ?Sized>(t: &mut T, a: &Dyadic, b: &Dyadic) -> Result<Dyadic> {
    let ar = t.arena_mut();
    let mut out = a.clone();
    for (f, g, m) in &b.terms {
        match out.terms.iter_mut().find(|(x, y, _)| x == f && y == g) {
            Some((_, _, acc)) => {
                for i in 0..3 {
                    for j in 0..3 {
                        acc[i][j] = ar.add(&[acc[i][j], m[i][j]])?;
                    }
                }
            }
            None => out.terms.push((*f, *g, *m)),
        }
    }
    Ok(out)
}

/// `k * d` for a dyadic.
pub(crate) fn scale_dyadic<T: FrameTree + ?Sized>(t: &mut T, d: &Dyadic, k: ExprId) -> Result<Dyadic> {
    let ar = t.arena_mut();
    let mut out = d.clone();
    for (_, _, m) in out.terms.iter_mut() {
        for row in m.iter_mut() {
            for x in row.iter_mut() {
                *x = ar.mul(&[k, *x])?;
            }
        }
    }
    Ok(out)
}

/// `d . v`.
pub(crate) fn dyadic_dot<T: FrameTree + ?Sized>(t: &mut T, d: &Dyadic, v: &Vector) -> Result<Vector> {
    let mut out = Vector::zero();
    for (fa, fb, m) in &d.terms {
        let vb = express(t, v, *fb)?;
        let ar = t.arena_mut();
        let mut r = [ar.zero(); 3];
        for (i, slot) in r.iter_mut().enumerate() {
            let terms: Vec<ExprId> =
                (0..3).map(|j| ar.mul(&[m[i][j], vb[j]])).collect::<std::result::Result<_, _>>()?;
            *slot = ar.add(&terms)?;
        }
        out = add_vectors(t, &out, &Vector::new(*fa, r))?;
    }
    Ok(out)
}
