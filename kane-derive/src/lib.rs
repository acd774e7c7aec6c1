//! Procedural macros that expand model files into Rust modules (see issue: code generation).
//!
//! This crate stays a thin shell over `kane-model`; the `model!` macro is not implemented yet.
