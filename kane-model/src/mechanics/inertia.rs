//! Central inertia of primitive shapes, and the parallel-axis transfer.
//!
//! Autolev has no inertia by shape; these are an extension. Each returns the principal moments
//! about the mass centre along the shape's own axes 1, 2, 3.

use crate::expr::ExprId;

use super::error::Result;
use super::ids::{FrameId, Mat3};
use super::model::{Model, Orientation};
use super::vector::{Dyadic, Vector};

/// A body shape with uniform density; axis 3 is the symmetry axis where there is one.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// Solid ellipsoid with semi-axes `a, b, c` along axes 1, 2, 3: `m (b^2 + c^2) / 5`, ...
    SolidEllipsoid {
        /// Semi-axis along 1.
        a: ExprId,
        /// Semi-axis along 2.
        b: ExprId,
        /// Semi-axis along 3.
        c: ExprId,
    },
    /// Solid sphere of radius `r`: `2 m r^2 / 5` about every axis.
    SolidSphere {
        /// The radius of the shape.
        r: ExprId,
    },
    /// Solid cylinder of radius `r` and length `l` along axis 3.
    SolidCylinder {
        /// The radius of the shape.
        r: ExprId,
        /// The length along the axis.
        l: ExprId,
    },
    /// Thin rod of length `l` along axis 3: `m l^2 / 12` transverse, zero axial.
    ThinRod {
        /// The length along the axis.
        l: ExprId,
    },
    /// Box with edge lengths `a, b, c` along axes 1, 2, 3: `m (b^2 + c^2) / 12`, ...
    Cuboid {
        /// Edge along 1.
        a: ExprId,
        /// Edge along 2.
        b: ExprId,
        /// Edge along 3.
        c: ExprId,
    },
    /// Thin disk of radius `r` with normal along axis 3: `m r^2 / 4` transverse, `m r^2 / 2` axial.
    ThinDisk {
        /// The radius of the shape.
        r: ExprId,
    },
}

impl Model {
    /// Principal central moments of `shape` with mass `m` about axes 1, 2, 3.
    pub fn shape_moments(&mut self, shape: Shape, m: ExprId) -> Result<[ExprId; 3]> {
        let ar = &mut self.ar;
        let frac = |ar: &mut crate::expr::Arena, num: i128, den: i128, terms: &[ExprId]| -> Result<ExprId> {
            let k = ar.rational(num, den)?;
            let sq: Vec<ExprId> =
                terms.iter().map(|t| ar.powi(*t, 2)).collect::<std::result::Result<_, _>>()?;
            let s = ar.add(&sq)?;
            Ok(ar.mul(&[k, m, s])?)
        };
        Ok(match shape {
            Shape::SolidEllipsoid { a, b, c } => {
                [frac(ar, 1, 5, &[b, c])?, frac(ar, 1, 5, &[a, c])?, frac(ar, 1, 5, &[a, b])?]
            }
            Shape::SolidSphere { r } => {
                let i = frac(ar, 2, 5, &[r])?;
                [i, i, i]
            }
            Shape::SolidCylinder { r, l } => {
                let r2 = frac(ar, 1, 4, &[r])?;
                let l2 = frac(ar, 1, 12, &[l])?;
                let t = ar.add(&[r2, l2])?;
                [t, t, frac(ar, 1, 2, &[r])?]
            }
            Shape::ThinRod { l } => {
                let t = frac(ar, 1, 12, &[l])?;
                [t, t, ar.zero()]
            }
            Shape::Cuboid { a, b, c } => {
                [frac(ar, 1, 12, &[b, c])?, frac(ar, 1, 12, &[a, c])?, frac(ar, 1, 12, &[a, b])?]
            }
            Shape::ThinDisk { r } => {
                let t = frac(ar, 1, 4, &[r])?;
                [t, t, frac(ar, 1, 2, &[r])?]
            }
        })
    }

    /// The central inertia dyadic of `shape` with mass `m`, its axes along `frame`'s.
    pub fn shape_inertia(&mut self, shape: Shape, m: ExprId, frame: FrameId) -> Result<Dyadic> {
        let d = self.shape_moments(shape, m)?;
        Ok(self.diagonal_inertia(frame, d))
    }

    /// `d[0] f1 f1 + d[1] f2 f2 + d[2] f3 f3`.
    pub fn diagonal_inertia(&self, frame: FrameId, d: [ExprId; 3]) -> Dyadic {
        let z = self.ar.zero();
        Dyadic::in_frame(frame, [[d[0], z, z], [z, d[1], z], [z, z, d[2]]])
    }

    /// The same dyadic written in the frame closest to the Newtonian frame in which it has the same
    /// measure numbers: a diagonal inertia axisymmetric about the axis of a simple rotation is
    /// unchanged by that rotation, so a symmetric rotor's inertia can be used in its gimbal's
    /// frame and the rotor angle drops out of the equations.
    pub fn rebase_inertia(&self, d: &Dyadic) -> Dyadic {
        let mut out = d.clone();
        for term in out.terms.iter_mut() {
            loop {
                let (fa, fb, m) = *term;
                if fa != fb || !is_diagonal(&self.ar, &m) {
                    break;
                }
                let frame = &self.frames[fa.index()];
                let (Some(parent), Some(Orientation::Axis { axis, .. })) = (frame.parent, &frame.orientation)
                else {
                    break;
                };
                let k = usize::from(axis.unsigned_abs()) - 1;
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                if m[i][i] != m[j][j] || self.frames[fa.index()].ang_vel.is_some() {
                    break;
                }
                *term = (parent, parent, m);
            }
        }
        out
    }

    /// Parallel-axis transfer: inertia about a point at `r` from the mass centre,
    /// `I + m (r.r U - r r)`, expressed in `frame`.
    pub fn parallel_axis(
        &mut self,
        central: &Dyadic,
        m: ExprId,
        r: &Vector,
        frame: FrameId,
    ) -> Result<Dyadic> {
        let rr = self.express(r, frame)?;
        let r2 = self.dot(r, r)?;
        let mut shift = [[self.ar.zero(); 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                let outer = self.ar.mul(&[rr[i], rr[j]])?;
                let e = if i == j { self.ar.sub(r2, outer)? } else { self.ar.neg(outer)? };
                shift[i][j] = self.ar.mul(&[m, e])?;
            }
        }
        self.add_dyadics(central, &Dyadic::in_frame(frame, shift))
    }
}

fn is_diagonal(ar: &crate::expr::Arena, m: &Mat3) -> bool {
    (0..3).all(|i| (0..3).all(|j| i == j || ar.is_zero(m[i][j])))
}
