//! `kane fmu`: a model file's FMI 2.0 FMU (Model Exchange and Co-Simulation): the model
//! description, the C source and a shared library for this platform compiled with the system's
//! C compiler (`CC`, else `cc`), zipped into one file.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;

use kane_model::generate::{BuildError, StandaloneFile};

use super::output::outln;
use super::read;

/// The FMI platform folder and library suffix of this machine, if FMI 2.0 names one.
fn platform() -> Option<(&'static str, &'static str)> {
    match (std::env::consts::OS, std::env::consts::ARCH) {
        ("linux", "x86_64") => Some(("linux64", "so")),
        ("macos", "x86_64" | "aarch64") => Some(("darwin64", "dylib")),
        _ => None,
    }
}

/// Runs `kane fmu FILE -o NAME.fmu`.
pub fn fmu(file: PathBuf, output: Option<PathBuf>) -> Result<(), String> {
    let source = read(&file)?;
    let loaded = StandaloneFile::load(&file, &source).map_err(|e| match e {
        BuildError::Model(report) => report.render(),
        other => other.to_string(),
    })?;
    let text = loaded.fmu().map_err(|e| format!("{}: {e}", file.display()))?;
    let (folder, suffix) = platform().ok_or_else(|| {
        format!("FMI 2.0 names no binary folder for {} on {}", std::env::consts::ARCH, std::env::consts::OS)
    })?;
    let path = output.unwrap_or_else(|| file.with_file_name(format!("{}.fmu", text.identifier)));
    let work = std::env::temp_dir().join(format!("kane-fmu-{}-{}", text.identifier, std::process::id()));
    let result =
        build(&text, &work, folder, suffix).and_then(|library| zip(&path, &text, &library, folder, suffix));
    let _ = std::fs::remove_dir_all(&work);
    result?;
    outln!("wrote {}", path.display());
    Ok(())
}

/// Compiles the source into `work`; the library's path.
fn build(
    text: &kane_model::standalone::FmuText,
    work: &Path,
    folder: &str,
    suffix: &str,
) -> Result<PathBuf, String> {
    std::fs::create_dir_all(work).map_err(|e| format!("{}: {e}", work.display()))?;
    let source = work.join(format!("{}.c", text.identifier));
    std::fs::write(&source, &text.source).map_err(|e| format!("{}: {e}", source.display()))?;
    let library = work.join(format!("{}.{suffix}", text.identifier));
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = Command::new(&cc)
        .args(["-shared", "-fPIC", "-O2", "-std=c99", "-fvisibility=hidden", "-o"])
        .arg(&library)
        .arg(&source)
        .arg("-lm")
        .output()
        .map_err(|e| format!("the C compiler `{cc}` cannot be run ({e}): install one (gcc) or set CC"))?;
    if !out.status.success() {
        return Err(format!(
            "`{cc}` could not compile the FMU's source for {folder} (a bug: please report it):\n{}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(library)
}

/// Writes the FMU archive to `path` through a temporary file.
fn zip(
    path: &Path,
    text: &kane_model::standalone::FmuText,
    library: &Path,
    folder: &str,
    suffix: &str,
) -> Result<(), String> {
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let binary = std::fs::read(library).map_err(|e| fail(&e))?;
    let tmp = path.with_extension("fmu.partial");
    let written = (|| -> Result<(), String> {
        let file = std::fs::File::create(&tmp).map_err(|e| fail(&e))?;
        let mut archive = zip::ZipWriter::new(file);
        let options =
            zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
        let id = &text.identifier;
        let entries: [(String, &[u8]); 3] = [
            ("modelDescription.xml".into(), text.model_description.as_bytes()),
            (format!("sources/{id}.c"), text.source.as_bytes()),
            (format!("binaries/{folder}/{id}.{suffix}"), &binary),
        ];
        for (name, bytes) in entries {
            archive.start_file(name, options).map_err(|e| fail(&e))?;
            archive.write_all(bytes).map_err(|e| fail(&e))?;
        }
        archive.finish().map_err(|e| fail(&e))?;
        std::fs::rename(&tmp, path).map_err(|e| fail(&e))
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written
}
