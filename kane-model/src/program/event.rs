//! Event expressions lowered: in comes a scalar expression in an arena (an event's text read by
//! the model language, its derivatives taken there) and the slot each of its symbols reads;
//! out goes an [`EventCode`], a straight-line [`Section`] whose inputs are positional slots
//! ([`Input::Slot`]) the caller fills with the values and rates [`EventCode::slots`] lists, so
//! nothing symbolic is evaluated when the section runs.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, Compiler, ExprId, SymbolId, TIME};

use super::ir::{Input, Section};

/// What one input slot of an event section holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventSlot {
    /// Time.
    Time,
    /// The value of name `i` (an index into the names given).
    Value(usize),
    /// The time derivative of name `i`.
    Rate(usize),
}

/// A lowered event expression.
#[derive(Clone, Debug, PartialEq)]
pub struct EventCode {
    /// One result, the expression; `Input::Slot(k)` reads `slots[k]`.
    pub section: Section,
    /// What each slot holds.
    pub slots: Vec<EventSlot>,
}

/// The code of `root` in `ar`: time reads a time slot, and each other symbol the slot `reads`
/// gives it (one slot per symbol read, in the order [`Arena::free_symbols`] lists them).
pub fn lower(ar: &Arena, root: ExprId, reads: impl Fn(SymbolId) -> Option<EventSlot>) -> EventCode {
    let mut slots = Vec::new();
    let mut inputs: FxHashMap<SymbolId, Input> = FxHashMap::default();
    for s in ar.free_symbols(&[root]) {
        let slot = if s == TIME {
            EventSlot::Time
        } else {
            match reads(s) {
                Some(slot) => slot,
                None => continue,
            }
        };
        inputs.insert(s, Input::Slot(slots.len()));
        slots.push(slot);
    }
    let mut lowering = Compiler::new(ar, |s| inputs.get(&s).copied(), None);
    let values = lowering.lower_all(&[root]);
    EventCode { section: lowering.builder.finish(values), slots }
}
