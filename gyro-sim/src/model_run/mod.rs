//! Running a model file: in come the file (named by `--model`, or by a scene's
//! `model = "file.al"`), the scene when there is one, what the command line gives and the
//! engine asked; out goes a [`PreparedRun`]: the scene (generated when there is none, each line
//! knowing its origin), the file's model on its engine in a registry, and the problem resolved
//! once. Errors keep their origins as data ([`ModelRunError`]).

mod error;
mod open_inputs;
mod origins;
mod scene_text;

use std::path::{Path, PathBuf};

pub use error::ModelRunError;
pub use origins::{GeneratedScene, GENERATED};
pub use scene_text::{scene_text, ModelRunArgs, ModelValues};

use crate::models::{FileRun, ModelFile, Registry};
use crate::problem::{Engine, Problem, SharedModel};
use crate::scene::{Scene, SceneError};

/// A model file compiled into this binary (the compiled path's cached binaries).
#[derive(Clone)]
pub struct CompiledModel {
    /// Its registry key ([`crate::models::registry_key`] of the file's equations).
    pub key: String,
    /// The compiled model.
    pub model: SharedModel,
    /// What the file says about a run.
    pub run: FileRun,
}

/// What a run of a model file is asked.
pub struct FileRunRequest<'a> {
    /// The model file.
    pub file: &'a Path,
    /// The scene naming it, when there is one (else a scene is generated).
    pub scene: Option<Scene>,
    /// What the command line gives a run without a scene (`view`: draw the model).
    pub args: ModelRunArgs,
    /// How the equations run.
    pub engine: Engine,
}

/// A model file's run, ready to resolve and run.
pub struct PreparedRun {
    /// The scene run.
    pub scene: Scene,
    /// The registry with the file's model under the scene's `model`.
    pub registry: Registry,
    /// The file's model on its engine (on the instant engine when the compiled one is asked:
    /// the values are checked before anything is built).
    pub model: SharedModel,
    /// Warnings of the model file (empty when none).
    pub warnings: String,
    /// The checked file, to build the compiled binary from, when the compiled engine is asked
    /// and this binary is not already it.
    pub to_compile: Option<ModelFile>,
    file: PathBuf,
    generated: Option<GeneratedScene>,
}

/// Reads and checks the model file, puts its model on the engine asked (this binary's own
/// compiled model when it is the file's) and makes the scene.
pub fn prepare(
    request: FileRunRequest<'_>,
    registry: Registry,
    compiled: Option<CompiledModel>,
) -> Result<PreparedRun, ModelRunError> {
    let specified = request.scene.as_ref().map_or(&[][..], |s| &s.specified[..]);
    // The default drawing's outputs only for a view that draws the model.
    let drawn = request.scene.as_ref().map_or(request.args.view, Scene::draws_model);
    let source = crate::models::source_with(request.file, specified)?;
    let key = crate::models::registry_key(&source);
    let file = ModelFile::from_source(request.file, source, drawn)?;
    let run = file.run.clone();
    let (model, to_compile, warnings) = match compiled.filter(|c| c.key == key) {
        Some(c) => (file.dress_compiled(c.model), None, String::new()),
        None => {
            let model = crate::models::in_process_model(&file, request.engine == Engine::Jit)?;
            let warnings = file.warnings.clone();
            (model, (request.engine == Engine::Compiled).then_some(file), warnings)
        }
    };
    let (scene, generated) = match request.scene {
        Some(scene) => (scene, None),
        None => generated_scene(request.file, &run, &model, request.args)?,
    };
    let registry = registry.with_entry(&scene.model, model.clone());
    Ok(PreparedRun {
        scene,
        registry,
        model,
        warnings,
        to_compile,
        file: request.file.to_path_buf(),
        generated,
    })
}

impl PreparedRun {
    /// The problem of the scene, an error at a generated scene's line told at its origin.
    pub fn resolve(&self) -> Result<Problem, ModelRunError> {
        crate::resolve::resolve(&self.scene, &self.registry).map_err(|e| self.locate(e))
    }

