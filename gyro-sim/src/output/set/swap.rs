//! The one atomic step of a commit: the staged folder takes the output folder's place.

use std::fs;
use std::path::Path;

/// Puts the folder `stage` in the place of `out`: by one exchange, after which `stage` names the
/// earlier set; where the filesystem cannot exchange, by renaming `out` to `old` and `stage` to
/// `out`.
pub(super) fn swap(stage: &Path, out: &Path, old: &Path) -> Result<(), String> {
    match exchange(stage, out) {
        Ok(()) => Ok(()),
        Err(None) => by_renames(stage, out, old),
        Err(Some(e)) => Err(format!(
            "{}: the new set could not take this folder's place (exchanging it with {} failed: {e}); the earlier set is unchanged",
            out.display(),
            stage.display()
        )),
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
pub(super) fn by_renames(stage: &Path, out: &Path, old: &Path) -> Result<(), String> {
    let failed = |what: &str, e: std::io::Error| {
        format!("{}: the new set could not take this folder's place ({what} failed: {e})", out.display())
    };
    fs::rename(out, old).map_err(|e| failed(&format!("renaming it to {}", old.display()), e))?;
    if let Err(e) = fs::rename(stage, out) {
        let back = match fs::rename(old, out) {
            Ok(()) => "the earlier set is unchanged".to_string(),
            Err(b) => format!("the earlier set is in {} ({b}); rename it back", old.display()),
        };
        return Err(format!("{}; {back}", failed(&format!("renaming {} to it", stage.display()), e)));
    }
    Ok(())
}
