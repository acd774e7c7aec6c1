//! Point kinematics: positions in a tree of points, velocities and accelerations in any frame.
//!
//! A velocity not set explicitly is the velocity of the point it is located from plus the time
//! derivative of the position vector in the frame. For a position fixed in a body this is the
//! two-points-fixed-on-a-body theorem (V2PTS); for one moving on a body, V1PT.

use super::error::{MechanicsError, Result};
use super::ids::{FrameId, PointId};
use super::model::Model;
use super::vector::Vector;

impl Model {
    /// Locates `point` at `r` from `from` (Autolev `P_FROM_POINT> = r`).
    ///
    /// Positions form a tree: the relation becomes `point`'s link to `from` if `point` has none,
    /// else `from`'s link to `point` (with `-r`) if that closes no loop; a relation between points
    /// already connected is redundant and is replaced by the new one in place of the old link
    /// only when `point` is linked directly to `from`. Locating a point from itself is an error.
    pub fn set_position(&mut self, point: PointId, from: PointId, r: Vector) -> Result<()> {
        if point == from {
            return Err(MechanicsError::PositionCycle(self.point_name(point).to_string()));
        }
        // Every relation is also an edge of the position graph (the newest between two points).
        self.position_edges.retain(|(a, b, _)| !((*a == from && *b == point) || (*a == point && *b == from)));
        self.position_edges.push((from, point, r.clone()));
        let linked_to_from = matches!(&self.points[point.index()].position, Some((p, _)) if *p == from);
        if linked_to_from
            || (self.points[point.index()].position.is_none() && !self.point_chain(from).contains(&point))
        {
            self.points[point.index()].position = Some((from, r));
        } else if self.points[from.index()].position.is_none() && !self.point_chain(point).contains(&from) {
            let minus = self.scale(&r, self.ar.minus_one())?;
            self.points[from.index()].position = Some((point, minus));
        } else if self.point_chain(from).contains(&point) && self.point_chain(point).len() == 1 {
            return Err(MechanicsError::PositionCycle(self.point_name(point).to_string()));
        }
        self.kinematics_cache = super::model::KinematicsCache::default();
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

    /// Two points fixed on a body (Autolev `V2PTS(frame, body, from, point)`): sets and returns
    /// `v_point = v_from + w_body x r`, with `r` the position of `point` from `from`.
    pub fn v2pts(&mut self, frame: FrameId, body: FrameId, from: PointId, point: PointId) -> Result<Vector> {
        let v0 = self.velocity(from, frame)?;
        let w = self.angular_velocity(body, frame)?;
        let r = self.position(point, from)?;
        let wr = self.cross(&w, &r)?;
        let v = self.add_vectors(&v0, &wr)?;
        self.set_velocity(point, frame, v.clone());
        Ok(v)
    }

    /// Two points fixed on a body (Autolev `A2PTS`): sets and returns
    /// `a_point = a_from + alpha x r + w x (w x r)`.
    pub fn a2pts(&mut self, frame: FrameId, body: FrameId, from: PointId, point: PointId) -> Result<Vector> {
        let a0 = self.acceleration(from, frame)?;
        let w = self.angular_velocity(body, frame)?;
        let alpha = self.angular_acceleration(body, frame)?;
        let r = self.position(point, from)?;
        let ar = self.cross(&alpha, &r)?;
        let wr = self.cross(&w, &r)?;
        let wwr = self.cross(&w, &wr)?;
        let a = self.add_vectors(&a0, &ar)?;
        let a = self.add_vectors(&a, &wwr)?;
        self.set_acceleration(point, frame, a.clone());
        Ok(a)
    }

    /// One point moving on a body (Autolev `V1PT(frame, body, from, point)`): sets and returns
    /// `v_point = v_from + v_point_in_body + w_body x r`, with `from` fixed on the body.
    pub fn v1pt(&mut self, frame: FrameId, body: FrameId, from: PointId, point: PointId) -> Result<Vector> {
        let v0 = self.velocity(from, frame)?;
        let r = self.position(point, from)?;
        let rel = self.dt_in(&r, body)?;
        let w = self.angular_velocity(body, frame)?;
        let wr = self.cross(&w, &r)?;
        let v = self.add_vectors(&v0, &rel)?;
        let v = self.add_vectors(&v, &wr)?;
        self.set_velocity(point, frame, v.clone());
        Ok(v)
    }

    /// One point moving on a body (Autolev `A1PT`): sets and returns
    /// `a_point = a_from + a_rel + alpha x r + w x (w x r) + 2 w x v_rel`.
    pub fn a1pt(&mut self, frame: FrameId, body: FrameId, from: PointId, point: PointId) -> Result<Vector> {
        let a0 = self.acceleration(from, frame)?;
        let r = self.position(point, from)?;
        let v_rel = self.dt_in(&r, body)?;
        let a_rel = self.dt_in(&v_rel, body)?;
        let w = self.angular_velocity(body, frame)?;
        let alpha = self.angular_acceleration(body, frame)?;
        let t1 = self.cross(&alpha, &r)?;
        let wr = self.cross(&w, &r)?;
        let t2 = self.cross(&w, &wr)?;
        let wv = self.cross(&w, &v_rel)?;
        let two = self.ar.integer(2);
        let t3 = self.scale(&wv, two)?;
        let mut a = self.add_vectors(&a0, &a_rel)?;
        for t in [t1, t2, t3] {
            a = self.add_vectors(&a, &t)?;
        }
        self.set_acceleration(point, frame, a.clone());
        Ok(a)
    }

    /// Fixes `point` in `frame`: zero velocity and acceleration there.
    pub fn fix_point(&mut self, point: PointId, frame: FrameId) {
        self.set_velocity(point, frame, Vector::zero());
        self.set_acceleration(point, frame, Vector::zero());
    }

    /// `point`, the point it is located from, and so on.
    pub(crate) fn point_chain(&self, point: PointId) -> Vec<PointId> {
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

    /// The position of `point` from `from` (Autolev `P_FROM_POINT>`), along the shortest chain of
    /// position relations (the newest relation between two points counts).
    pub fn position(&mut self, point: PointId, from: PointId) -> Result<Vector> {
        if point == from {
            return Ok(Vector::zero());
        }
        let Some(steps) = self.position_steps(point, from) else {
            return Err(MechanicsError::NoPositionPath {
                a: self.point_name(from).to_string(),
                b: self.point_name(point).to_string(),
            });
        };
        let mut r = Vector::zero();
        for (k, forward) in steps {
            let step = self.position_edges[k].2.clone();
            r = if forward { self.add_vectors(&r, &step)? } else { self.sub_vectors(&r, &step)? };
        }
        Ok(r)
    }

    /// The position relations on the shortest chain from `from` to `point`, each as the pair of
    /// points it relates (empty when there is none, or the two are one point).
    pub fn position_path(&self, point: PointId, from: PointId) -> Vec<(PointId, PointId)> {
        let steps = self.position_steps(point, from).unwrap_or_default();
        steps.into_iter().map(|(k, _)| (self.position_edges[k].0, self.position_edges[k].1)).collect()
    }

    /// The frames whose unit vectors the positions from `from` to `point` are written in.
    pub fn position_path_frames(&self, point: PointId, from: PointId) -> Vec<FrameId> {
        let steps = self.position_steps(point, from).unwrap_or_default();
        let mut out: Vec<FrameId> = steps
            .iter()
            .flat_map(|(k, _)| self.position_edges[*k].2.terms().iter().map(|(f, _)| *f))
            .collect();
        out.sort();
        out.dedup();
        out
    }

    /// The points connected to `point` by chains of position relations, `point` included.
    pub fn position_component(&self, point: PointId) -> Vec<PointId> {
        let (_, seen) = self.position_search(point, None);
        (0..self.points.len()).filter(|i| seen[*i]).map(|i| PointId(i as u32)).collect()
    }

    /// The edges (index, walked forward) from `from` to `point` along the shortest chain.
    fn position_steps(&self, point: PointId, from: PointId) -> Option<Vec<(usize, bool)>> {
        let (came, seen) = self.position_search(from, Some(point));
        if !seen[point.index()] {
            return None;
        }
        let mut steps = Vec::new();
        let mut p = point;
        while let Some((prev, k, forward)) = came[p.index()] {
            steps.push((k, forward));
            p = prev;
        }
        steps.reverse();
        Some(steps)
    }

    /// Breadth-first search of the position relations from `from` (until `goal`): for each
    /// point the edge it was reached through, and which points were reached.
    #[allow(clippy::type_complexity)]
    fn position_search(
        &self,
        from: PointId,
        goal: Option<PointId>,
    ) -> (Vec<Option<(PointId, usize, bool)>>, Vec<bool>) {
        let mut came: Vec<Option<(PointId, usize, bool)>> = vec![None; self.points.len()];
        let mut queue = std::collections::VecDeque::from([from]);
        let mut seen = vec![false; self.points.len()];
        seen[from.index()] = true;
        while let Some(p) = queue.pop_front() {
            if Some(p) == goal {
                break;
            }
            for (k, (a, b, _)) in self.position_edges.iter().enumerate() {
                let (next, forward) = if *a == p {
                    (*b, true)
                } else if *b == p {
                    (*a, false)
                } else {
                    continue;
                };
                if !seen[next.index()] {
                    seen[next.index()] = true;
                    came[next.index()] = Some((p, k, forward));
                    queue.push_back(next);
                }
            }
        }
        (came, seen)
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
        if let Some(v) = self.kinematics_cache.velocity.get(&(point, frame)) {
            return Ok(v.clone());
        }
        let base = self.velocity(from, frame)?;
        let rel = self.dt_in(&r, frame)?;
        let v = self.add_vectors(&base, &rel)?;
        self.kinematics_cache.velocity.insert((point, frame), v.clone());
        Ok(v)
    }

    /// Acceleration of `point` in `frame` (Autolev `A_P_A>`).
    pub fn acceleration(&mut self, point: PointId, frame: FrameId) -> Result<Vector> {
        if let Some(a) = self.points[point.index()].acceleration.get(&frame) {
            return Ok(a.clone());
        }
        if let Some(a) = self.kinematics_cache.acceleration.get(&(point, frame)) {
            return Ok(a.clone());
        }
        let v = self.velocity(point, frame)?;
        let a = self.dt_in(&v, frame)?;
        self.kinematics_cache.acceleration.insert((point, frame), a.clone());
        Ok(a)
    }
}
