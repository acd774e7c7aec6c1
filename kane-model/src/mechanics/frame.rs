//! Orienting frames in a tree, direction cosines between any two frames, angular velocities.

use crate::expr::{ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::ids::{FrameId, Mat3};
use super::model::{Model, Orientation};
use super::vector::Vector;

impl Model {
    /// Orients `frame` relative to `parent` (Autolev's SIMPROT, DIRCOS, `A_B = [...]`).
    ///
    /// Orientations form a tree, whichever of the two frames each statement names first: a frame
    /// already oriented in another tree turns that tree around (the Newtonian frame's tree stays
    /// rooted at it), and orienting two frames already related directly replaces that relation,
    /// as a later Autolev statement replaces an earlier one. Relating two frames already related
    /// through others would close a loop: an error.
    pub fn orient(&mut self, frame: FrameId, parent: FrameId, orientation: Orientation) -> Result<()> {
        match self.link(frame, parent)? {
            Link::Child => self.frames[frame.index()].orientation = Some(orientation),
            Link::Parent => {
                let inverse = self.inverse_orientation(orientation)?;
                self.frames[parent.index()].orientation = Some(inverse);
            }
        }
        self.clear_orientation_caches();
        Ok(())
    }

    /// Sets the angular velocity of `frame` relative to its parent explicitly.
    pub fn set_angular_velocity(&mut self, frame: FrameId, w: Vector) {
        self.frames[frame.index()].ang_vel = Some(w);
        self.clear_kinematics_caches();
    }

    /// Sets the angular velocity of `frame` in `reference` (Autolev `W_B_A> = ...`) when the two
    /// are related directly or not yet at all; a frame not yet oriented is related to
    /// `reference` with that angular velocity and no orientation (its direction cosines are then
    /// unknown, and asking for them is an error). Returns the frame whose angular velocity in
    /// its parent was set: `frame`, or `reference` (with `-w`) where the tree has `frame` above.
    pub fn set_angular_velocity_in(
        &mut self,
        frame: FrameId,
        reference: FrameId,
        w: Vector,
    ) -> Result<FrameId> {
        let (set, w) = match self.link(frame, reference)? {
            Link::Child => (frame, w),
            Link::Parent => (reference, self.scale(&w, self.ar.minus_one())?),
        };
        self.clear_orientation_caches();
        self.set_angular_velocity(set, w);
        Ok(set)
    }

    /// Whether `frame` and `reference` are related directly (either way round).
    pub fn frames_related(&self, frame: FrameId, reference: FrameId) -> bool {
        self.frames[frame.index()].parent == Some(reference)
            || self.frames[reference.index()].parent == Some(frame)
    }

    /// Relates `frame` to `parent` in the tree of orientations and says which of the two is the
    /// child: `frame`, unless `frame` is connected to the Newtonian frame and `parent` is not
    /// (then `parent`'s tree is turned to hang from `frame`), or the two are related already the
    /// other way round.
    fn link(&mut self, frame: FrameId, parent: FrameId) -> Result<Link> {
        let cycle = || MechanicsError::OrientationCycle {
            frame: self.frame_name(frame).to_string(),
            parent: self.frame_name(parent).to_string(),
        };
        if frame == parent {
            return Err(cycle());
        }
        if self.frames[frame.index()].parent == Some(parent) {
            return Ok(Link::Child);
        }
        if self.frames[parent.index()].parent == Some(frame) {
            return Ok(Link::Parent);
        }
        let (root_f, root_p) = (self.root(frame), self.root(parent));
        if root_f == root_p {
            return Err(cycle());
        }
        if root_f == self.newtonian {
            self.reroot(parent)?;
            self.frames[parent.index()].parent = Some(frame);
            return Ok(Link::Parent);
        }
        self.reroot(frame)?;
        self.frames[frame.index()].parent = Some(parent);
        Ok(Link::Child)
    }

    /// The root of `frame`'s tree of orientations.
    fn root(&self, frame: FrameId) -> FrameId {
        *self.ancestors(frame).last().unwrap_or(&frame)
    }

    /// Turns `frame`'s tree around so that `frame` is its root: every relation on the way from
    /// `frame` up to the old root is reversed (orientation inverted, angular velocity negated).
    fn reroot(&mut self, frame: FrameId) -> Result<()> {
        let chain = self.ancestors(frame);
        let mut reversed = Vec::with_capacity(chain.len());
        for w in chain.windows(2) {
            let (child, up) = (w[0], w[1]);
            let f = &self.frames[child.index()];
            let (orientation, ang_vel) = (f.orientation.clone(), f.ang_vel.clone());
            let orientation = orientation.map(|o| self.inverse_orientation(o)).transpose()?;
            let ang_vel = ang_vel.map(|w| self.scale(&w, self.ar.minus_one())).transpose()?;
            reversed.push((up, child, orientation, ang_vel));
        }
        self.frames[frame.index()].parent = None;
        self.frames[frame.index()].orientation = None;
        self.frames[frame.index()].ang_vel = None;
        for (f, parent, orientation, ang_vel) in reversed {
            let slot = &mut self.frames[f.index()];
            slot.parent = Some(parent);
            slot.orientation = orientation;
            slot.ang_vel = ang_vel;
        }
        self.clear_orientation_caches();
        Ok(())
    }

    /// The orientation of a parent relative to its child, from the child's relative to the
    /// parent: a simple rotation turns about the opposite axis; anything else is the transposed
    /// direction cosine matrix.
    fn inverse_orientation(&mut self, o: Orientation) -> Result<Orientation> {
        Ok(match o {
            Orientation::Axis { axis, angle } => Orientation::Axis { axis: -axis, angle },
            other => Orientation::Dcm(transpose(&self.orientation_dcm(&other)?)),
        })
    }

    /// Forgets direction cosines and angular velocities computed for the orientations before.
    fn clear_orientation_caches(&mut self) {
        self.dcm_cache.clear();
        self.clear_kinematics_caches();
    }

    /// The frame `frame` is oriented relative to, if any.
    pub fn frame_parent(&self, frame: FrameId) -> Option<FrameId> {
        self.frames[frame.index()].parent
    }

    /// Sets the angular velocity of `frame`, oriented through a chain of frames, in `reference`
    /// to `w`: `frame` turns in its parent at `w - W_parent_reference`, so `W_frame_reference`
    /// is `w` as written.
    pub fn set_angular_velocity_through(
        &mut self,
        frame: FrameId,
        reference: FrameId,
        w: Vector,
    ) -> Result<()> {
        let parent = self.frames[frame.index()].parent.unwrap_or(reference);
        let carried = self.angular_velocity(parent, reference)?;
        let relative = self.sub_vectors(&w, &carried)?;
        self.set_angular_velocity(frame, relative);
        Ok(())
    }

    /// The kinematic equations an angular velocity `w` of `frame` in `reference`, given in
    /// speeds, implies for the coordinate rates of the chain of orientations between them that
    /// have none yet (SymPy's `kd` equations, `w_chain = w`): none when `w` is written in the
    /// coordinates' rates or the chain's rates all have equations; else all three, set on the
    /// model and returned.
    pub fn chain_kinematics(
        &mut self,
        frame: FrameId,
        reference: FrameId,
        w: &Vector,
    ) -> Result<Vec<(SymbolId, ExprId)>> {
        if self.vector_has_rates(w)? {
            return Ok(Vec::new());
        }
        // The chain's own angular velocity from the orientations' rates, frame by frame.
        let chain = self.along_tree(frame, reference, Model::orientation_angular_velocity)?;
        let difference = self.sub_vectors(&chain, w)?;
        let equations = self.express(&difference, frame)?;
        let rates: Vec<SymbolId> = self
            .ar
            .free_symbols(&equations)
            .into_iter()
            .filter(|s| {
                let info = self.ar.symbol_info(*s);
                matches!(info.kind, crate::expr::SymbolKind::Variable { order: 1 })
                    && !self.kinematics.contains_key(&info.base)
            })
            .collect();
        if rates.is_empty() {
            return Ok(Vec::new());
        }
        if rates.len() != 3 {
            let names: Vec<&str> = rates.iter().map(|s| self.ar.symbol_info(*s).name.as_str()).collect();
            return Err(MechanicsError::AngularVelocityUnderdetermined {
                frame: self.frame_name(frame).to_string(),
                reference: self.frame_name(reference).to_string(),
                found: rates.len(),
                names: names.join(", "),
            });
        }
        let solved = self.ar.solve_linear(&equations, &rates)?;
        let mut set = Vec::with_capacity(3);
        for (rate, rhs) in rates.iter().zip(solved) {
            let q = self.ar.symbol_info(*rate).base;
            let rhs = self.ar.trig_simplify(rhs)?;
            let q_expr = self.ar.symbol_expr(q);
            self.set_kinematics(q_expr, rhs)?;
            set.push((q, rhs));
        }
        Ok(set)
    }

    /// Whether `w`'s measure numbers hold the rate of a variable (`Q'`, a derivative symbol).
    fn vector_has_rates(&mut self, w: &Vector) -> Result<bool> {
        let entries: Vec<ExprId> = w.terms.iter().flat_map(|(_, m)| *m).collect();
        let ar = &self.ar;
        Ok(ar.free_symbols(&entries).iter().any(|s| {
            let info = ar.symbol_info(*s);
            matches!(info.kind, crate::expr::SymbolKind::Variable { order } if order >= 1) && info.base != *s
        }))
    }

    /// `frame`, its parent, grandparent, ... up to the root of its tree.
    fn ancestors(&self, frame: FrameId) -> Vec<FrameId> {
        let mut chain = vec![frame];
        let mut f = frame;
        while let Some(p) = self.frames[f.index()].parent {
            chain.push(p);
            f = p;
        }
        chain
    }

    /// The chains from `a` and from `b` up to their lowest common ancestor (included in both).
    fn paths_to_common(&self, a: FrameId, b: FrameId) -> Result<(Vec<FrameId>, Vec<FrameId>)> {
        let up_a = self.ancestors(a);
        let up_b = self.ancestors(b);
        let Some(pos_b) = up_b.iter().position(|f| up_a.contains(f)) else {
            return Err(MechanicsError::NoOrientationPath {
                a: self.frame_name(a).to_string(),
                b: self.frame_name(b).to_string(),
            });
        };
        let common = up_b[pos_b];
        let pos_a = up_a.iter().position(|f| *f == common).unwrap_or(0);
        Ok((up_a[..=pos_a].to_vec(), up_b[..=pos_b].to_vec()))
    }

    /// Direction cosines `a_i . b_j` between any two connected frames (cached).
    pub fn dcm(&mut self, a: FrameId, b: FrameId) -> Result<Mat3> {
        if a == b {
            let (z, o) = (self.ar.zero(), self.ar.one());
            return Ok([[o, z, z], [z, o, z], [z, z, o]]);
        }
        if let Some(m) = self.dcm_cache.get(&(a, b)) {
            return Ok(*m);
        }
        if let Some(m) = self.dcm_cache.get(&(b, a)) {
            return Ok(transpose(m));
        }
        let m = if self.frames[b.index()].parent == Some(a) {
            self.dcm_from_parent(b)?
        } else if self.frames[a.index()].parent == Some(b) {
            transpose(&self.dcm_from_parent(a)?)
        } else {
            // a_i . b_j through the lowest common ancestor L: (a . L)(L . b), each along a chain.
            let (up_a, up_b) = self.paths_to_common(a, b)?;
            let common = *up_a.last().unwrap_or(&a);
            if let (Some((ax_a, angle_a)), Some((ax_b, angle_b))) =
                (self.single_axis_chain(&up_a)?, self.single_axis_chain(&up_b)?)
            {
                if ax_a == ax_b {
                    // Both hang from L by rotations about one axis: a . b is one rotation.
                    let angle = self.ar.sub(angle_b, angle_a)?;
                    let m = self.axis_rotation(ax_a, angle)?;
                    self.dcm_cache.insert((a, b), m);
                    return Ok(m);
                }
            }
            let down = self.chain_dcm(&up_b)?;
            let up = self.chain_dcm(&up_a)?;
            let a_l = transpose(&up);
            if a == common {
                down
            } else if b == common {
                a_l
            } else {
                self.mat_mul(&a_l, &down)?
            }
        };
        self.dcm_cache.insert((a, b), m);
        Ok(m)
    }

    /// `L . x` for the chain `x, parent(x), ..., L`. Consecutive rotations about the same axis
    /// are one rotation by the sum of their angles, so a chain of relative angles gives
    /// `cos(q1 + q2)`, not the products of every angle's sine and cosine.
    fn chain_dcm(&mut self, chain: &[FrameId]) -> Result<Mat3> {
        let mut m = self.dcm(chain[chain.len() - 1], chain[chain.len() - 1])?;
        let mut run: Option<(u8, Vec<ExprId>)> = None;
        for w in chain.windows(2).rev() {
            let simple = match &self.frames[w[0].index()].orientation {
                Some(Orientation::Axis { axis, angle }) if self.frames[w[0].index()].parent == Some(w[1]) => {
                    Some((*axis, *angle))
                }
                _ => None,
            };
            match (simple, &mut run) {
                (Some((axis, angle)), Some((run_axis, angles))) if axis.unsigned_abs() == *run_axis => {
                    angles.push(if axis < 0 { self.ar.neg(angle)? } else { angle });
                }
                (Some((axis, angle)), _) => {
                    m = self.apply_run(&m, run.take())?;
                    let angle = if axis < 0 { self.ar.neg(angle)? } else { angle };
                    run = Some((axis.unsigned_abs(), vec![angle]));
                }
                (None, _) => {
                    m = self.apply_run(&m, run.take())?;
                    let step = self.dcm(w[1], w[0])?;
                    m = self.mat_mul(&m, &step)?;
                }
            }
        }
        self.apply_run(&m, run)
    }

    /// The axis and total angle of the chain `x, parent(x), ..., L` when every step is a simple
    /// rotation about that one axis (a chain of one frame turns by 0 about any axis: `None`).
    fn single_axis_chain(&mut self, chain: &[FrameId]) -> Result<Option<(u8, ExprId)>> {
        let mut axis_seen = None;
        let mut angles = Vec::with_capacity(chain.len());
        for w in chain.windows(2) {
            let frame = &self.frames[w[0].index()];
            let Some(Orientation::Axis { axis, angle }) = frame.orientation.clone() else { return Ok(None) };
            if frame.parent != Some(w[1]) || axis_seen.is_some_and(|a| a != axis.unsigned_abs()) {
                return Ok(None);
            }
            axis_seen = Some(axis.unsigned_abs());
            angles.push(if axis < 0 { self.ar.neg(angle)? } else { angle });
        }
        match axis_seen {
            Some(axis) => Ok(Some((axis, self.ar.add(&angles)?))),
            None => Ok(None),
        }
    }

    /// `m` times the rotation about `axis` by the sum of `angles` (`m` itself when `None`).
    fn apply_run(&mut self, m: &Mat3, run: Option<(u8, Vec<ExprId>)>) -> Result<Mat3> {
        let Some((axis, angles)) = run else { return Ok(*m) };
        let angle = self.ar.add(&angles)?;
        let step = self.axis_rotation(axis, angle)?;
        self.mat_mul(m, &step)
    }

    fn mat_mul(&mut self, a: &Mat3, b: &Mat3) -> Result<Mat3> {
        let z = self.ar.zero();
        let mut out = [[z; 3]; 3];
        for (i, row) in out.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                let mut terms = Vec::with_capacity(3);
                for k in 0..3 {
                    terms.push(self.ar.mul(&[a[i][k], b[k][j]])?);
                }
                *cell = self.ar.add(&terms)?;
            }
        }
        Ok(out)
    }

    /// `parent_i . frame_j` from the frame's orientation.
    fn dcm_from_parent(&mut self, frame: FrameId) -> Result<Mat3> {
        let Some(orientation) = self.frames[frame.index()].orientation.clone() else {
            return Err(MechanicsError::NoOrientationPath {
                a: self.frame_name(frame).to_string(),
                b: self.frame_name(self.newtonian).to_string(),
            });
        };
        self.orientation_dcm(&orientation)
    }

    /// `parent_i . child_j` of an orientation.
    fn orientation_dcm(&mut self, orientation: &Orientation) -> Result<Mat3> {
        Ok(match *orientation {
            Orientation::Axis { axis, angle } => {
                let angle = if axis < 0 { self.ar.neg(angle)? } else { angle };
                self.axis_rotation(axis.unsigned_abs(), angle)?
            }
            Orientation::BodyFixed { axes, angles } => {
                let r0 = self.axis_rotation(axes[0], angles[0])?;
                let r1 = self.axis_rotation(axes[1], angles[1])?;
                let r2 = self.axis_rotation(axes[2], angles[2])?;
                let m = self.mat_mul(&r0, &r1)?;
                self.mat_mul(&m, &r2)?
            }
            Orientation::SpaceFixed { axes, angles } => {
                let r0 = self.axis_rotation(axes[0], angles[0])?;
                let r1 = self.axis_rotation(axes[1], angles[1])?;
                let r2 = self.axis_rotation(axes[2], angles[2])?;
                let m = self.mat_mul(&r2, &r1)?;
                self.mat_mul(&m, &r0)?
            }
            Orientation::EulerParameters(e) => self.quaternion_dcm(e)?,
            Orientation::Rodrigues(g) => {
                // Euler parameters (1, g) / |(1, g)|: the quadratic form over |(1, g)|^2.
                let one = self.ar.one();
                let m = self.quaternion_dcm([one, g[0], g[1], g[2]])?;
                let mut norm = vec![one];
                for x in g {
                    norm.push(self.ar.powi(x, 2)?);
                }
                let norm = self.ar.add(&norm)?;
                let inv = self.ar.powi(norm, -1)?;
                let mut out = m;
                for x in out.iter_mut().flatten() {
                    *x = self.ar.mul(&[*x, inv])?;
                }
                out
            }
            Orientation::Dcm(m) => m,
        })
    }

    /// `parent_i . child_j` for a rotation by `angle` about the shared axis `axis` (1, 2, 3).
    fn axis_rotation(&mut self, axis: u8, angle: ExprId) -> Result<Mat3> {
        let c = self.ar.cos(angle)?;
        let s = self.ar.sin(angle)?;
        let ms = self.ar.neg(s)?;
        let (z, o) = (self.ar.zero(), self.ar.one());
        Ok(match axis {
            1 => [[o, z, z], [z, c, ms], [z, s, c]],
            2 => [[c, z, s], [z, o, z], [ms, z, c]],
            _ => [[c, ms, z], [s, c, z], [z, z, o]],
        })
    }

    fn quaternion_dcm(&mut self, e: [ExprId; 4]) -> Result<Mat3> {
        let ar = &mut self.ar;
        let sq: Vec<ExprId> = e.iter().map(|x| ar.powi(*x, 2)).collect::<std::result::Result<_, _>>()?;
        let two = ar.integer(2);
        let mut prod = |i: usize, j: usize, k: usize, l: usize, sign: bool| -> Result<ExprId> {
            let p = ar.mul(&[e[i], e[j]])?;
            let q = ar.mul(&[e[k], e[l]])?;
            let s = if sign { ar.add(&[p, q])? } else { ar.sub(p, q)? };
            Ok(ar.mul(&[two, s])?)
        };
        let m01 = prod(1, 2, 0, 3, false)?;
        let m02 = prod(1, 3, 0, 2, true)?;
        let m10 = prod(1, 2, 0, 3, true)?;
        let m12 = prod(2, 3, 0, 1, false)?;
        let m20 = prod(1, 3, 0, 2, false)?;
        let m21 = prod(2, 3, 0, 1, true)?;
        let diag = |ar: &mut crate::expr::Arena, plus: [usize; 2], minus: [usize; 2]| -> Result<ExprId> {
            let p = ar.add(&[sq[plus[0]], sq[plus[1]]])?;
            let m = ar.add(&[sq[minus[0]], sq[minus[1]]])?;
            Ok(ar.sub(p, m)?)
        };
        let m00 = diag(&mut self.ar, [0, 1], [2, 3])?;
        let m11 = diag(&mut self.ar, [0, 2], [1, 3])?;
        let m22 = diag(&mut self.ar, [0, 3], [1, 2])?;
        Ok([[m00, m01, m02], [m10, m11, m12], [m20, m21, m22]])
    }

    /// Angular velocity of `frame` relative to its parent.
    fn ang_vel_in_parent(&mut self, frame: FrameId) -> Result<Vector> {
        if let Some(w) = self.frames[frame.index()].ang_vel.clone() {
            return Ok(w);
        }
        self.orientation_angular_velocity(frame)
    }

    /// The angular velocity of `frame` in its parent implied by its orientation's rates (even
    /// where an angular velocity is set explicitly); zero for a frame with no orientation.
    pub fn orientation_angular_velocity(&mut self, frame: FrameId) -> Result<Vector> {
        match self.frames[frame.index()].orientation.clone() {
            Some(o) => self.orientation_rates(&o, frame),
            None => Ok(Vector::zero()),
        }
    }

    /// The angular velocity, in `frame`'s unit vectors, of a frame oriented by `orientation`
    /// relative to its parent as its angles change (ANGVEL with a rotation sequence).
    pub fn orientation_rates(&mut self, orientation: &Orientation, frame: FrameId) -> Result<Vector> {
        match orientation.clone() {
            Orientation::Axis { axis, angle } => {
                let rate = self.dt(angle)?;
                let rate = if axis < 0 { self.ar.neg(rate)? } else { rate };
                let z = self.ar.zero();
                let mut m = [z; 3];
                m[usize::from(axis.unsigned_abs()) - 1] = rate;
                // The rotation axis has the same measure numbers in parent and child.
                Ok(Vector::new(frame, m))
            }
            other => {
                // Child-frame components from the skew matrix C^T dC/dt, C = parent . child.
                let c = self.orientation_dcm(&other)?;
                let mut cdot = c;
                for row in cdot.iter_mut() {
                    for x in row.iter_mut() {
                        *x = self.dt(*x)?;
                    }
                }
                let mut w = [self.ar.zero(); 3];
                for (slot, (k, j)) in w.iter_mut().zip([(2, 1), (0, 2), (1, 0)]) {
                    let mut terms = Vec::with_capacity(3);
                    for i in 0..3 {
                        terms.push(self.ar.mul(&[c[i][k], cdot[i][j]])?);
                    }
                    let sum = self.ar.add(&terms)?;
                    *slot = self.ar.trig_simplify(sum)?;
                }
                Ok(Vector::new(frame, w))
            }
        }
    }

    /// Angular velocity of frame `b` in frame `a` (Autolev `W_B_A>`).
    pub fn angular_velocity(&mut self, b: FrameId, a: FrameId) -> Result<Vector> {
        if let Some(w) = self.ang_vel_cache.get(&(b, a)) {
            return Ok(w.clone());
        }
        let w = self.along_tree(b, a, Model::ang_vel_in_parent)?;
        self.ang_vel_cache.insert((b, a), w.clone());
        Ok(w)
    }

    /// The sum of `rel(f)` (a frame's angular velocity in its parent) over the frames from `b`
    /// up to the frame it shares with `a`, less the same from `a`: `b`'s in `a`.
    fn along_tree(
        &mut self,
        b: FrameId,
        a: FrameId,
        rel: fn(&mut Model, FrameId) -> Result<Vector>,
    ) -> Result<Vector> {
        let (up_b, up_a) = self.paths_to_common(b, a)?;
        let mut w = Vector::zero();
        for &f in &up_b[..up_b.len() - 1] {
            let r = rel(self, f)?;
            w = self.add_vectors(&w, &r)?;
        }
        for &f in &up_a[..up_a.len() - 1] {
            let r = rel(self, f)?;
            w = self.sub_vectors(&w, &r)?;
        }
        Ok(w)
    }

    /// Angular acceleration of frame `b` in frame `a` (Autolev `ALF_B_A>`).
    pub fn angular_acceleration(&mut self, b: FrameId, a: FrameId) -> Result<Vector> {
        let w = self.angular_velocity(b, a)?;
        self.dt_in(&w, a)
    }
}

/// Which of two frames related by [`Model::orient`] is the child in the tree.
enum Link {
    /// The frame named first.
    Child,
    /// The frame named second (the relation runs the other way round).
    Parent,
}

fn transpose(m: &Mat3) -> Mat3 {
    [[m[0][0], m[1][0], m[2][0]], [m[0][1], m[1][1], m[2][1]], [m[0][2], m[1][2], m[2][2]]]
}
