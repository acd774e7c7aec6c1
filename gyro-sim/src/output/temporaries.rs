//! Files put in place whole: in comes a file's path and what writes it; the writing goes to a
//! temporary beside it (`.partial-{pid}-{random}-NAME`, a name no other process or call uses)
//! renamed over the path at the end. The one place that names temporaries also recognises and
//! removes those a killed process left.

use std::hash::{BuildHasher, Hasher};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

use super::WriteError;

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// A number no other call, here or in another process on any host, is likely to draw (the
/// standard library seeds its hash keys from the system's random source).
pub(crate) fn random() -> u64 {
    let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
    hasher.write_u64(COUNTER.fetch_add(1, Ordering::Relaxed));
    hasher.write_u32(std::process::id());
    hasher.finish()
}

/// `.partial-{pid}-{random}-{name}`: a temporary name no other process, and no other call here, uses.
pub(crate) fn unique_temporary(name: &str) -> String {
    format!(".partial-{}-{:016x}-{name}", std::process::id(), random())
}

/// Whether `file_name` is a temporary [`unique_temporary`] made for `name`.
pub(crate) fn is_temporary_of(file_name: &str, name: &str) -> bool {
    file_name.starts_with(".partial-") && file_name.ends_with(&format!("-{name}"))
}

/// Removes from `dir` the temporaries (`.partial-{pid}-{random}-NAME`) of the files `names`.
pub(crate) fn remove_temporaries(dir: &Path, names: &[&str]) -> Result<(), WriteError> {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(WriteError::io(dir, e)),
    };
    for entry in entries {
        let entry = entry.map_err(|e| WriteError::io(dir, e))?;
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if names.iter().any(|n| is_temporary_of(&name, n)) {
            let path = entry.path();
            std::fs::remove_file(&path).map_err(|e| WriteError::io(&path, e))?;
        }
    }
    Ok(())
}

/// Writes `path` through a temporary file in the same folder, named for this process and call,
/// and a rename; `write` writes the temporary, and its error (or the rename's) is returned.
pub(crate) fn write_atomically<E: From<WriteError>>(
    path: &Path,
    write: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    // The temporary keeps the real extension last: encoders choose the format from it.
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("output");
    let tmp = path.with_file_name(unique_temporary(name));
    let result =
        write(&tmp).and_then(|_| std::fs::rename(&tmp, path).map_err(|e| E::from(WriteError::io(path, e))));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes `bytes` to `path` through [`write_atomically`].
pub(crate) fn write_file_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    write_atomically(path, |tmp| std::fs::write(tmp, bytes).map_err(|e| WriteError::io(tmp, e)))
}
