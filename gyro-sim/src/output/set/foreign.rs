//! The entries of an output folder that are not a run's set (a user's notes, a sweep's files):
//! kept in the folder across commits, never lost.

use std::fs::{self, FileType};
use std::path::Path;

use super::names::SET_FILES;
use super::SetError;

/// What an entry of an output folder is to a commit.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A file of a run's set: replaced or removed by the next set.
    Set,
    /// What earlier versions left in the folder (their lock file, staging folders): dropped.
    Retired,
    /// Another file (or link): kept.
    File,
    /// Another folder: kept, but it cannot be linked.
    Folder,
}

fn kind(name: &str, file_type: FileType) -> Kind {
    let folder = file_type.is_dir();
    if !folder && SET_FILES.contains(&name) {
        Kind::Set
    } else if name == ".gyro-sim.lock" || (folder && name.starts_with(".partial-")) {
        Kind::Retired
    } else if folder {
        Kind::Folder
    } else {
        Kind::File
    }
}

/// The names and kinds of `dir`'s entries.
fn entries(dir: &Path) -> Result<Vec<(String, Kind)>, SetError> {
    let read = fs::read_dir(dir).map_err(|e| SetError::io(dir, e))?;
    let mut out = Vec::new();
    for entry in read {
        let entry = entry.map_err(|e| SetError::io(dir, e))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let file_type = entry.file_type().map_err(|e| SetError::io(entry.path(), e))?;
        let kind = kind(&name, file_type);
        out.push((name, kind));
    }
    Ok(out)
}

/// An error naming the folders in `out` that are not a run's (a set replaces the folder whole and
/// carries files only).
pub(super) fn refuse_folders(out: &Path) -> Result<(), SetError> {
    let folders: Vec<String> =
        entries(out)?.into_iter().filter(|(_, k)| *k == Kind::Folder).map(|(name, _)| name).collect();
    if folders.is_empty() {
        return Ok(());
    }
    Err(SetError::HoldsFolders { out: out.to_path_buf(), folders })
}

/// Hard-links the files of `out` that are not set files into the staging folder `stage`, so that
/// they are in the folder before and after the exchange; refuses folders.
pub(super) fn link_into(out: &Path, stage: &Path) -> Result<(), SetError> {
    refuse_folders(out)?;
    for (name, kind) in entries(out)? {
        if kind != Kind::File {
            continue;
        }
        let (from, to) = (out.join(&name), stage.join(&name));
        match fs::hard_link(&from, &to) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {} // removed meanwhile
            Err(source) => return Err(SetError::Keep { from, to, source }),
        }
    }
    Ok(())
}

/// After an exchange, `old` holds the earlier set: the entries in it that `out` lacks (made in
/// `out` during the commit) move into `out`, set files and links of files `out` holds go, and then
/// `old` itself; whether `old` is gone (an entry `out` holds another file of the same name for
/// stays, and `old` with it).
pub(super) fn give_back(old: &Path, out: &Path) -> bool {
    let Ok(list) = entries(old) else { return false };
    for (name, kind) in list {
        let (from, to) = (old.join(&name), out.join(&name));
        let _ = match kind {
            Kind::Set => fs::remove_file(&from),
            Kind::Retired => fs::remove_dir_all(&from).or_else(|_| fs::remove_file(&from)),
            _ if fs::symlink_metadata(&to).is_err() => fs::rename(&from, &to),
            _ if kind == Kind::File && same_entry(&from, &to) => fs::remove_file(&from),
            _ => Ok(()),
        };
    }
    fs::remove_dir(old).is_ok()
}

/// Whether `a` and `b` are links of one file.
fn same_entry(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let id = |p: &Path| fs::symlink_metadata(p).map(|m| (m.dev(), m.ino())).ok();
        id(a).is_some() && id(a) == id(b)
    }
    #[cfg(not(unix))]
    {
        let id = |p: &Path| fs::symlink_metadata(p).and_then(|m| Ok((m.len(), m.modified()?))).ok();
        id(a).is_some() && id(a) == id(b)
    }
}
