//! Typed indices of frames, points, bodies and particles, and the 3x3 matrix of expressions.
//!
//! In: nothing but [`crate::expr::ExprId`]. Out: the small copyable ids every other mechanics
//! file names things by; this file depends on no other part of the mechanics layer.

use crate::expr::ExprId;

macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
        pub struct $name(pub(crate) u32);

        impl $name {
            /// Position in the model's list.
            pub fn index(self) -> usize {
                self.0 as usize
            }
        }
    };
}

id_type!(
    /// A reference frame.
    FrameId
);
id_type!(
    /// A point.
    PointId
);
id_type!(
    /// A rigid body.
    BodyId
);
id_type!(
    /// A particle.
    ParticleId
);

/// A 3x3 matrix of expressions.
pub type Mat3 = [[ExprId; 3]; 3];
