//! The lowered program: in come the equations and outputs of a spec (through
//! [`super::lower`]); out goes a [`Program`], straight-line SSA sections of elementary operations
//! ([`Op`]: each section is a [`Tape`] of this module's [`Input`]s, the program type the
//! interpreted paths run too) that every consumer reads: the Rust printer, operation counts,
//! events and Taylor coefficients.

use crate::expr::{Tape, TapeBuilder};
use crate::runtime::OpCounts;

pub use crate::expr::Op;

/// A value a section reads from outside.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Input {
    /// Time.
    Time,
    /// State `i` (coordinates, then speeds).
    State(usize),
    /// Parameter `i`.
    Param(usize),
    /// Parameter-only quantity `i`, computed by the `param_constants` section.
    ParamConstant(usize),
    /// The speed rate `u'_i`, computed by the `rhs` section.
    Rate(usize),
    /// Positional value `i` the caller gives (an event expression's names: see
    /// [`super::event`]); model sections never read one.
    Slot(usize),
}

/// One straight-line section of the lowered program: a tape reading [`Input`]s.
pub type Section = Tape<Input>;

/// Builds a section (a tape of [`Input`]s), each instruction emitted once.
pub type SectionBuilder = TapeBuilder<Input>;

/// One output's section and what the driver needs to know about it.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputCode {
    /// Its instructions; results are its components.
    pub section: Section,
    /// The states its value depends on (coordinates that cancel are left out).
    pub reads: Vec<usize>,
    /// Whether it reads the speed rates `u'` (then the driver evaluates `rhs` first).
    pub needs_rates: bool,
}

/// The lowered program of one model.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Parameter-only quantities, in `f64`, once per parameter set; inputs are parameters.
    pub param_constants: Section,
    /// `y' = f(t, y)`: results are `q'` then `u'`.
    pub rhs: Section,
    /// One section per output.
    pub outputs: Vec<OutputCode>,
    /// Coordinates no equation reads (cyclic).
    pub cyclic: Vec<usize>,
    /// Number of coordinates.
    pub n_coordinates: usize,
}

impl Program {
    /// Operations per `rhs` call and per evaluation of all outputs.
    pub fn op_counts(&self) -> OpCounts {
        OpCounts {
            rhs: self.rhs.op_count(),
            outputs: self.outputs.iter().map(|o| o.section.op_count()).sum(),
        }
    }
}