    /// The path a failure of the run is named by: the scene's, or the model file's when the
    /// scene was generated.
    pub fn named_by(&self) -> &Path {
        match self.generated {
            Some(_) => &self.file,
            None => &self.scene.path,
        }
    }

    /// The scene's text to save and run: a generated scene names the model file by its
    /// absolute path (a saved scene's model path is read relative to the scene's folder).
    pub fn printable_scene(&self) -> String {
        let text = &self.scene.source;
        let Some(absolute) = self.generated.as_ref().and_then(|_| std::fs::canonicalize(&self.file).ok())
        else {
            return text.clone();
        };
        let given = format!("model = {:?}", self.scene.model);
        text.replacen(&given, &format!("model = {:?}", absolute.display().to_string()), 1)
    }

    /// A warning naming the model's open inputs the scene gives no value, or None.
    pub fn open_inputs_warning(&self) -> Option<String> {
        open_inputs::open_inputs_warning(&self.scene, self.model.info())
    }

    fn locate(&self, error: SceneError) -> ModelRunError {
        locate(error, self.generated.as_ref(), &self.file)
    }
}

/// The scene of a run without one, parsed.
fn generated_scene(
    file: &Path,
    run: &FileRun,
    model: &SharedModel,
    args: ModelRunArgs,
) -> Result<(Scene, Option<GeneratedScene>), ModelRunError> {
    let args = ModelRunArgs { view: model.drawing().is_some(), ..args };
    let (params, initial) = (model.default_params(), model.initial_state());
    let values = ModelValues { params: &params, initial: &initial };
    let generated = scene_text(&file.display().to_string(), run, model.info(), values, &args)?;
    let mut scene =
        Scene::parse(GENERATED, &generated.text()).map_err(|e| locate(e, Some(&generated), file))?;
    // The model is found under the path as given (not relative to a scene file).
    scene.path = PathBuf::from(GENERATED);
    Ok((scene, Some(generated)))
}

/// `error`, told at its origin when it is at a line of the generated scene.
fn locate(error: SceneError, generated: Option<&GeneratedScene>, file: &Path) -> ModelRunError {
    match generated {
        Some(g) if error.file == GENERATED => {
            let origin = g.origin(error.line);
            ModelRunError::AtOrigin { file: file.to_path_buf(), origin, error: Box::new(error) }
        }
        _ => ModelRunError::Scene(Box::new(error)),
    }
}

/// `registry` with the model file `scene` names, if it names one, on the JIT engine (for the
/// commands that run a scene's members or controls: sweep, serve), and the file's warnings.
pub fn with_file_model(scene: &Scene, registry: Registry) -> Result<(Registry, String), ModelRunError> {
    let Some(path) = model_file_of(scene) else { return Ok((registry, String::new())) };
    let source = crate::models::source_with(&path, &scene.specified)?;
    let file = ModelFile::from_source(&path, source, scene.draws_model())?;
    let model = crate::models::jit_file_model(&file)?;
    Ok((registry.with_entry(&scene.model, model), file.warnings))
}

/// What a scene at `scene_path` naming `model` takes where it gives no times or tolerances:
/// for a model file, its TFINAL, INTEGSTP, RELERR and ABSERR, else what a `--model` run takes
/// (also when the file does not load: its mistakes are reported when it is run); nothing for a
/// built-in model.
pub fn file_defaults(scene_path: &Path, model: &str) -> crate::scene::SceneDefaults {
    if !model.to_ascii_lowercase().ends_with(".al") {
        return crate::scene::SceneDefaults::default();
    }
    let path = scene_path.parent().unwrap_or(Path::new(".")).join(model);
    let source = std::fs::read_to_string(&path).unwrap_or_default();
    let run = kane_model::lang::load(&path.display().to_string(), &source)
        .map(|loaded| FileRun::of(&loaded))
        .unwrap_or_default();
    scene_text::scene_defaults(&run)
}

/// The model file a scene names (`model = "file.al"`, relative to the scene), if it does.
pub fn model_file_of(scene: &Scene) -> Option<PathBuf> {
    if !scene.model.to_ascii_lowercase().ends_with(".al") {
        return None;
    }
    let dir = scene.path.parent().unwrap_or(Path::new("."));
    Some(dir.join(&scene.model))
}
