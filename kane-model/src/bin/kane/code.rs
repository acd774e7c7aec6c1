//! `kane code`: the standalone programs a model file's CODE statements ask for (or one in a
//! language named on the command line), written beside the file or into a folder.

use std::path::{Path, PathBuf};

use kane_model::generate::{BuildError, CodeFile, StandaloneFile};
use kane_model::lang::CodeRequest;
use kane_model::standalone::{Language, StandaloneError};

use super::output::outln;
use super::{read, write_output};

/// What `kane code` is asked.
pub struct CodeArgs {
    /// The model file.
    pub file: PathBuf,
    /// The folder programs are written to (default: the model file's).
    pub out_dir: Option<PathBuf>,
    /// One program in this language, instead of the file's CODE statements.
    pub language: Option<String>,
    /// Where that program goes.
    pub output: Option<PathBuf>,
}

/// Runs `kane code`.
pub fn code(args: CodeArgs) -> Result<(), String> {
    let source = read(&args.file)?;
    let dir =
        args.out_dir.clone().unwrap_or_else(|| args.file.parent().unwrap_or(Path::new("")).to_path_buf());
    if let Some(name) = &args.language {
        let language = Language::named(name).ok_or_else(|| {
            format!("--lang {name}: not a language kane writes (c, fortran, matlab, python)")
        })?;
        let stem = kane_model::generate::model_name(&args.file);
        let path =
            args.output.clone().unwrap_or_else(|| dir.join(format!("{stem}.{}", language.extension())));
        let file = StandaloneFile::load(&args.file, &source).map_err(rendered)?;
        return write_program(&path, |stem| file.program(language, stem).map_err(|e| failed(&file, e)));
    }
    if args.output.is_some() {
        return Err("-o names the file of the program --lang asks for: give --lang too".into());
    }
    let code = CodeFile::load(&args.file, &source).map_err(rendered)?;
    if code.requests.is_empty() {
        return Err(format!(
            "{}: the file has no CODE statement: add one (CODE DYNAMICS() NAME.m, .c, .f90 or .py), or give --lang c|fortran|matlab|python",
            args.file.display()
        ));
    }
    let mut dynamics: Option<Result<StandaloneFile, String>> = None;
    let mut failures = Vec::new();
    for (i, request) in code.requests.iter().enumerate() {
        let written = request_path(&code, request, &dir).and_then(|(language, path)| {
            write_program(&path, |stem| {
                if let Some(text) = code.system_program(i, language, stem) {
                    return text.map_err(|e| code.error_at(request, &e, "this statement writes no program"));
                }
                let file = dynamics
                    .get_or_insert_with(|| StandaloneFile::load(&args.file, &source).map_err(rendered))
                    .as_ref()
                    .map_err(String::clone)?;
                let text = match request.kind.as_str() {
                    "DYNAMICS" => file.program(language, stem),
                    _ => file.outputs_program(language, stem),
                };
                text.map_err(|e| code.error_at(request, &e.to_string(), "this statement writes no program"))
            })
        });
        if let Err(e) = written {
            failures.push(e);
        }
    }
    if failures.is_empty() {
        return Ok(());
    }
    let written = code.requests.len() - failures.len();
    Err(format!("{}\n{written} of {} CODE statements written", failures.join("\n"), code.requests.len()))
}

fn rendered(e: BuildError) -> String {
    match e {
        BuildError::Model(report) => report.render(),
        other => other.to_string(),
    }
}

fn failed(file: &StandaloneFile, e: StandaloneError) -> String {
    format!("{}: {e}", file.shown)
}

/// The language and path of the program `request` asks for, or why it writes none.
fn request_path(file: &CodeFile, request: &CodeRequest, dir: &Path) -> Result<(Language, PathBuf), String> {
    let mut parts = request.file.split(',').map(str::trim);
    let name = parts.next().unwrap_or("");
    for option in parts {
        if !["SUBS", "NOSUBS"].iter().any(|known| option.eq_ignore_ascii_case(known)) {
            let message = format!("CODE option `{option}` is not one kane knows");
            return Err(file.error_at(
                request,
                &message,
                "remove it; SUBS and NOSUBS are accepted (the program reads the parameters as values \
                 and starts from the file's INPUT values either way)",
            ));
        }
    }
    if !["DYNAMICS", "ALGEBRAIC", "NONLINEAR"].contains(&request.kind.as_str()) {
        let message = format!("CODE {}() programs are not written", request.kind);
        return Err(file.error_at(
            request,
            &message,
            "CODE DYNAMICS() writes the equations of motion with a driver that integrates them",
        ));
    }
    if name.is_empty() {
        let message = format!("CODE {}() names no file", request.kind);
        let help = format!("name one: CODE {}(...) NAME.m (or .c, .f90, .py)", request.kind);
        return Err(file.error_at(request, &message, &help));
    }
    let language = Language::of_file(name).ok_or_else(|| {
        let message = format!("`{name}`: kane writes no program in the language this extension names");
        file.error_at(
            request,
            &message,
            "name a .m (MATLAB, Octave), .c (C), .f, .for or .f90 (Fortran) or .py (Python) file",
        )
    })?;
    // A Windows path (`gait\model.c`) names the same folders. MATLAB and Octave load only `.m`,
    // and `.C` is C++ to compilers: the extension is written in lower case.
    let name = name.replace('\\', "/");
    let (stem, extension) = name.rsplit_once('.').unwrap_or((&name, ""));
    let path = dir.join(format!("{stem}.{}", extension.to_ascii_lowercase()));
    match path.parent() {
        Some(folder) if !folder.as_os_str().is_empty() && !folder.is_dir() => {
            let message = format!("`{name}` is in a folder that does not exist: {}", folder.display());
            let help =
                "a name is relative to the model file's folder (Autolev's was relative to the folder it \
                        ran in: --out DIR names that one); create the folder or pass --out DIR";
            Err(file.error_at(request, &message, help))
        }
        _ => Ok((language, path)),
    }
}

/// Writes the program `text` gives for the path's stem (the program's name) to `path`.
fn write_program(path: &Path, text: impl FnOnce(&str) -> Result<String, String>) -> Result<(), String> {
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("model");
    write_output(path, &text(stem)?)?;
    outln!("wrote {}", path.display());
    Ok(())
}
