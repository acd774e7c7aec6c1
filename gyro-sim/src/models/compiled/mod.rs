//! The compiled path: in comes a checked model file; out goes the path of a gyro-sim binary
//! with that model compiled in (the integrator and the model inlined together, as for the
//! built-in models). Binaries are cached by the file's equations (its text without its INPUT
//! lines) and the tool's identity and built once, offline: by rustc against the workspace's own
//! compiled libraries, or, when that fails, as a binary of a package of model binaries built
//! with cargo. A later run of the same file reuses the binary, and so does a file whose INPUT
//! values alone changed (the binary reads them from the file at run time); any other edit
//! builds a new one.

mod direct;
mod lock;

use std::path::{Path, PathBuf};
use std::process::Command;

use thiserror::Error;

use super::model_file::{FileRun, ModelFile};

/// Why the compiled path cannot run.
#[derive(Debug, Error)]
pub enum CompileError {
    /// No cargo on the PATH.
    #[error("the compiled path needs a Rust toolchain, and `cargo` was not found: install Rust (https://rustup.rs), or run with --engine instant")]
    NoToolchain,
    /// The simulator's sources are not where this binary was built from.
    #[error("the compiled path builds against the gyro-sim sources at {}, which are not there: run from the project's checkout, or run with --engine instant", .0.display())]
    NoSources(PathBuf),
    /// Writing the crate failed.
    #[error("cannot write the compiled model's crate in {}: {source}", path.display())]
    Io {
        /// The folder it was written in.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The built binary could not be put in the cache.
    #[error("cannot put the compiled model in place: {0}")]
    Place(#[from] crate::output::WriteError),
    /// cargo failed.
    #[error("building the compiled model failed (cargo exit {0}); its output is above; --engine instant runs without compiling")]
    Build(String),
}

/// FNV-1a of `bytes`, as 16 hex digits: stable across Rust versions and machines.
pub fn content_hash(bytes: &[u8]) -> String {
    let h =
        bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(*b)).wrapping_mul(0x100_0000_01b3));
    format!("{h:016x}")
}

/// The key under which a model file's compiled model is registered: the hash of its
/// equations, `equations_text`.
pub fn registry_key(source: &str) -> String {
    format!("file:{}", content_hash(equations_text(source).as_bytes()))
}

/// A model file's text without its INPUT lines (values, units, initial conditions and run
/// settings, which the compiled binary reads from the file at run time): what its generated
/// code depends on.
pub fn equations_text(source: &str) -> String {
    let is_input = |line: &str| {
        let word: String = line.trim_start().chars().take_while(|c| c.is_ascii_alphabetic()).collect();
        word.eq_ignore_ascii_case("input")
    };
    source.lines().filter(|l| !is_input(l)).collect::<Vec<_>>().join("\n")
}

/// This tool's identity (its binary's size and modification time): a rebuilt simulator builds
/// its models again.
fn tool_id() -> String {
    let meta = std::env::current_exe().and_then(std::fs::metadata);
    let stamp = match meta {
        Ok(m) => {
            let modified = m.modified().ok().and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok());
            format!("{}-{}-{:?}", env!("CARGO_PKG_VERSION"), m.len(), modified)
        }
        Err(_) => env!("CARGO_PKG_VERSION").to_string(),
    };
    content_hash(stamp.as_bytes())[..8].to_string()
}

/// Where compiled models live: `$GYRO_SIM_CACHE`, else `$XDG_CACHE_HOME/gyro-sim`, else
/// `~/.cache/gyro-sim`.
pub fn cache_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("GYRO_SIM_CACHE") {
        return PathBuf::from(dir);
    }
    let base = std::env::var_os("XDG_CACHE_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cache")));
    base.unwrap_or_else(std::env::temp_dir).join("gyro-sim")
}

/// Where cargo builds compiled models: `$GYRO_SIM_TARGET_DIR`, else the workspace's own target
/// folder when there is one (its dependencies are built already), else the cache's.
fn target_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("GYRO_SIM_TARGET_DIR") {
        return PathBuf::from(dir);
    }
    let own = workspace().join("target");
    if own.is_dir() {
        own
    } else {
        cache_dir().join("target")
    }
}

/// The cargo profile compiled models are built with: `$GYRO_SIM_MODEL_PROFILE`, else `release`
/// (`dev` builds much faster and runs slower: the tests take it).
fn profile() -> String {
    std::env::var("GYRO_SIM_MODEL_PROFILE").ok().filter(|p| !p.is_empty()).unwrap_or_else(|| "release".into())
}

