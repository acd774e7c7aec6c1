//! The models a simulator knows: in come generated models (the built-in ones in `builtin`, a
//! user's crate's through [`Registry::with`]) and model files (`model_file`: checked, lowered,
//! with what the file says about a run); out goes a [`Registry`] finding each by name as a
//! [`crate::problem::ModelEntry`] with the solver instantiated for it. A model file runs on the
//! JIT engine (`jit`: its lowered program compiled to machine code in process), the instant
//! engine (`instant`: the program evaluated) or the compiled one (`compiled`: a cached binary
//! with the model compiled in, whose generated driver names only `gyro_sim::` re-exports).

use kane_model::codegen::jit::JitError;

mod builtin;
mod compiled;
mod instant;
mod jit;
mod model_file;
mod registry;

pub use builtin::{gimbal_gyroscope, heavy_top};
pub use compiled::{cache_dir, content_hash, ensure_binary, not_a_program, registry_key, CompileError};
pub use instant::{file_entry, InstantSystem};
pub use jit::{jit_file_entry, JitSystem};
pub use model_file::{source_with, FileRun, ModelFile, ModelFileError};
pub use registry::Registry;

/// The entry running `file` in this process: on the JIT engine when `jit`, else on the instant
/// engine.
pub fn in_process_entry(file: &ModelFile, jit: bool) -> Result<crate::problem::ModelEntry, JitError> {
    match jit {
        true => jit_file_entry(file),
        false => Ok(file_entry(file)),
    }
}
