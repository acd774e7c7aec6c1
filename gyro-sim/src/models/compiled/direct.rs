//! A model binary built by rustc alone, against the workspace's own compiled libraries: cargo
//! lists them (building nothing when the workspace is built), so gyro-sim, kane-model and
//! kane-derive are not compiled again for the model, as they are for a package of its own
//! (cargo names a path dependency by its place relative to the workspace that builds it).

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use serde_json::Value;

/// The compiled libraries a model binary links against, and the profile they were built with.
pub(super) struct Libraries {
    gyro_sim: PathBuf,
    /// kane-model as gyro-sim links it: cargo may build it twice alike (once for the macro's
    /// host), so the candidates, the likelier first; rustc tells which one gyro-sim uses.
    kane_model: Vec<PathBuf>,
    kane_derive: PathBuf,
    deps: PathBuf,
    opt_level: String,
}

/// The libraries of the workspace at `workspace` built in `target` with `profile`, as cargo
/// reports them (it builds what is out of date first); `None` when cargo fails or does not
/// report all three.
pub(super) fn libraries(cargo: &Path, workspace: &Path, target: &Path, profile: &str) -> Option<Libraries> {
    let out = Command::new(cargo)
        .args(["build", "--profile", profile, "--offline", "--message-format=json", "--lib"])
        .args(["-p", "gyro-sim", "--manifest-path"])
        .arg(workspace.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(target)
        .stderr(Stdio::inherit())
        .output()
        .ok()
        .filter(|o| o.status.success())?;
    let artifacts: Vec<Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| serde_json::from_str::<Value>(l).ok())
        .filter(|v| v["reason"] == "compiler-artifact")
        .collect();
    pick(&artifacts)
}

/// The libraries among cargo's compiler artifacts: gyro-sim's, the kane-model built as it is,
/// and kane-derive's macro.
fn pick(artifacts: &[Value]) -> Option<Libraries> {
    fn named<'a>(all: &'a [Value], name: &'a str) -> impl Iterator<Item = &'a Value> {
        all.iter().filter(move |a| a["target"]["name"] == name)
    }
    let file = |a: &Value, ext: &str| {
        a["filenames"]
            .as_array()?
            .iter()
            .filter_map(Value::as_str)
            .find(|f| f.ends_with(ext))
            .map(PathBuf::from)
    };
    let gyro = named(artifacts, "gyro_sim").next()?;
    // Built as gyro-sim is first (the macro's host build may have another profile).
    let mut models: Vec<&Value> = named(artifacts, "kane_model").collect();
    models.sort_by_key(|a| a["profile"] != gyro["profile"]);
    let kane_model: Vec<PathBuf> = models.iter().filter_map(|a| file(a, ".rlib")).collect();
    let kane_derive = named(artifacts, "kane_derive").find_map(|a| file(a, std::env::consts::DLL_SUFFIX))?;
    let libraries = Libraries {
        // A dependency's files are in `deps`; gyro-sim's own may be copied up beside it.
        deps: kane_model.first()?.parent()?.to_path_buf(),
        gyro_sim: file(gyro, ".rlib")?,
        kane_model,
        kane_derive,
        opt_level: gyro["profile"]["opt_level"].as_str().unwrap_or("3").to_string(),
    };
    Some(libraries)
}

/// Compiles the binary `main` of the models package at `package` into `out` (written whole
/// or not at all), against each kane-model candidate until one is gyro-sim's; false when none
/// compiles (rustc's messages for the last are on standard error).
pub(super) fn build(libs: &Libraries, package: &Path, main: &Path, out: &Path) -> bool {
    if out.parent().is_some_and(|d| std::fs::create_dir_all(d).is_err()) {
        return false;
    }
    let name = out.file_name().and_then(|n| n.to_str()).unwrap_or("model").replace('-', "_");
    let built = crate::output::write_atomically(out, |partial| {
        let mut failed = RustcError::NotRun;
        for kane_model in &libs.kane_model {
            match rustc(libs, kane_model, package, main, &name, partial) {
                Some(o) if o.status.success() => return Ok(()),
                Some(o) => failed = RustcError::Failed(String::from_utf8_lossy(&o.stderr).into_owned()),
                None => failed = RustcError::NotRun,
            }
        }
        Err(failed)
    });
    if let Err(e) = &built {
        eprint!("{e}");
    }
    built.is_ok()
}

