//! The models a simulator knows: in come generated models (the built-in ones in `builtin`, a
//! user's crate's through [`Registry::with`]) and model files (`model_file`: checked, lowered,
//! with what the file says about a run); out goes a [`Registry`] finding each by name as a
//! [`crate::problem::SharedModel`], one implementation of it per engine. A model file runs on the
//! JIT engine (`jit`: its lowered program compiled to machine code in process), the instant
//! engine (`instant`: the program evaluated) or the compiled one (`compiled`: a cached binary
//! with the model compiled in, whose generated driver names only `gyro_sim::` re-exports).

use kane_model::jit::JitError;

mod builtin;
mod compiled;
mod generated;
mod instant;
mod jit;
mod model_file;
mod registry;

pub use builtin::{gimbal_gyroscope, heavy_top};
pub use compiled::{cache_dir, content_hash, ensure_binary, not_a_program, registry_key, CompileError};
pub use generated::generated;
pub use instant::{instant_file_model, InstantSystem};
pub use jit::{jit_file_model, JitSystem};
pub use model_file::{source_with, FileRun, ModelFile, ModelFileError};
pub use registry::Registry;

/// The model file `file` run in this process: on the JIT engine when `jit`, else on the
/// instant engine.
pub fn in_process_model(file: &ModelFile, jit: bool) -> Result<crate::problem::SharedModel, JitError> {
    match jit {
        true => jit_file_model(file),
        false => Ok(instant_file_model(file)),
    }
}
