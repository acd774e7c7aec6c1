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
    /// `V_P_N> = ...`, V2PTS, V1PT.
    pub(crate) velocities: FxHashMap<(PointId, FrameId), Span>,
    /// V2PTS(N, B, P, Q): Q's velocity in N carried from P, by `(Q, N)`.
    pub(crate) carried_from: FxHashMap<(PointId, FrameId), PointId>,
    /// `A_P_N> = ...`, A2PTS, A1PT.
    pub(crate) accelerations: FxHashMap<(PointId, FrameId), Span>,
    /// `W_B_A> = ...`, by the frame B.
    pub(crate) angular_velocities: FxHashMap<FrameId, Span>,
    /// SIMPROT, DIRCOS, `A_B = [...]`, by the oriented frame.
    pub(crate) orientations: FxHashMap<FrameId, Span>,
    /// MASS items and INERTIA statements, by upper-cased body or particle name.
    pub(crate) inertial: FxHashMap<String, Span>,
    /// Every load given, in order: `FORCE_P>` / `TORQUE_B>` and where (assignments, and the
    /// FORCE and TORQUE commands).
    pub(crate) loads: Vec<LoadSource>,
    /// Constants MASS and INERTIA declared by using them (`MASS A = MA`), with where.
    pub(crate) implicit_constants: Vec<(String, Span)>,
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
    /// Records the statement relating points `a` and `b`.
    pub(crate) fn position(&mut self, a: PointId, b: PointId, span: &Span) {
        self.positions.insert(pair(a, b), span.clone());
    }

    /// The statement relating points `a` and `b`, if one did.
    pub(crate) fn position_of(&self, a: PointId, b: PointId) -> Option<&Span> {
        self.positions.get(&pair(a, b))
    }
}

fn pair(a: PointId, b: PointId) -> (PointId, PointId) {
    if a.index() <= b.index() {
        (a, b)
    } else {
        (b, a)
    }
}