/// Why rustc did not build a binary.
#[derive(Debug, thiserror::Error)]
enum RustcError {
    /// rustc could not be started.
    #[error("rustc could not be run")]
    NotRun,
    /// rustc failed: its messages.
    #[error("{0}")]
    Failed(String),
    /// The binary could not be put in place.
    #[error("{0}\n")]
    Write(#[from] crate::output::WriteError),
}

/// rustc on `main` with `kane_model` as the kane-model crate, the crate `name`, writing `out`.
fn rustc(
    libs: &Libraries,
    kane_model: &Path,
    package: &Path,
    main: &Path,
    name: &str,
    out: &Path,
) -> Option<Output> {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let extern_ = |krate: &str, path: &Path| format!("{krate}={}", path.display());
    let mut cmd = Command::new(rustc);
    cmd.env("CARGO_MANIFEST_DIR", package)
        .args(["--edition", "2021", "--crate-type", "bin", "--crate-name", name])
        .arg("-C")
        .arg(format!("opt-level={}", libs.opt_level))
        .arg(main)
        .arg("--extern")
        .arg(extern_("gyro_sim", &libs.gyro_sim))
        .arg("--extern")
        .arg(extern_("kane_model", kane_model))
        .arg("--extern")
        .arg(extern_("kane_derive", &libs.kane_derive))
        .arg("-L")
        .arg(format!("dependency={}", libs.deps.display()))
        .arg("-o")
        .arg(out);
    if libs.opt_level != "0" {
        // One unit: no link-time pass over sixteen, and the model inlines into the stepper.
        cmd.args(["-C", "codegen-units=1"]);
    }
    cmd.stderr(Stdio::piped()).output().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn artifact(name: &str, opt: &str, files: &[&str]) -> Value {
        serde_json::json!({"reason": "compiler-artifact", "target": {"name": name},
            "profile": {"opt_level": opt}, "filenames": files})
    }

    #[test]
    fn the_libraries_are_those_built_as_gyro_sim_is() {
        let so = format!("/t/release/deps/libkane_derive-1{}", std::env::consts::DLL_SUFFIX);
        let all = [
            artifact(
                "kane_model",
                "0",
                &["/t/release/deps/libkane_model-h.rlib", "/t/release/deps/libkane_model-h.rmeta"],
            ),
            artifact(
                "kane_model",
                "3",
                &["/t/release/deps/libkane_model-r.rlib", "/t/release/deps/libkane_model-r.rmeta"],
            ),
            artifact("kane_derive", "0", &[so.as_str()]),
            artifact(
                "gyro_sim",
                "3",
                &["/t/release/libgyro_sim.rlib", "/t/release/deps/libgyro_sim-g.rmeta"],
            ),
        ];
        let libs = pick(&all).unwrap();
        assert_eq!(
            libs.kane_model[0],
            Path::new("/t/release/deps/libkane_model-r.rlib"),
            "gyro-sim's profile first"
        );
        assert_eq!(libs.kane_model.len(), 2);
        assert_eq!(libs.gyro_sim, Path::new("/t/release/libgyro_sim.rlib"));
        assert_eq!(libs.deps, Path::new("/t/release/deps"), "where the dependencies are");
        assert_eq!(libs.kane_derive, Path::new(&so));
        assert_eq!(libs.opt_level, "3");
        assert!(pick(&all[1..]).is_some() && pick(&all[..3]).is_none(), "gyro-sim is needed");
    }
}
