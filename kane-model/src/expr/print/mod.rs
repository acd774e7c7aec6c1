//! Printers: plain text, LaTeX and Rust tokens, sharing one layout.

mod latex;
mod layout;
mod rust;
mod text;

pub use rust::{RustStyle, Scalar};
