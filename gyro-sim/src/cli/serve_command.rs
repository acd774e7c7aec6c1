//! `gyro-sim serve`: in come a scene and a port; out goes the scene's page on 127.0.0.1 until a
//! stop signal (see [`crate::serve`]).

use std::path::Path;
use std::process::ExitCode;

use super::CliError;
use crate::models::Registry;
use crate::scene::Scene;

/// Loads the scene (a model file it names runs on the JIT engine), runs it once and serves it.
pub fn serve_command(scene: &Path, port: u16, registry: Registry) -> Result<ExitCode, CliError> {
    let scene = Scene::load_with(scene, &Default::default(), &|m| crate::model_run::file_defaults(scene, m))?;
    let (registry, warnings) = crate::model_run::with_file_model(&scene, registry)?;
    eprint!("{warnings}");
    if scene.controls.is_empty() {
        eprintln!(
            "{}: the scene has no [[controls]]: the page plays its run, with nothing to move",
            scene.path.display()
        );
    }
    let app = crate::serve::app(scene, registry)?;
    crate::serve::serve(app, port, |address| {
        println!("serving http://{address}/ (Ctrl-C stops)");
    })?;
    Ok(ExitCode::SUCCESS)
}
