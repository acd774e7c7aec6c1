//! Vector and dyadic algebra: sums, scaling, dot, cross, express, time and partial derivatives.
//!
//! Operations keep measure numbers in the frames they were written in and convert a term only
//! when it meets a term of another frame.

use crate::expr::{ExprId, SymbolId};

use super::error::Result;
use super::model::{FrameId, Model, Orientation};
use super::vector::{Dyadic, Vector};

impl Model {
    /// The unit vector `frame_axis` (axis 1, 2 or 3).
    pub fn unit(&self, frame: FrameId, axis: usize) -> Vector {
        let mut m = [self.ar.zero(); 3];
        m[axis - 1] = self.ar.one();
        Vector::new(frame, m)
    }

    /// `sum_i m[i] frame_i`.
    pub fn vector(&self, frame: FrameId, m: [ExprId; 3]) -> Vector {
        Vector::new(frame, m)
    }

    /// `a + b`, merging terms of the same frame.
    pub fn add_vectors(&mut self, a: &Vector, b: &Vector) -> Result<Vector> {
        let mut out = a.clone();
        for (f, m) in &b.terms {
            match out.terms.iter_mut().find(|(g, _)| g == f) {
                Some((_, acc)) => {
                    for i in 0..3 {
                        acc[i] = self.ar.add(&[acc[i], m[i]])?;
                    }
                }
                None => out.terms.push((*f, *m)),
            }
        }
        self.prune(&mut out)?;
        Ok(out)
    }

    /// `a - b`.
    pub fn sub_vectors(&mut self, a: &Vector, b: &Vector) -> Result<Vector> {
        let nb = self.scale(b, self.ar.minus_one())?;
        self.add_vectors(a, &nb)
    }

    /// `k * v`.
    pub fn scale(&mut self, v: &Vector, k: ExprId) -> Result<Vector> {
        let mut out = v.clone();
        for (_, m) in out.terms.iter_mut() {
            for x in m.iter_mut() {
                *x = self.ar.mul(&[k, *x])?;
            }
        }
        self.prune(&mut out)?;
        Ok(out)
    }

