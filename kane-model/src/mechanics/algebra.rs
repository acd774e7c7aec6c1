//! The model's vector and dyadic methods: the model as the [`FrameTree`] of the vector algebra,
//! and the public methods (`add_vectors`, `dot`, `cross`, `express`, ...) that forward to it.
//!
//! In: vectors, dyadics and frames of a [`Model`]. Out: what [`super::vector_ops`] computes,
//! with the model's frames supplying direction cosines and simple rotations.

use crate::expr::{Arena, ExprId, SymbolId};

use super::error::Result;
use super::ids::{FrameId, Mat3};
use super::model::{Model, Orientation};
use super::vector::{Dyadic, Vector};
use super::vector_ops::{self as ops, FrameTree};

impl FrameTree for Model {
    fn arena(&self) -> &Arena {
        &self.ar
    }

    fn arena_mut(&mut self) -> &mut Arena {
        &mut self.ar
    }

    fn direction_cosines(&mut self, a: FrameId, b: FrameId) -> Result<Mat3> {
        self.dcm(a, b)
    }

    fn simple_rotation(&self, frame: FrameId) -> Option<(FrameId, usize)> {
        let f = &self.frames[frame.index()];
        match (f.parent, &f.orientation) {
            (Some(parent), Some(Orientation::Axis { axis, .. })) => {
                Some((parent, usize::from(axis.unsigned_abs()) - 1))
            }
            _ => None,
        }
    }
}

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
        ops::add_vectors(self, a, b)
    }

    /// `a - b`.
    pub fn sub_vectors(&mut self, a: &Vector, b: &Vector) -> Result<Vector> {
        ops::sub_vectors(self, a, b)
    }

    /// `k * v`.
    pub fn scale(&mut self, v: &Vector, k: ExprId) -> Result<Vector> {
        ops::scale(self, v, k)
    }

    /// Measure numbers of `v` in `frame`.
    pub fn express(&mut self, v: &Vector, frame: FrameId) -> Result<[ExprId; 3]> {
        ops::express(self, v, frame)
    }

    /// `v` rewritten as a single term in `frame`.
    pub fn express_vector(&mut self, v: &Vector, frame: FrameId) -> Result<Vector> {
        ops::express_vector(self, v, frame)
    }

    /// `a . b`.
    pub fn dot(&mut self, a: &Vector, b: &Vector) -> Result<ExprId> {
        ops::dot(self, a, b)
    }

    /// `a x b`, in the frames of `a`'s terms.
    pub fn cross(&mut self, a: &Vector, b: &Vector) -> Result<Vector> {
        ops::cross(self, a, b)
    }

    /// `|v|`.
    pub fn magnitude(&mut self, v: &Vector) -> Result<ExprId> {
        ops::magnitude(self, v)
    }

    /// The partial derivative of `v` with respect to a symbol (frames do not depend on it).
    pub fn partial(&mut self, v: &Vector, s: SymbolId) -> Result<Vector> {
        ops::partial(self, v, s)
    }

    /// The outer product `a b` (Autolev `A1>*B1>` in a dyadic context).
    pub fn outer(&mut self, a: &Vector, b: &Vector) -> Result<Dyadic> {
        ops::outer(self, a, b)
    }

    /// `a + b` for dyadics.
    pub fn add_dyadics(&mut self, a: &Dyadic, b: &Dyadic) -> Result<Dyadic> {
        ops::add_dyadics(self, a, b)
    }

    /// `k * d` for a dyadic.
    pub fn scale_dyadic(&mut self, d: &Dyadic, k: ExprId) -> Result<Dyadic> {
        ops::scale_dyadic(self, d, k)
    }

    /// `d . v`.
    pub fn dyadic_dot(&mut self, d: &Dyadic, v: &Vector) -> Result<Vector> {
        ops::dyadic_dot(self, d, v)
    }

    /// `v x d` when `v_first`, else `d x v`: each term `m a_i b_j` becomes `m (v x a_i) b_j`,
    /// or `m a_i (b_j x v)`.
    pub fn cross_dyadic(&mut self, v: &Vector, d: &Dyadic, v_first: bool) -> Result<Dyadic> {
        let mut out = Dyadic::zero();
        for (a, b, m) in d.terms.clone() {
            for (i, row) in m.iter().enumerate() {
                for (j, &k) in row.iter().enumerate() {
                    if self.ar.is_zero(k) {
                        continue;
                    }
                    let (a_i, b_j) = (self.unit_vector(a, i), self.unit_vector(b, j));
                    let term = if v_first {
                        let left = self.cross(v, &a_i)?;
                        self.outer(&left, &b_j)?
                    } else {
                        let right = self.cross(&b_j, v)?;
                        self.outer(&a_i, &right)?
                    };
                    let term = self.scale_dyadic(&term, k)?;
                    out = self.add_dyadics(&out, &term)?;
                }
            }
        }
        Ok(out)
    }

    /// The unit vector along axis `i` (0, 1, 2) of `frame`.
    fn unit_vector(&mut self, frame: FrameId, i: usize) -> Vector {
        let (zero, one) = (self.ar.zero(), self.ar.one());
        Vector::new(frame, std::array::from_fn(|k| if k == i { one } else { zero }))
    }
}
