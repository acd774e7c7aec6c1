//! Printers: plain text and LaTeX, sharing one layout with code generation's lowering.

mod latex;
pub(crate) mod layout;
mod text;
