//! Model files to generated modules, for build scripts, proc macros and tools: in comes a model
//! file (or the name of a canonical system); out goes its generated module. File I/O lives here,
//! not in the stages.

use std::path::Path;

use thiserror::Error;

use crate::codegen::{CodeOptions, Emitted};
use crate::program::LowerError;

/// Why a model could not be generated.
#[derive(Debug, Error)]
pub enum BuildError {
    /// The model file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// What the system said.
        source: std::io::Error,
    },
    /// The model file has errors (each with its line and column).
    #[error("{0}")]
    Model(#[from] crate::lang::Report),
    /// The model file has no spec (no equations, or an OUTPUT it does not define).
    #[error("{model}: {source}")]
    Spec {
        /// The model file.
        model: String,
        /// Why the model text did not become a spec.
        source: crate::lang::SpecError,
    },
    /// The model cannot be turned into code.
    #[error("{model}: {source}")]
    Codegen {
        /// The model file or name.
        model: String,
        /// Why the spec could not be lowered to code.
        source: LowerError,
    },
    /// The generated tokens are not a Rust file (a bug in the printer).
    #[error("generated code does not parse: {0}")]
    Format(#[from] syn::Error),
    /// No canonical system has this name.
    #[error("no built-in model `{name}` (known: {known})")]
    UnknownBuiltin {
        /// The name asked for.
        name: String,
        /// The names known.
        known: String,
    },
}

/// The generated code of the model file `path` (its text `source`), named after the file.
pub fn generate_file(path: &Path, source: &str, options: &CodeOptions) -> Result<Emitted, BuildError> {
    let shown = path.display().to_string();
    let loaded = crate::lang::check_for_generation(&shown, source)?.model;
    let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or("model").to_string();
    let spec = match options.drawing {
        true => loaded.into_spec_drawn(&name).map(|(spec, _)| spec),
        false => loaded.into_spec(&name),
    };
    let mut spec = spec.map_err(|source| BuildError::Spec { model: shown.clone(), source })?;
    crate::codegen::generate(&mut spec, options)
        .map_err(|source| BuildError::Codegen { model: shown, source })
}

/// The generated code of the canonical system `name` of [`crate::models::builtin_spec`].
pub fn generate_builtin(name: &str, options: &CodeOptions) -> Result<Emitted, BuildError> {
    let known = crate::models::BUILTIN_SPECS.join(", ");
    let spec = crate::models::builtin_spec(name)
        .ok_or_else(|| BuildError::UnknownBuiltin { name: name.to_string(), known })?;
    let codegen = |source| BuildError::Codegen { model: name.to_string(), source };
    let mut spec = spec.map_err(|e| codegen(LowerError::Mechanics(e)))?;
    if options.drawing {
        spec.add_drawing(None).map_err(|e| codegen(LowerError::Mechanics(e)))?;
    }
    crate::codegen::generate(&mut spec, options).map_err(codegen)
}

/// For `build.rs`: reads `model` (a model file), writes its generated module to `out` (for
/// `include!`), and asks cargo to rerun when the model file changes.
///
/// ```text
/// // build.rs
/// fn main() {
///     let out = std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("gimbal.rs");
///     let options = kane_model::codegen::CodeOptions::default();
///     kane_model::generate::build_script("models/gimbal_gyroscope.al", &out, &options).unwrap();
/// }
/// // src/lib.rs: pub mod gimbal { include!(concat!(env!("OUT_DIR"), "/gimbal.rs")); }
/// ```
pub fn build_script(model: &str, out: &Path, options: &CodeOptions) -> Result<(), BuildError> {
    println!("cargo:rerun-if-changed={model}");
    let io = |path: &Path| {
        let path = path.display().to_string();
        move |source| BuildError::Io { path, source }
    };
    let src = std::fs::read_to_string(model).map_err(io(Path::new(model)))?;
    let emitted = generate_file(Path::new(model), &src, options)?;
    let text = crate::codegen::to_items(&emitted)?;
    let tmp = out.with_extension("rs.partial");
    std::fs::write(&tmp, text).map_err(io(&tmp))?;
    std::fs::rename(&tmp, out).map_err(io(out))
}

/// A model's name from its file: the stem, as an identifier (`my gimbal-2.al` -> `my_gimbal_2`).
pub fn model_name(path: &Path) -> String {
    let stem = path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
    let mut name: String = stem.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    if name.is_empty() || name.starts_with(|c: char| c.is_ascii_digit()) {
        name.insert_str(0, "model_");
    }
    name
}

/// A model file's CODE statements, with the systems CODE ALGEBRAIC and CODE NONLINEAR ask
/// for ready for their programs (the dynamics are lowered only by [`StandaloneFile`]).
pub struct CodeFile {
    /// The file's CODE statements, in order.
    pub requests: Vec<crate::lang::CodeRequest>,
    /// The model file as shown.
    pub shown: String,
    /// Each request's system plan (or why there is none); `None` for a request without one.
    systems: Vec<Option<Result<crate::standalone::SystemPlan, String>>>,
    /// What a system's program says about itself.
    about: crate::standalone::Program,
    /// An empty report on the file, for errors at its CODE statements.
    report: crate::lang::Report,
}

impl CodeFile {
    /// Checks the model file `path` (its text `source`) and plans its systems.
    pub fn load(path: &Path, source: &str) -> Result<CodeFile, BuildError> {
        let shown = path.display().to_string();
        let mut loaded = crate::lang::check_for_generation(&shown, source)?.model;
        let requests = loaded.code.clone();
        let report = loaded.report(&shown, Vec::new());
        // CODE ALGEBRAIC() of a file without equations of motion evaluates its OUTPUT quantities.
        let evaluates = |r: &crate::lang::CodeRequest| r.kind == "ALGEBRAIC" && r.system.is_none();
        let evaluation =
            (loaded.equations.is_none() && !loaded.forces_formed && requests.iter().any(evaluates))
                .then(|| loaded.output_evaluation());
        let names: Vec<String> = loaded.model.ar.symbols().map(|(_, info)| info.name.clone()).collect();
        let values: Vec<Option<f64>> = names.iter().map(|n| loaded.input(n)).collect();
        let value_of = |s: crate::expr::SymbolId| values.get(s.index()).copied().flatten();
        let systems = requests
            .iter()
            .map(|r| {
                let plan = |system: &crate::lang::algebraic::AlgebraicSystem, ar: &mut crate::expr::Arena| {
                    crate::standalone::SystemPlan::new(ar, system, &value_of).map_err(|e| e.to_string())
                };
                match (&r.system, &evaluation) {
                    (Some(system), _) => Some(plan(system, &mut loaded.model.ar)),
                    (None, Some(outputs)) if evaluates(r) => Some(outputs.clone().map(|quantities| {
                        crate::standalone::SystemPlan::evaluation(&loaded.model.ar, &quantities, &value_of)
                    })),
                    _ => None,
                }
            })
            .collect();
        let about = crate::standalone::Program { identifier: model_name(path), model_file: shown.clone() };
        Ok(CodeFile { requests, shown, systems, about, report })
    }

    /// The program of request `i`'s system in `language`, named `stem`; `None` when the request
    /// has no system (CODE DYNAMICS, CODE ALGEBRAIC()).
    pub fn system_program(
        &self,
        i: usize,
        language: crate::standalone::Language,
        stem: &str,
    ) -> Option<Result<String, String>> {
        let plan = self.systems.get(i)?.as_ref()?;
        Some(plan.as_ref().map_err(String::clone).and_then(|plan| {
            crate::standalone::write_system(plan, language, stem, &self.about).map_err(|e| e.to_string())
        }))
    }

    /// `message` (with `help`) as an error at `request`'s line, rendered.
    pub fn error_at(&self, request: &crate::lang::CodeRequest, message: &str, help: &str) -> String {
        let d = crate::lang::Diagnostic::error(request.span.clone(), message).with_help(help);
        crate::lang::Report { diagnostics: vec![d], ..self.report.clone() }.render()
    }
}

/// A model file ready for standalone programs of its dynamics: its lowered program and run
/// settings.
pub struct StandaloneFile {
    /// The lowered program and the file's values.
    pub model: crate::program::ProgramModel,
    /// What the file says about a run.
    pub run: crate::lang::FileRun,
    /// The model file as shown.
    pub shown: String,
}

impl StandaloneFile {
    /// Checks and lowers the model file `path` (its text `source`).
    pub fn load(path: &Path, source: &str) -> Result<StandaloneFile, BuildError> {
        let shown = path.display().to_string();
        let loaded = crate::lang::check_for_generation(&shown, source)?.model;
        let run = crate::lang::FileRun::of(&loaded);
        let mut spec = loaded
            .into_spec(&model_name(path))
            .map_err(|source| BuildError::Spec { model: shown.clone(), source })?;
        let model = crate::program::ProgramModel::new(&mut spec)
            .map_err(|source| BuildError::Codegen { model: shown.clone(), source })?;
        Ok(StandaloneFile { model, run, shown })
    }

    /// The program in `language` named `stem` (its file's stem).
    pub fn program(
        &self,
        language: crate::standalone::Language,
        stem: &str,
    ) -> Result<String, crate::standalone::StandaloneError> {
        let plan = crate::standalone::Plan::new(&self.model, &self.run)?;
        crate::standalone::write(&plan, language, stem, &self.about())
    }

    /// The program in `language` named `stem` that evaluates the OUTPUT quantities once, at
    /// the file's INPUT values (what `CODE ALGEBRAIC()` asks for).
    pub fn outputs_program(
        &self,
        language: crate::standalone::Language,
        stem: &str,
    ) -> Result<String, crate::standalone::StandaloneError> {
        let plan = crate::standalone::Plan::new(&self.model, &self.run)?.at_start();
        crate::standalone::write(&plan, language, stem, &self.about())
    }

    /// The texts of the file's FMU.
    pub fn fmu(&self) -> Result<crate::standalone::FmuText, crate::standalone::StandaloneError> {
        let plan = crate::standalone::Plan::new(&self.model, &self.run)?;
        crate::standalone::fmu(&plan, &self.about())
    }

    /// What a program says about itself: the model's name and file.
    fn about(&self) -> crate::standalone::Program {
        let identifier = self.model.info().name.to_string();
        crate::standalone::Program { identifier, model_file: self.shown.clone() }
    }
}
