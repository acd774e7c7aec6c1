//! Events watched during an integration: times where an expression of the states, output
//! columns, parameters and `t` crosses zero, found on the integrator's dense output after each
//! accepted step.
//!
//! In come the problem's events ([`crate::problem::EventSpec`], each lowered into a kane-model IR
//! section when the scene was resolved); out go the crossings, in the trajectory's
//! [`crate::problem::EventLog`]. `eval` runs the sections; `detect` finds the crossings, every
//! sign change inside a step isolated by `isolate` and located by `root`; `watch` does both after
//! each step of an integration, `limits` noting where crossings outran the steps or the rows.

mod detect;
mod eval;
mod isolate;
mod limits;
mod root;
mod watch;

pub(crate) use watch::Watch;
