//! The model file a scene names: in comes a scene; out go the path of the model file its
//! `model` key names (relative to the scene), and a registry with that file's model on the
//! JIT engine, for the commands that run a scene's members or controls (sweep, serve).

use std::path::{Path, PathBuf};

use super::CliError;
use crate::models::{ModelFile, Registry};
use crate::scene::Scene;

/// `registry` with the model file `scene` names, if it names one, on the JIT engine.
pub(super) fn with_file_model(scene: &Scene, registry: Registry) -> Result<Registry, CliError> {
    let Some(path) = model_file_of(scene) else { return Ok(registry) };
    let source = crate::models::source_with(&path, &scene.specified)?;
    let file = ModelFile::from_source(&path, source, scene.draws_model())?;
    eprint!("{}", file.warnings);
    Ok(registry.with_entry(&scene.model, crate::models::jit_file_entry(&file)?))
}

/// The model file a scene names (`model = "file.al"`, relative to the scene), if it does.
pub(super) fn model_file_of(scene: &Scene) -> Option<PathBuf> {
    if !scene.model.to_ascii_lowercase().ends_with(".al") {
        return None;
    }
    let dir = scene.path.parent().unwrap_or(Path::new("."));
    Some(dir.join(&scene.model))
}
