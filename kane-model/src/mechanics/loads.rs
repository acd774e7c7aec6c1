//! Applied loads: forces at points, torques on bodies, action-reaction pairs, linear springs and
//! dampers between points.
//!
//! In: points, frames, vectors and coefficients. Out: entries of the model's load list, which
//! Kane's method turns into generalized active forces.

use crate::expr::ExprId;

use super::error::Result;
use super::ids::{FrameId, PointId};
use super::model::{Load, Model};
use super::vector::Vector;

impl Model {
    /// Removes every applied load.
    pub fn clear_loads(&mut self) {
        self.loads.clear();
    }

    /// Applies a force at a point.
    pub fn add_force(&mut self, point: PointId, force: Vector) {
        self.loads.push(Load::Force { point, force });
    }

    /// Applies a torque to the body fixed in `frame`.
    pub fn add_torque(&mut self, frame: FrameId, torque: Vector) {
        self.loads.push(Load::Torque { frame, torque });
    }

    /// Applies equal and opposite torques: `torque` on `on`, `-torque` on `from`.
    pub fn add_torque_pair(&mut self, on: FrameId, from: FrameId, torque: Vector) -> Result<()> {
        let minus = self.scale(&torque, self.ar.minus_one())?;
        self.add_torque(on, torque);
        self.add_torque(from, minus);
        Ok(())
    }

    /// Applies equal and opposite forces: `force` at `on`, `-force` at `from`.
    pub fn add_force_pair(&mut self, on: PointId, from: PointId, force: Vector) -> Result<()> {
        let minus = self.scale(&force, self.ar.minus_one())?;
        self.add_force(on, force);
        self.add_force(from, minus);
        Ok(())
    }

    /// A linear spring of stiffness `k` and natural length `length` between two points: the force
    /// `-k (|r| - length) r/|r|` on `a` and its opposite on `b`, with `r` from `b` to `a`.
    pub fn add_spring(&mut self, a: PointId, b: PointId, k: ExprId, length: ExprId) -> Result<()> {
        let r = self.position(a, b)?;
        let len = self.magnitude(&r)?;
        let stretch = self.ar.sub(len, length)?;
        let per_length = self.ar.div(stretch, len)?;
        let coeff = self.ar.mul(&[self.ar.minus_one(), k, per_length])?;
        let f = self.scale(&r, coeff)?;
        self.add_force_pair(a, b, f)
    }

    /// A linear damper of coefficient `c` between two points: the force `-c (d|r|/dt) r/|r|` on
    /// `a` and its opposite on `b`, with `r` from `b` to `a`.
    pub fn add_damper(&mut self, a: PointId, b: PointId, c: ExprId) -> Result<()> {
        let r = self.position(a, b)?;
        let n = self.newtonian;
        let va = self.velocity(a, n)?;
        let vb = self.velocity(b, n)?;
        let v = self.sub_vectors(&va, &vb)?;
        let rv = self.dot(&r, &v)?;
        let rr = self.dot(&r, &r)?;
        let rate = self.ar.div(rv, rr)?;
        let coeff = self.ar.mul(&[self.ar.minus_one(), c, rate])?;
        let f = self.scale(&r, coeff)?;
        self.add_force_pair(a, b, f)
    }

    /// The applied loads.
    pub fn loads(&self) -> &[Load] {
        &self.loads
    }
}
