//! The one atomic step of a commit: the staged folder takes the output folder's place.

use std::fs;
use std::path::Path;

use super::SetError;

/// Puts the folder `stage` in the place of `out`: by one exchange, after which `stage` names the
/// earlier set; where the filesystem cannot exchange, by renaming `out` to `old` and `stage` to
/// `out`.
pub(super) fn swap(stage: &Path, out: &Path, old: &Path) -> Result<(), SetError> {
    match exchange(stage, out) {
        Ok(()) => Ok(()),
        Err(None) => by_renames(stage, out, old),
        Err(Some(source)) => {
            Err(SetError::Exchange { out: out.to_path_buf(), stage: stage.to_path_buf(), source })
        }
    }
}

/// Exchanges two folders in one step; `Err(None)` where the system or filesystem cannot.
#[cfg(any(target_os = "linux", target_os = "android", target_vendor = "apple"))]
fn exchange(a: &Path, b: &Path) -> Result<(), Option<std::io::Error>> {
    use rustix::fs::{renameat_with, RenameFlags, CWD};
    use rustix::io::Errno;
    match renameat_with(CWD, a, CWD, b, RenameFlags::EXCHANGE) {
        Ok(()) => Ok(()),
        Err(e) if [Errno::INVAL, Errno::NOSYS, Errno::NOTSUP, Errno::OPNOTSUPP].contains(&e) => Err(None),
        Err(e) => Err(Some(e.into())),
    }
}

/// Exchanges two folders in one step; `Err(None)` where the system or filesystem cannot.
#[cfg(not(any(target_os = "linux", target_os = "android", target_vendor = "apple")))]
fn exchange(_: &Path, _: &Path) -> Result<(), Option<std::io::Error>> {
    Err(None)
}

/// The fallback: `out` renamed to `old`, then `stage` to `out`; a kill between the two leaves
/// no `out` until the next commit renames `old` back.
pub(super) fn by_renames(stage: &Path, out: &Path, old: &Path) -> Result<(), SetError> {
    let set_aside = |source| SetError::SetAside { out: out.to_path_buf(), old: old.to_path_buf(), source };
    fs::rename(out, old).map_err(set_aside)?;
    if let Err(source) = fs::rename(stage, out) {
        let back = fs::rename(old, out).err();
        let (out, stage, old) = (out.to_path_buf(), stage.to_path_buf(), old.to_path_buf());
        return Err(SetError::PutInPlace { out, stage, old, source, back });
    }
    Ok(())
}
