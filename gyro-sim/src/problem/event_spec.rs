//! Events ready to watch: what resolving a scene's `[[events]]` gives the problem. Each is its
//! expression lowered to a kane-model IR section, where each of the section's inputs is read from
//! (time, states, output columns and their rates, parameters), and the crossings that count.

use kane_model::program::event::EventCode;

use crate::scene::Direction;

/// What is watched of one event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rule {
    /// The crossings that count.
    pub direction: Direction,
    /// The run ends at this crossing (counted from one), if any.
    pub stop_after: Option<usize>,
}

/// Where an event section's positional input comes from (values in the CSV's units: angles the
/// model gives in degrees scaled to degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    /// The time `t`.
    Time,
    /// State `i` times `scale`.
    State(usize, f64),
    /// The rate of state `i` times `scale`.
    StateRate(usize, f64),
    /// Column `col` of output `k` times `scale`.
    Column(usize, usize, f64),
    /// The rate of column `col` of output `k` times `scale`.
    ColumnRate(usize, usize, f64),
    /// Parameter `i` times `scale`.
    Param(usize, f64),
}

/// An event ready to evaluate.
#[derive(Clone, Debug, PartialEq)]
pub struct EventSpec {
    /// Its name.
    pub name: String,
    /// The lowered expression.
    pub code: EventCode,
    /// What each of its inputs reads.
    pub sources: Vec<Source>,
    /// The crossings watched and when the run ends.
    pub rule: Rule,
    /// The states its value depends on (directly or through outputs).
    pub reads: Vec<usize>,
}
