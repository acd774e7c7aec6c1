//! The models a simulator knows: in come generated models (the built-in ones in `builtin`, a
//! user's crate's through [`Registry::with`]) and model files (`model_file`: checked, lowered,
//! with what the file says about a run); out goes a [`Registry`] finding each by name as a
//! [`crate::problem::ModelEntry`] with the solver instantiated for it. A model file runs on the
//! instant engine (`instant`: its lowered program evaluated) or the compiled one (`compiled`: a
//! cached binary with the model compiled in, whose generated driver names only `gyro_sim::`
//! re-exports).

mod builtin;
mod compiled;
mod instant;
mod model_file;
mod registry;

pub use builtin::{gimbal_gyroscope, heavy_top};
pub use compiled::{cache_dir, content_hash, ensure_binary, not_a_program, registry_key, CompileError};
pub use instant::file_entry;
pub use model_file::{source_with, FileRun, ModelFile, ModelFileError};
pub use registry::Registry;