/// The folder cargo puts a profile's binaries in (`dev` and `test` share `debug`, `bench`
/// uses `release`).
fn profile_folder(profile: &str) -> &str {
    match profile {
        "dev" | "test" => "debug",
        "bench" => "release",
        other => other,
    }
}

/// The workspace this binary was built from.
fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Why the file at `path` is not a native program, if it is not (checked before it is started:
/// `execvp` would hand a file without a known header to `/bin/sh`).
pub fn not_a_program(path: &Path) -> Option<String> {
    use std::io::Read;
    let mut head = [0u8; 4];
    let read = std::fs::File::open(path).and_then(|mut f| f.read_exact(&mut head));
    if let Err(e) = read {
        return Some(format!("its header cannot be read: {e}"));
    }
    const HEADERS: [[u8; 4]; 4] =
        [*b"\x7fELF", [0xcf, 0xfa, 0xed, 0xfe], [0xce, 0xfa, 0xed, 0xfe], [0xca, 0xfe, 0xba, 0xbe]];
    let native = HEADERS.contains(&head) || (cfg!(windows) && head[..2] == *b"MZ");
    (!native).then(|| "it does not start with a program header (ELF, Mach-O or PE)".to_string())
}

/// The compiled binary for `file`, with Taylor coefficients when `taylor` (a scene integrates
/// it by the Taylor method) and the default drawing's outputs when `drawn` (each built apart
/// from the binary without them): the cached one, or one
/// built now (cargo's progress shown on standard error). True in the second value when it was
/// built.
pub fn ensure_binary(file: &ModelFile, taylor: bool, drawn: bool) -> Result<(PathBuf, bool), CompileError> {
    let hash = content_hash(equations_text(&file.source).as_bytes());
    let kind = format!("{}{}", if taylor { "-taylor" } else { "" }, if drawn { "-drawn" } else { "" });
    let crate_name =
        format!("gyro-model-{}-{}-{}{kind}", file.name.replace('_', "-"), &hash[..12], tool_id());
    let target = target_dir();
    let profile = profile();
    // Binaries live in the cache (one folder per profile), apart from the shared target folder.
    let binary = cache_dir().join("bin").join(&profile).join(&crate_name);
    if binary.is_file() {
        return Ok((binary, false));
    }
    let sources = workspace();
    if !sources.join("gyro-sim").join("Cargo.toml").is_file() {
        return Err(CompileError::NoSources(sources));
    }
    // One package for every model file (a binary each), so its dependencies build once.
    let dir = cache_dir().join("models").join(format!("gyro-models-{}", tool_id()));
    write_model(&dir, &crate_name, file, &sources, Generated { taylor, drawn })?;
    eprintln!("compiling the model {} (once per version of the file):", file.path.display());
    if let Some(note) = lock::wait_note(&target, profile_folder(&profile)) {
        eprintln!("{note}");
    }
    let cargo = std::env::var_os("CARGO").map_or_else(|| PathBuf::from("cargo"), PathBuf::from);
    if let Some(libs) = direct::libraries(&cargo, &sources, &target, &profile) {
        let main = dir.join("src").join("bin").join(format!("{crate_name}.rs"));
        if direct::build(&libs, &dir, &main, &binary) {
            return Ok((binary, true));
        }
        eprintln!("rustc against the workspace's libraries failed; building the model's package with cargo instead:");
    }
    let status = Command::new(&cargo)
        .args(["build", "--profile", &profile, "--offline", "--bin", &crate_name, "--manifest-path"])
        .arg(dir.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(&target)
        .status()
        .map_err(|_| CompileError::NoToolchain)?;
    let built = target.join(profile_folder(&profile)).join(&crate_name);
    if !status.success() || !built.is_file() {
        return Err(CompileError::Build(status.code().map_or("none".into(), |c| c.to_string())));
    }
    place(&built, &binary)?;
    Ok((binary, true))
}

/// Copies the binary `built` to `binary`, whole or not at all.
fn place(built: &Path, binary: &Path) -> Result<(), CompileError> {
    if let Some(folder) = binary.parent() {
        std::fs::create_dir_all(folder)
            .map_err(|source| CompileError::Io { path: folder.to_path_buf(), source })?;
    }
    let copy = |partial: &Path| {
        std::fs::copy(built, partial).map(|_| ()).map_err(|e| crate::output::WriteError::io(partial, e))
    };
    Ok(crate::output::write_atomically(binary, copy)?)
}

/// Writes one model into the models package at `dir`: the package's manifest against the
/// workspace's crates (its lock file copied, so the build resolves offline to the same
/// versions) when it has none, the model file under `models/NAME/` and a binary `src/bin/NAME.rs`
/// registering the model under its key.
fn write_model(
    dir: &Path,
    bin_name: &str,
    file: &ModelFile,
    sources: &Path,
    generated: Generated,
) -> Result<(), CompileError> {
    let io = |source: std::io::Error| CompileError::Io { path: dir.to_path_buf(), source };
    std::fs::create_dir_all(dir.join("src").join("bin")).map_err(io)?;
    // The file keeps its name (the model is named after it), in a folder of this binary's.
    std::fs::create_dir_all(dir.join("models").join(bin_name)).map_err(io)?;
    let model_file = format!("models/{bin_name}/{}.al", file.name);
    std::fs::write(dir.join(&model_file), &file.source).map_err(io)?;
    let path = |c: &str| format!("{:?}", sources.join(c).display().to_string());
    let manifest = format!(
        "[package]\nname = \"gyro-models\"\nversion = \"0.0.0\"\nedition = \"2021\"\npublish = false\nautobins = true\n\n[dependencies]\ngyro-sim = {{ path = {} }}\nkane-derive = {{ path = {} }}\nkane-model = {{ path = {}, default-features = false }}\n\n[profile.release]\ndebug = false\n\n[workspace]\n",
        path("gyro-sim"),
        path("kane-derive"),
        path("kane-model"),
    );
    if std::fs::read_to_string(dir.join("Cargo.toml")).ok().as_deref() != Some(manifest.as_str()) {
        std::fs::write(dir.join("Cargo.toml"), manifest).map_err(io)?;
        if let Ok(lock) = std::fs::read_to_string(sources.join("Cargo.lock")) {
            std::fs::write(dir.join("Cargo.lock"), lock).map_err(io)?;
        }
    }
    let main = main_source(file, &model_file, generated);
    std::fs::write(dir.join("src").join("bin").join(format!("{bin_name}.rs")), main).map_err(io)?;
    Ok(())
}

/// What a compiled model's code has beyond its equations.
#[derive(Clone, Copy)]
struct Generated {
    /// Taylor coefficients.
    taylor: bool,
    /// The default drawing's outputs.
    drawn: bool,
}

/// A model's binary in the models package (`model_file` relative to the package).
fn main_source(file: &ModelFile, model_file: &str, generated: Generated) -> String {
    let FileRun { t_final, step, abserr, relerr, outputs } = &file.run;
    let extras = format!(
        "{}{}",
        if generated.taylor { ", taylor" } else { "" },
        if generated.drawn { ", drawing" } else { "" }
    );
    format!(
        r#"//! gyro-sim with the model file {path:?} compiled in. Generated by gyro-sim: do not edit.

mod model {{
    kane_derive::model!({model_file:?}{extras});
}}

fn main() -> std::process::ExitCode {{
    let run = gyro_sim::FileRun {{
        t_final: {t_final:?},
        step: {step:?},
        abserr: {abserr:?},
        relerr: {relerr:?},
        outputs: vec![{outputs}],
    }};
    let model = gyro_sim::generated::<model::Model>();
    let key = gyro_sim::registry_key(include_str!(concat!("../../", {model_file:?})));
    let compiled = gyro_sim::CompiledModel {{ key, model, run }};
    // The file's model alone: the built-in models stay out of this binary.
    gyro_sim::main_with(gyro_sim::Registry::new(), Some(compiled))
}}
"#,
        path = file.path.display().to_string(),
        outputs = outputs.iter().map(|o| format!("{o:?}.to_string()")).collect::<Vec<_>>().join(", "),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn input_values_do_not_change_the_key_and_equations_do() {
        let a = "CONSTANTS M\nINPUT M = 1 kg, TFINAL = 5\nKANE()\n";
        let b = "CONSTANTS M\n  input M = 2 kg\nKANE()\n";
        let c = "CONSTANTS M, K\nINPUT M = 1 kg, TFINAL = 5\nKANE()\n";
        assert_eq!(registry_key(a), registry_key(b));
        assert_ne!(registry_key(a), registry_key(c));
        assert_eq!(equations_text("INPUTS\nX"), "INPUTS\nX", "only the INPUT command is left out");
    }
}
