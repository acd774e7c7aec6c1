//! The symbolic expression engine.
//!
//! Expressions live in an [`Arena`] and are referred to by [`ExprId`]. Nodes are hash-consed,
//! so structurally equal expressions share one id and the whole set of expressions is a DAG.
//! Canonical form is decided at construction ([`Arena::add`], [`Arena::mul`], [`Arena::pow`],
//! [`Arena::func`]); transformations (derivatives, substitution, expansion, trigonometric
//! simplification) walk the DAG bottom-up and never recurse, so deep expressions are safe.

mod abbrev;
mod angles;
mod arena;
mod canonical;
mod collect;
mod cse;
mod diff;
mod equiv;
mod error;
mod estimate;
mod eval;
mod expand;
mod linear;
mod node;
mod number;
mod print;
mod tape;
mod tidy;
mod traverse;

pub use abbrev::Abbreviations;
pub use arena::{Arena, Symbol, TIME};
pub use cse::{Cse, StraightLine};
pub use diff::TimeDerivative;
pub use equiv::{Equivalence, EquivalenceConfig, SampleAround};
pub use error::ExprError;
pub use expand::TrigBasis;
pub(crate) use expand::MAX_EXPANDED_TERMS;
pub use node::{ExprId, Func, Node, SymbolId, SymbolKind};
pub use number::{Number, Rational};
pub use print::Intermediates;
pub(crate) use tape::Compiler;
pub use tape::{Op, Tape, TapeBuilder};
pub use tidy::{Collected, CollectedTerm};
