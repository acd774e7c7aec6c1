//! Printers: plain text and LaTeX, sharing one layout with code generation's lowering.

mod collected;
mod latex;
pub(crate) mod layout;
mod named;
mod text;

pub use named::Intermediates;
