//! Where the kinematics came from: the span of the statement that set each position, velocity,
//! acceleration, angular velocity, orientation, mass and inertia, for checks that name lines.
//!
//! In: the interpreter's record calls as statements run. Out: spans looked up by the entities
//! they set (the newest statement wins, as it does in the model).

use rustc_hash::FxHashMap;

use crate::mechanics::{FrameId, PointId};

use super::super::token::Span;

/// Spans of the statements that set the model's kinematic and inertial data.
#[derive(Clone, Debug, Default)]
pub(crate) struct Sources {
    /// `P_A_B> = ...`, by the unordered pair of points.
    pub(crate) positions: FxHashMap<(PointId, PointId), Span>,
    /// `V_P_N> = ...`, V2PTS, V1PT, by the point and frame.
    pub(crate) velocities: FxHashMap<(PointId, FrameId), KinematicSource>,
    /// `A_P_N> = ...`, A2PTS, A1PT, by the point and frame.
    pub(crate) accelerations: FxHashMap<(PointId, FrameId), KinematicSource>,
    /// `W_B_A> = ...`, by the frame B.
    pub(crate) angular_velocities: FxHashMap<FrameId, Span>,
    /// SIMPROT, DIRCOS, `A_B = [...]`, by the unordered pair of frames.
    pub(crate) orientations: FxHashMap<(FrameId, FrameId), Span>,
    /// MASS items and INERTIA statements, by upper-cased body or particle name.
    pub(crate) inertial: FxHashMap<String, Span>,
    /// Every load given, in order: `FORCE_P>` / `TORQUE_B>` and where (assignments, and the
    /// FORCE and TORQUE commands).
    pub(crate) loads: Vec<LoadSource>,
    /// Constants MASS and INERTIA declared by using them (`MASS A = MA`), with where.
    pub(crate) implicit_constants: Vec<(String, Span)>,
    /// Every statement run, in the order run.
    pub(crate) executed: Vec<Span>,
    /// `executed` as (start, end, place in the run), by start: made once the run is over.
    by_start: std::cell::OnceCell<Vec<(usize, usize, usize)>>,
}

/// The statement that set a point's velocity or acceleration in a frame, and what it took.
#[derive(Clone, Debug)]
pub(crate) struct KinematicSource {
    /// Where the statement is.
    pub(crate) span: Span,
    /// For V2PTS, V1PT, A2PTS and A1PT: the body frame and the point carried from.
    pub(crate) theorem: Option<(Theorem, FrameId, PointId)>,
    /// For an assignment: the points whose velocities or accelerations its value read.
    pub(crate) reads: Vec<PointId>,
}

/// The velocity and acceleration theorems.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Theorem {
    /// V2PTS and A2PTS: the point of the body at the point named.
    TwoPoints,
    /// V1PT and A1PT: a point moving on the body.
    OnePoint,
}

impl KinematicSource {
    /// The points this setting took a velocity or acceleration from.
    pub(crate) fn bases(&self) -> impl Iterator<Item = PointId> + '_ {
        self.theorem.iter().map(|(_, _, from)| *from).chain(self.reads.iter().copied())
    }
}

/// One statement adding to a load.
#[derive(Clone, Debug)]
pub(crate) struct LoadSource {
    /// The load, as an assignment names it: `FORCE_P>` or `TORQUE_B>`.
    pub(crate) name: String,
    /// Where the statement is in the file.
    pub(crate) span: Span,
    /// An assignment (`TORQUE_B> = ...`), not a FORCE or TORQUE command.
    pub(crate) assigned: bool,
}

impl Sources {
    /// The place in the run of the statement at byte `offset`: a file's RUN statement runs the
    /// other file's statements there, although their text follows the file's.
    pub(crate) fn rank(&self, offset: usize) -> usize {
        let sorted = self.by_start.get_or_init(|| {
            let mut v: Vec<(usize, usize, usize)> =
                self.executed.iter().enumerate().map(|(k, s)| (s.start, s.end.max(s.start + 1), k)).collect();
            v.sort_unstable();
            v
        });
        let at = sorted.partition_point(|(start, _, _)| *start <= offset);
        match at.checked_sub(1).map(|k| sorted[k]) {
            Some((_, end, k)) if offset < end => k,
            _ => usize::MAX,
        }
    }

    /// Records the statement relating points `a` and `b`.
    pub(crate) fn position(&mut self, a: PointId, b: PointId, span: &Span) {
        self.positions.insert(pair(a, b), span.clone());
    }

    /// The statement relating points `a` and `b`, if one did.
    pub(crate) fn position_of(&self, a: PointId, b: PointId) -> Option<&Span> {
        self.positions.get(&pair(a, b))
    }
}

impl Sources {
    /// Records the statement relating frames `a` and `b` by an orientation.
    pub(crate) fn orientation(&mut self, a: FrameId, b: FrameId, span: &Span) {
        self.orientations.insert(frame_pair(a, b), span.clone());
    }

    /// The statement that oriented `frame` in the tree of orientations (relative to its parent
    /// there, either frame named first), if one did.
    pub(crate) fn orientation_of(&self, model: &crate::mechanics::Model, frame: FrameId) -> Option<&Span> {
        let parent = model.frame_parent(frame)?;
        self.orientations.get(&frame_pair(frame, parent))
    }
}

fn frame_pair(a: FrameId, b: FrameId) -> (FrameId, FrameId) {
    if a.index() <= b.index() {
        (a, b)
    } else {
        (b, a)
    }
}

fn pair(a: PointId, b: PointId) -> (PointId, PointId) {
    if a.index() <= b.index() {
        (a, b)
    } else {
        (b, a)
    }
}
