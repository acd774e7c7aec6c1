//! `kane code`: the standalone programs a model file's CODE statements ask for (or one in a
//! language named on the command line), written beside the file or into a folder.

use std::path::{Path, PathBuf};

use kane_model::generate::{BuildError, StandaloneFile};
use kane_model::lang::CodeRequest;
use kane_model::standalone::Language;

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
    let file = StandaloneFile::load(&args.file, &source).map_err(|e| match e {
        BuildError::Model(report) => report.render(),
        other => other.to_string(),
    })?;
    let dir =
        args.out_dir.clone().unwrap_or_else(|| args.file.parent().unwrap_or(Path::new("")).to_path_buf());
    if let Some(name) = &args.language {
        let language = Language::named(name).ok_or_else(|| {
            format!("--lang {name}: not a language kane writes (c, fortran, matlab, python)")
        })?;
        let stem = kane_model::generate::model_name(&args.file);
        let path =
            args.output.clone().unwrap_or_else(|| dir.join(format!("{stem}.{}", language.extension())));
        return write_program(&file, language, &path);
    }
    if args.output.is_some() {
        return Err("-o names the file of the program --lang asks for: give --lang too".into());
    }
    let mut failures = Vec::new();
    let mut written = 0;
    for request in &file.requests {
        match request_path(&file, request, &dir)
            .and_then(|(language, path)| write_program(&file, language, &path))
        {
            Ok(()) => written += 1,
            Err(e) => failures.push(e),
        }
    }
    if file.requests.is_empty() {
        return Err(format!(
            "{}: the file has no CODE statement: add one (CODE DYNAMICS() NAME.m, .c, .f90 or .py), or give --lang c|fortran|matlab|python",
            args.file.display()
        ));
    }
    if failures.is_empty() {
        return Ok(());
    }
    Err(format!("{}\n{written} of {} CODE statements written", failures.join("\n"), file.requests.len()))
}

/// The language and path of the program `request` asks for, or why it writes none.
fn request_path(
    file: &StandaloneFile,
    request: &CodeRequest,
    dir: &Path,
) -> Result<(Language, PathBuf), String> {
    let mut parts = request.file.split(',').map(str::trim);
    let name = parts.next().unwrap_or("");
    for option in parts {
        if !option.eq_ignore_ascii_case("SUBS") {
            let message = format!("CODE option `{option}` is not one kane knows");
            return Err(file.error_at(
                request,
                &message,
                "remove it; SUBS is accepted (the program carries the file's INPUT values)",
            ));
        }
    }
    if request.kind != "DYNAMICS" {
        let message = format!("CODE {}() programs are not written yet", request.kind);
        return Err(file.error_at(
            request,
            &message,
            "`kane solve FILE` solves the system at the file's INPUT values",
        ));
    }
    if name.is_empty() {
        return Err(file.error_at(
            request,
            "CODE DYNAMICS() names no file",
            "name one: CODE DYNAMICS() NAME.m (or .c, .f90, .py)",
        ));
    }
    let language = Language::of_file(name).ok_or_else(|| {
        let message = format!("`{name}`: kane writes no program in the language this extension names");
        file.error_at(
            request,
            &message,
            "name a .m (MATLAB, Octave), .c (C), .f, .for or .f90 (Fortran) or .py (Python) file",
        )
    })?;
    // MATLAB and Octave load only `.m`, and `.C` is C++ to compilers: the extension is written in
    // lower case.
    let (stem, extension) = name.rsplit_once('.').unwrap_or((name, ""));
    Ok((language, dir.join(format!("{stem}.{}", extension.to_ascii_lowercase()))))
}

/// Writes `language`'s program to `path`, its name the path's stem.
fn write_program(file: &StandaloneFile, language: Language, path: &Path) -> Result<(), String> {
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("model");
    let text = file.program(language, stem).map_err(|e| format!("{}: {e}", file.shown))?;
    write_output(path, &text)?;
    outln!("wrote {}", path.display());
    Ok(())
}
