//! Staging folders and their owners: each staging folder `WORK/ID` has a lock file `WORK/ID.lock`
//! beside it, which the run that made it holds for its life and which records the folder's inode.
//! Whoever takes the lock (the owner when done, or a later commit after a kill) settles the
//! folder: a staging folder is removed; a folder that is no longer the staging one (after the
//! exchange it holds the earlier set) gives back the files `OUT` lacks and is removed; `ID.old`
//! (the earlier set after the fallback's first rename) goes back to `OUT` if `OUT` is missing.

use std::fs::{self, File, OpenOptions};
use std::io::{ErrorKind, Read, Write};
use std::path::{Path, PathBuf};

use super::foreign;
use super::names::COMMIT_LOCK;
use super::SetError;
use crate::output::temporaries::random;

/// A staging folder and the lock that says its run is alive.
pub(super) struct Owner {
    dir: PathBuf,
    lock_path: PathBuf,
    /// Held while the owner lives; released (by the kernel too) when it ends.
    lock: File,
    staging: Option<u64>,
    out: PathBuf,
    /// Tests only: drop as a killed run would, leaving everything for a later commit.
    abandoned: bool,
}

impl Owner {
    /// A new staging folder in `work` for the output folder `out`, its lock held.
    pub(super) fn create(work: &Path, out: &Path) -> Result<Owner, SetError> {
        for _ in 0..16 {
            let id = format!("set-{}-{:016x}", std::process::id(), random());
            let lock_path = work.join(format!("{id}.lock"));
            let lock = match OpenOptions::new().read(true).write(true).create_new(true).open(&lock_path) {
                Ok(lock) => lock,
                Err(e) if e.kind() == ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(SetError::io(&lock_path, e)),
            };
            lock.lock().map_err(|e| SetError::io(&lock_path, e))?;
            if !same_file(&lock, &lock_path) {
                continue; // taken for abandoned and removed before it was locked
            }
            let dir = work.join(&id);
            let mut owner =
                Owner { dir, lock_path, lock, staging: None, out: out.to_path_buf(), abandoned: false };
            fs::create_dir(&owner.dir).map_err(|e| SetError::io(&owner.dir, e))?;
            let ino = inode(&owner.dir).ok_or_else(|| SetError::Vanished { dir: owner.dir.clone() })?;
            writeln!(&owner.lock, "{ino}").map_err(|e| SetError::io(&owner.lock_path, e))?;
            owner.staging = Some(ino);
            return Ok(owner);
        }
        Err(SetError::NamesTaken { work: work.to_path_buf() })
    }

    /// The staging folder.
    pub(super) fn dir(&self) -> &Path {
        &self.dir
    }

    /// Where the fallback puts the earlier set during a commit.
    pub(super) fn old(&self) -> PathBuf {
        old_of(&self.dir)
    }

    /// Tests only: ends as a killed run does, its lock released and its folders left.
    #[cfg(test)]
    pub(super) fn abandon(mut self) {
        self.abandoned = true;
    }
}

impl Drop for Owner {
    fn drop(&mut self) {
        if !self.abandoned && settle(&self.dir, self.staging, &self.out) {
            let _ = fs::remove_file(&self.lock_path);
        }
    }
}

/// `ID.old` for the staging folder `ID`.
fn old_of(dir: &Path) -> PathBuf {
    let mut name = dir.file_name().unwrap_or_default().to_os_string();
    name.push(".old");
    dir.with_file_name(name)
}

/// Settles the folders of the owner of `dir` (staging inode `staging`, if recorded) for `out`;
/// whether nothing of them is left.
fn settle(dir: &Path, staging: Option<u64>, out: &Path) -> bool {
    let old = old_of(dir);
    let staged = inode(dir).map(|ino| staging.is_none_or(|s| s == ino));
    if fs::symlink_metadata(&old).is_ok() {
        if staged == Some(true) {
            // Killed between the fallback's renames: the earlier set goes back (over the empty
            // folder a later run made meanwhile, if any).
            if fs::rename(&old, out).is_err() {
                return false;
            }
        } else if !foreign::give_back(&old, out) {
            return false;
        }
    }
    match staged {
        None => true,
        // The staging folder (unrecorded: killed right after making it): our files and links only.
        Some(true) => fs::remove_dir_all(dir).is_ok(),
        // The earlier set, after the exchange.
        Some(false) => foreign::give_back(dir, out),
    }
}

/// Settles the staging folders in `work` whose owners are gone (their locks can be taken); a
/// live owner's, on this host or another, is left alone.
pub(super) fn remove_abandoned(work: &Path, out: &Path) {
    let Ok(entries) = fs::read_dir(work) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(id) = name.strip_suffix(".lock").filter(|_| name != COMMIT_LOCK) else { continue };
        let path = entry.path();
        let Ok(mut lock) = OpenOptions::new().read(true).write(true).open(&path) else { continue };
        if lock.try_lock().is_err() || !same_file(&lock, &path) {
            continue; // alive, or settled by another commit meanwhile
        }
        let mut record = String::new();
        let staging = lock.read_to_string(&mut record).ok().and_then(|_| record.trim().parse().ok());
        if settle(&work.join(id), staging, out) {
            let _ = fs::remove_file(&path);
        }
    }
}

/// The inode of `path` (not following a link), if it exists.
pub(super) fn inode(path: &Path) -> Option<u64> {
    let meta = fs::symlink_metadata(path).ok()?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        Some(meta.ino())
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        Some(0)
    }
}

/// Whether `path` still names the open file `file`.
fn same_file(file: &File, path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let open = file.metadata().map(|m| (m.dev(), m.ino()));
        let named = fs::symlink_metadata(path).map(|m| (m.dev(), m.ino()));
        matches!((open, named), (Ok(a), Ok(b)) if a == b)
    }
    #[cfg(not(unix))]
    {
        let _ = file;
        path.exists()
    }
}
