//! A user's model file, run without rebuilding the simulator: in comes the path of an
//! Autolev-style model file; out go its checked model, its lowered program and what the file
//! says about a run (TFINAL, INTEGSTP, ABSERR, RELERR, its OUTPUT names).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use kane_model::mechanics::Model;
use kane_model::program::ProgramModel;

use crate::problem::{Engine, Problem, RowStream, SharedModel, SimModel, SolveError, Trajectory};
use kane_model::runtime::ModelInfo;
use kane_model::spec::Drawing;
use thiserror::Error;

/// Why a model file cannot be run.
#[derive(Debug, Error)]
pub enum ModelFileError {
    /// The file cannot be read.
    #[error("{}: cannot read the model file: {source}", path.display())]
    Read {
        /// The path given.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The file does not check: the language's report, whose diagnostics carry their file,
    /// line and column (syntax, derivation or consistency errors).
    #[error(transparent)]
    Check(#[from] kane_model::lang::Report),
    /// The checked model does not make a spec (no equations, a SPECIFIED quantity without a
    /// formula, ...).
    #[error("{}: {source}", path.display())]
    Spec {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: kane_model::lang::SpecError,
    },
    /// The equations cannot be lowered to a program.
    #[error("{}: {source}", path.display())]
    Lower {
        /// The file.
        path: PathBuf,
        /// Why.
        #[source]
        source: kane_model::program::LowerError,
    },
}

pub use kane_model::lang::FileRun;

/// A checked model file, ready to run.
pub struct ModelFile {
    /// The path it was read from.
    pub path: PathBuf,
    /// Its text.
    pub source: String,
    /// The model's name: the file's stem.
    pub name: String,
    /// The mechanics (for plausibility checks of a run's values).
    pub model: Arc<Model>,
    /// The lowered program (the instant path).
    pub program: Arc<ProgramModel>,
    /// What the file says about a run.
    pub run: FileRun,
    /// Warnings `kane check` would print (empty when none).
    pub warnings: String,
    /// Its default drawing, when loaded with it (its outputs are then in the program).
    pub drawing: Option<Arc<Drawing>>,
}

impl ModelFile {
    /// Reads, checks and lowers the model file at `path` (without its drawing).
    pub fn load(path: &Path) -> Result<ModelFile, ModelFileError> {
        ModelFile::from_source(path, source_with(path, &[])?, false)
    }

    /// Checks and lowers `source`, the text of the model file at `path` (see `source_with`),
    /// with the outputs of its default drawing when `drawn` and they can be computed (else
    /// without them, a warning saying why).
    pub fn from_source(path: &Path, source: String, drawn: bool) -> Result<ModelFile, ModelFileError> {
        if !drawn {
            return ModelFile::lowered(path, source, false);
        }
        match ModelFile::lowered(path, source.clone(), true) {
            Err(ModelFileError::Spec { source: why, .. }) => {
                ModelFile::undrawn(path, source, &why.to_string())
            }
            Err(ModelFileError::Lower { source: why, .. }) => {
                ModelFile::undrawn(path, source, &why.to_string())
            }
            other => other,
        }
    }

    /// The file without its drawing, a warning saying why it cannot be drawn.
    fn undrawn(path: &Path, source: String, why: &str) -> Result<ModelFile, ModelFileError> {
        let mut file = ModelFile::lowered(path, source, false)?;
        file.warnings.push_str(&format!(
            "{}: warning: the model's frames and points cannot be drawn ({why}): no view of them\n",
            path.display()
        ));
        Ok(file)
    }

    /// `runs` (an engine's model of this file's program) with the file's mechanics and drawing.
    pub fn dress(&self, runs: SharedModel) -> SharedModel {
        Arc::new(self.dressed(runs, None))
    }

    /// `runs` (a model compiled from this file's equations, perhaps before its INPUT values were
    /// edited) with the file's program, mechanics, drawing and values as they are now, by name.
    pub fn dress_compiled(&self, runs: SharedModel) -> SharedModel {
        let (info, now) = (runs.info(), self.program.info());
        let (params, initial) = (self.program.default_params(), self.program.initial_state());
        let params = info.param_names.iter().map(|n| now.param(n).map_or(f64::NAN, |i| params[i])).collect();
        let initial =
            info.state_names.iter().map(|n| now.state(n).map_or(f64::NAN, |i| initial[i])).collect();
        Arc::new(self.dressed(runs, Some((params, initial))))
    }

    fn dressed(&self, runs: SharedModel, values: Option<(Vec<f64>, Vec<f64>)>) -> Dressed {
        let (program, mechanics, drawing) = (self.program.clone(), self.model.clone(), self.drawing.clone());
        Dressed { runs, program, mechanics, drawing, values }
    }

    /// The file checked and lowered, with its drawing's outputs when `drawn`.
    fn lowered(path: &Path, source: String, drawn: bool) -> Result<ModelFile, ModelFileError> {
        let shown = path.display().to_string();
        let checked = kane_model::lang::check(&shown, &source)?;
        let warnings = checked.warnings.to_string();
        let loaded = checked.model;
        let name = model_name(path);
        let run = FileRun::of(&loaded);
        let spec = match drawn {
            true => loaded.into_spec_drawn(&name).map(|(spec, drawing)| (spec, Some(Arc::new(drawing)))),
            false => loaded.into_spec(&name).map(|spec| (spec, None)),
        };
        let (mut spec, drawing) =
            spec.map_err(|source| ModelFileError::Spec { path: path.to_path_buf(), source })?;
        let program = ProgramModel::new(&mut spec)
            .map_err(|source| ModelFileError::Lower { path: path.to_path_buf(), source })?;
        Ok(ModelFile {
            path: path.to_path_buf(),
            source,
            name,
            model: Arc::new(spec.model),
            program: Arc::new(program),
            run,
            warnings,
            drawing,
        })
    }
}

/// A model file's model on an engine, with the file's program, mechanics and drawing, and the
/// file's values when the engine's are not the file's as it is now.
struct Dressed {
    runs: SharedModel,
    program: Arc<ProgramModel>,
    mechanics: Arc<Model>,
    drawing: Option<Arc<Drawing>>,
    /// Parameter defaults and initial state, in `runs`'s order.
    values: Option<(Vec<f64>, Vec<f64>)>,
}

impl SimModel for Dressed {
    fn info(&self) -> &'static ModelInfo {
        self.runs.info()
    }
    fn engine(&self) -> Engine {
        self.runs.engine()
    }
    fn initial_state(&self) -> Vec<f64> {
        self.values.as_ref().map_or_else(|| self.runs.initial_state(), |(_, y)| y.clone())
    }
    fn default_params(&self) -> Vec<f64> {
        self.values.as_ref().map_or_else(|| self.runs.default_params(), |(p, _)| p.clone())
    }
    fn solve(&self, problem: &Problem, rows_to: Option<&RowStream>) -> Result<Trajectory, SolveError> {
        self.runs.solve(problem, rows_to)
    }
    fn program(&self) -> Option<Arc<ProgramModel>> {
        Some(self.program.clone())
    }
    fn mechanics(&self) -> Option<Arc<Model>> {
        Some(self.mechanics.clone())
    }
    fn drawing(&self) -> Option<Arc<Drawing>> {
        self.drawing.clone()
    }
}

/// The text of the model file at `path` with a scene's `[specified]` formulas appended (after
/// KANE(), where a file's own formulas for SPECIFIED quantities may stand).
pub fn source_with(
    path: &Path,
    specified: &[(String, String, std::ops::Range<usize>)],
) -> Result<String, ModelFileError> {
    let mut source = std::fs::read_to_string(path)
        .map_err(|source| ModelFileError::Read { path: path.to_path_buf(), source })?;
    if !specified.is_empty() {
        if !source.ends_with('\n') {
            source.push('\n');
        }
        source.push_str("% From the scene's [specified] table:\n");
        for (name, formula, _) in specified {
            source.push_str(&format!("{name} = {formula}\n"));
        }
    }
    Ok(source)
}

pub use kane_model::generate::model_name;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_come_from_the_stem() {
        assert_eq!(model_name(Path::new("/a/my gimbal-2.al")), "my_gimbal_2");
        assert_eq!(model_name(Path::new("2top.al")), "model_2top");
    }

    #[test]
    fn the_paper_file_gives_its_run_settings() {
        let path =
            Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/gimbal_gyroscope.al"));
        let file = ModelFile::load(path).unwrap();
        assert_eq!(file.name, "gimbal_gyroscope");
        assert_eq!(file.run.t_final, Some(5.0));
        assert_eq!(file.run.step, Some(0.05));
        assert_eq!((file.run.abserr, file.run.relerr), (Some(1e-7), Some(1e-7)));
        assert_eq!(file.run.outputs[..7], ["Q1", "Q2", "Q3", "U1", "U2", "U3", "AP"]);
    }
}
