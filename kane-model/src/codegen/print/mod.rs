//! Printing: in come a spec and its lowered program; out go Rust tokens (via `quote`), formatted
//! source with `prettyplease`. The generated runtime path lives here and nowhere else.

mod metadata;
mod module;
mod outputs;
mod section;
mod taylor;
mod unrolled;

pub use module::{module, Extras};
pub use section::{print as print_section, Scalar, SectionStyle};
