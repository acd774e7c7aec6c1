//! Where a file a model file names is: in comes a name and the folder of the file naming it; out
//! goes the path found there or in a folder above it (Autolev's search for run files and for a
//! user function's `.R` file).

use std::path::{Path, PathBuf};

/// `name` relative to `dir`, then to each folder above it; an absolute `name` as it is.
pub(super) fn find(name: &str, dir: Option<&Path>) -> Option<PathBuf> {
    let name = name.replace('\\', "/");
    let relative = Path::new(&name);
    if relative.is_absolute() {
        return relative.is_file().then(|| relative.to_path_buf());
    }
    let mut at = Some(dir.unwrap_or(Path::new("")));
    while let Some(d) = at {
        let candidate = d.join(relative);
        if candidate.is_file() {
            return Some(candidate);
        }
        at = d.parent();
    }
    None
}
