//! Point kinematics: positions in a tree of points, velocities and accelerations in any frame.
//!
//! A velocity not set explicitly is the velocity of the point it is located from plus the time
//! derivative of the position vector in the frame. For a position fixed in a body this is the
//! two-points-fixed-on-a-body theorem (V2PTS); for one moving on a body, V1PT.

use super::error::{MechanicsError, Result};
use super::model::{FrameId, Model, PointId};
use super::vector::Vector;

impl Model {
    /// Locates `point` at `r` from `from` (Autolev `P_FROM_POINT> = r`).
    pub fn set_position(&mut self, point: PointId, from: PointId, r: Vector) -> Result<()> {
        if self.point_chain(from).contains(&point) {
            return Err(MechanicsError::PositionCycle(self.point_name(point).to_string()));
        }
        self.points[point.index()].position = Some((from, r));
        Ok(())
    }

    /// Sets the velocity of `point` in `frame` (Autolev `V_P_A> = v`).
    pub fn set_velocity(&mut self, point: PointId, frame: FrameId, v: Vector) {
        self.points[point.index()].velocity.insert(frame, v);
    }

    /// Sets the acceleration of `point` in `frame` (Autolev `A_P_A> = a`).
    pub fn set_acceleration(&mut self, point: PointId, frame: FrameId, a: Vector) {
        self.points[point.index()].acceleration.insert(frame, a);
    }

    /// Fixes `point` in `frame`: zero velocity and acceleration there.
    pub fn fix_point(&mut self, point: PointId, frame: FrameId) {
        self.set_velocity(point, frame, Vector::zero());
        self.set_acceleration(point, frame, Vector::zero());
    }

    /// `point`, the point it is located from, and so on.
    fn point_chain(&self, point: PointId) -> Vec<PointId> {
        let mut chain = vec![point];
        let mut p = point;
        while let Some((q, _)) = &self.points[p.index()].position {
            if chain.contains(q) {
                break;
            }
            chain.push(*q);
            p = *q;
        }
        chain
    }

    /// The position of `point` from `from` (Autolev `P_FROM_POINT>`).
    pub fn position(&mut self, point: PointId, from: PointId) -> Result<Vector> {
        let up_p = self.point_chain(point);
        let up_f = self.point_chain(from);
        let Some(common) = up_p.iter().copied().find(|x| up_f.contains(x)) else {
            return Err(MechanicsError::NoPositionPath {
                a: self.point_name(from).to_string(),
                b: self.point_name(point).to_string(),
            });
        };
        let mut r = Vector::zero();
        for &p in up_p.iter().take_while(|p| **p != common) {
            let step = self.points[p.index()].position.clone().map(|x| x.1).unwrap_or_default();
            r = self.add_vectors(&r, &step)?;
        }
        for &p in up_f.iter().take_while(|p| **p != common) {
            let step = self.points[p.index()].position.clone().map(|x| x.1).unwrap_or_default();
            r = self.sub_vectors(&r, &step)?;
        }
        Ok(r)
    }

    /// Velocity of `point` in `frame` (Autolev `V_P_A>`).
    pub fn velocity(&mut self, point: PointId, frame: FrameId) -> Result<Vector> {
        if let Some(v) = self.points[point.index()].velocity.get(&frame) {
            return Ok(v.clone());
        }
        let Some((from, r)) = self.points[point.index()].position.clone() else {
            return Err(MechanicsError::VelocityUndefined {
                point: self.point_name(point).to_string(),
                frame: self.frame_name(frame).to_string(),
            });
        };
        let base = self.velocity(from, frame)?;
        let rel = self.dt_in(&r, frame)?;
        let v = self.add_vectors(&base, &rel)?;
        self.points[point.index()].velocity.insert(frame, v.clone());
        Ok(v)
    }

    /// Acceleration of `point` in `frame` (Autolev `A_P_A>`).
    pub fn acceleration(&mut self, point: PointId, frame: FrameId) -> Result<Vector> {
        if let Some(a) = self.points[point.index()].acceleration.get(&frame) {
            return Ok(a.clone());
        }
        let v = self.velocity(point, frame)?;
        let a = self.dt_in(&v, frame)?;
        self.points[point.index()].acceleration.insert(frame, a.clone());
        Ok(a)
    }
}