    /// Drops zero terms, and moves a term lying along the axis of its frame's simple rotation to
    /// the parent frame (where its measure numbers are the same), merging terms that meet.
    fn prune(&mut self, v: &mut Vector) -> Result<()> {
        v.terms.retain(|(_, m)| !m.iter().all(|x| self.ar.is_zero(*x)));
        let mut moved = false;
        for (f, m) in v.terms.iter_mut() {
            while let Some(parent) = self.axis_parent(*f, m) {
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
                            acc[i] = self.ar.add(&[acc[i], m[i]])?;
                        }
                    }
                    None => merged.push((f, m)),
                }
            }
            merged.retain(|(_, m)| !m.iter().all(|x| self.ar.is_zero(*x)));
            v.terms = merged;
        }
        Ok(())
    }

    /// The parent of `frame` when `m` lies along the axis of `frame`'s simple rotation.
    fn axis_parent(&self, frame: FrameId, m: &[ExprId; 3]) -> Option<FrameId> {
        let f = &self.frames[frame.index()];
        let (Some(parent), Some(Orientation::Axis { axis, .. })) = (f.parent, &f.orientation) else {
            return None;
        };
        let k = usize::from(axis.unsigned_abs()) - 1;
        let off_axis_zero = (0..3).all(|i| i == k || self.ar.is_zero(m[i]));
        off_axis_zero.then_some(parent)
    }

    /// Measure numbers of `v` in `frame`.
    pub fn express(&mut self, v: &Vector, frame: FrameId) -> Result<[ExprId; 3]> {
        let mut parts: [Vec<ExprId>; 3] = Default::default();
        for (f, m) in &v.terms {
            let conv = self.convert(m, *f, frame)?;
            for i in 0..3 {
                parts[i].push(conv[i]);
            }
        }
        Ok([self.ar.add(&parts[0])?, self.ar.add(&parts[1])?, self.ar.add(&parts[2])?])
    }

    /// `v` rewritten as a single term in `frame`.
    pub fn express_vector(&mut self, v: &Vector, frame: FrameId) -> Result<Vector> {
        let m = self.express(v, frame)?;
        let mut out = Vector::new(frame, m);
        self.prune(&mut out)?;
        Ok(out)
    }

    /// Measure numbers `m` (in frame `from`) converted to frame `to`.
    fn convert(&mut self, m: &[ExprId; 3], from: FrameId, to: FrameId) -> Result<[ExprId; 3]> {
        if from == to {
            return Ok(*m);
        }
        let c = self.dcm(to, from)?;
        let mut out = [self.ar.zero(); 3];
        for (i, slot) in out.iter_mut().enumerate() {
            let terms: Vec<ExprId> =
                (0..3).map(|j| self.ar.mul(&[c[i][j], m[j]])).collect::<std::result::Result<_, _>>()?;
            *slot = self.ar.add(&terms)?;
        }
        Ok(out)
    }

    /// `a . b`.
    pub fn dot(&mut self, a: &Vector, b: &Vector) -> Result<ExprId> {
        let mut terms = Vec::new();
        for (fa, ma) in &a.terms {
            for (fb, mb) in &b.terms {
                let mb = self.convert(mb, *fb, *fa)?;
                for i in 0..3 {
                    terms.push(self.ar.mul(&[ma[i], mb[i]])?);
                }
            }
        }
        Ok(self.ar.add(&terms)?)
    }

    /// `a x b`, in the frames of `a`'s terms.
    pub fn cross(&mut self, a: &Vector, b: &Vector) -> Result<Vector> {
        let mut out = Vector::zero();
        for (fa, ma) in &a.terms {
            for (fb, mb) in &b.terms {
                let mb = self.convert(mb, *fb, *fa)?;
                let mut c = [self.ar.zero(); 3];
                for (i, slot) in c.iter_mut().enumerate() {
                    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                    let p = self.ar.mul(&[ma[j], mb[k]])?;
                    let q = self.ar.mul(&[ma[k], mb[j]])?;
                    *slot = self.ar.sub(p, q)?;
                }
                out = self.add_vectors(&out, &Vector::new(*fa, c))?;
            }
        }
        Ok(out)
    }

    /// `|v|`.
    pub fn magnitude(&mut self, v: &Vector) -> Result<ExprId> {
        let d = self.dot(v, v)?;
        Ok(self.ar.sqrt(d)?)
    }

    /// The time derivative of `v` as seen in `frame`, with the kinematic equations applied.
    pub fn dt_in(&mut self, v: &Vector, frame: FrameId) -> Result<Vector> {
        let mut out = Vector::zero();
        for (f, m) in v.terms.clone() {
            let mut d = [self.ar.zero(); 3];
            for i in 0..3 {
                d[i] = self.dt(m[i])?;
            }
            out = self.add_vectors(&out, &Vector::new(f, d))?;
            if f != frame {
                let w = self.angular_velocity(f, frame)?;
                let t = self.cross(&w, &Vector::new(f, m))?;
                out = self.add_vectors(&out, &t)?;
            }
        }
        Ok(out)
    }

    /// The partial derivative of `v` with respect to a symbol (frames do not depend on it).
    pub fn partial(&mut self, v: &Vector, s: SymbolId) -> Result<Vector> {
        let mut out = Vector::zero();
        for (f, m) in &v.terms {
            let mut d = [self.ar.zero(); 3];
            for i in 0..3 {
                d[i] = self.ar.diff(m[i], s)?;
            }
            out.terms.push((*f, d));
        }
        self.prune(&mut out)?;
        Ok(out)
    }

    /// The outer product `a b` (Autolev `A1>*B1>` in a dyadic context).
    pub fn outer(&mut self, a: &Vector, b: &Vector) -> Result<Dyadic> {
        let mut out = Dyadic::zero();
        for (fa, ma) in &a.terms {
            for (fb, mb) in &b.terms {
                let mut m = [[self.ar.zero(); 3]; 3];
                for i in 0..3 {
                    for j in 0..3 {
                        m[i][j] = self.ar.mul(&[ma[i], mb[j]])?;
                    }
                }
                out = self.add_dyadics(&out, &Dyadic { terms: vec![(*fa, *fb, m)] })?;
            }
        }
        Ok(out)
    }

    /// `a + b` for dyadics.
    pub fn add_dyadics(&mut self, a: &Dyadic, b: &Dyadic) -> Result<Dyadic> {
        let mut out = a.clone();
        for (f, g, m) in &b.terms {
            match out.terms.iter_mut().find(|(x, y, _)| x == f && y == g) {
                Some((_, _, acc)) => {
                    for i in 0..3 {
                        for j in 0..3 {
                            acc[i][j] = self.ar.add(&[acc[i][j], m[i][j]])?;
                        }
                    }
                }
                None => out.terms.push((*f, *g, *m)),
            }
        }
        Ok(out)
    }

    /// `k * d` for a dyadic.
    pub fn scale_dyadic(&mut self, d: &Dyadic, k: ExprId) -> Result<Dyadic> {
        let mut out = d.clone();
        for (_, _, m) in out.terms.iter_mut() {
            for row in m.iter_mut() {
                for x in row.iter_mut() {
                    *x = self.ar.mul(&[k, *x])?;
                }
            }
        }
        Ok(out)
    }

    /// `d . v`.
    pub fn dyadic_dot(&mut self, d: &Dyadic, v: &Vector) -> Result<Vector> {
        let mut out = Vector::zero();
        for (fa, fb, m) in &d.terms {
            let vb = self.express(v, *fb)?;
            let mut r = [self.ar.zero(); 3];
            for (i, slot) in r.iter_mut().enumerate() {
                let terms: Vec<ExprId> =
                    (0..3).map(|j| self.ar.mul(&[m[i][j], vb[j]])).collect::<std::result::Result<_, _>>()?;
                *slot = self.ar.add(&terms)?;
            }
            out = self.add_vectors(&out, &Vector::new(*fa, r))?;
        }
        Ok(out)
    }
}
