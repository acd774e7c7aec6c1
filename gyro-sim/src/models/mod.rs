//! Models by name.

mod builtin;
mod compiled;
mod instant;
mod model_file;
mod registry;

pub use builtin::{gimbal_gyroscope, heavy_top};
pub use compiled::{cache_dir, content_hash, ensure_binary, not_a_program, registry_key};
pub use instant::file_entry;
pub use model_file::{source_with, FileRun, ModelFile};
pub use registry::{MechanicsSource, ModelEntry, ProgramSource, Registry};
