//! Vectors as measure numbers along the unit vectors of one or more frames.

use crate::expr::ExprId;

use super::ids::FrameId;

/// A vector: a sum of terms, each three measure numbers along one frame's unit vectors.
///
/// Terms stay in the frame they were written in; conversion happens only when an operation
/// needs two frames to meet (dot, cross, express).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vector {
    pub(crate) terms: Vec<(FrameId, [ExprId; 3])>,
}

impl Vector {
    /// The zero vector.
    pub fn zero() -> Vector {
        Vector::default()
    }

    /// The vector with measure numbers `m` in `frame`.
    pub fn new(frame: FrameId, m: [ExprId; 3]) -> Vector {
        Vector { terms: vec![(frame, m)] }
    }

    /// The terms: each frame with its measure numbers.
    pub fn terms(&self) -> &[(FrameId, [ExprId; 3])] {
        &self.terms
    }

    /// True when the vector has no terms (it may still be zero with terms whose numbers are 0).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }
}

/// A dyadic: terms `frame_a, frame_b, M` meaning `sum_ij M[i][j] a_i b_j`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dyadic {
    pub(crate) terms: Vec<(FrameId, FrameId, [[ExprId; 3]; 3])>,
}

impl Dyadic {
    /// The zero dyadic.
    pub fn zero() -> Dyadic {
        Dyadic::default()
    }

    /// `sum_ij m[i][j] f_i f_j`.
    pub fn in_frame(frame: FrameId, m: [[ExprId; 3]; 3]) -> Dyadic {
        Dyadic { terms: vec![(frame, frame, m)] }
    }

    /// The transpose: `sum_ij m[i][j] b_j a_i` for each term `m[i][j] a_i b_j`.
    pub fn transpose(&self) -> Dyadic {
        let flip = |m: &[[ExprId; 3]; 3]| std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]));
        Dyadic { terms: self.terms.iter().map(|(a, b, m)| (*b, *a, flip(m))).collect() }
    }

    /// The terms.
    pub fn terms(&self) -> &[(FrameId, FrameId, [[ExprId; 3]; 3])] {
        &self.terms
    }
}
