//! Output sets, committed whole: a run's files (CSV, figures, view) appear in its output folder
//! `OUT` together or not at all, as SQLite's and Git's commits do, so that a run killed at any
//! instant leaves the folder's earlier set or its new one, never a mix of the two.
//!
//! The design. A set is written into a staging folder in the work folder
//! `PARENT/.OUT.gyro-sim/`, beside `OUT` on the same filesystem, and made visible by one atomic
//! step: the staging folder and `OUT` exchange places (`renameat2(RENAME_EXCHANGE)` on Linux,
//! `renameatx_np(RENAME_SWAP)` on macOS). The earlier set, now in the work folder, is removed after.
//! Where the filesystem cannot exchange (NFS, other systems) `OUT` is renamed into the work folder
//! and the staging folder renamed to `OUT`: a kill between the two renames leaves no `OUT` until
//! the next run into it puts the earlier set back. Set files that are symbolic links into a folder
//! per set (one link switched) would be atomic too, and were not chosen: the files users open,
//! copy, archive, commit or share would be links, copied as links they dangle, and filesystems
//! without links (FAT, SMB shares) could not hold the folder.
//!
//! Other files in `OUT` (notes, a sweep's files) are in it at every instant: each is hard-linked
//! into the staging folder before the exchange. Folders in `OUT` cannot be linked and are refused,
//! named, before the run. A file made in `OUT` during a commit goes with the earlier set and is
//! moved back after the exchange; a kill at that instant leaves it in the work folder until the
//! next commit moves it back. Nothing there is deleted unless it is a set file or also in `OUT`.
//!
//! Each staging folder has a lock file beside it that its run holds for its life: the kernel
//! releases it when the process dies, and NFS clients emulate it with byte-range locks that hold
//! across hosts. A commit removes the staging folders whose lock it can take (abandoned by a killed
//! run) and no others; process ids are never trusted. Commits into one folder are serialised by
//! the work folder's `commit.lock`, which the exchange does not move. A failed or interrupted run's
//! rows are put in `OUT` as `trajectory.partial.csv` by one rename, the earlier set left as it was.
//!
//! What it costs: `OUT` is a new folder after each commit, so a shell whose working folder is `OUT`
//! is left in the removed one (`cd .` again); `OUT`'s permission bits are carried over, its owner
//! and extended attributes are not; `OUT` must be on its parent's filesystem (not a mount point).

mod error;
mod foreign;
mod names;
mod owner;
mod swap;
#[cfg(test)]
mod tests;

use std::fs::{self, File, OpenOptions};
use std::path::{Path, PathBuf};

pub use error::SetError;
use names::COMMIT_LOCK;
pub use names::PARTIAL_CSV;
use owner::Owner;

/// Where a set goes: the output folder as given and resolved, and the work folder beside it.
struct Place {
    shown: PathBuf,
    out: PathBuf,
    work: PathBuf,
}

impl Place {
    /// The place of the output folder `dir` (which may not exist yet); the work folder is made.
    fn of(dir: &Path) -> Result<Place, SetError> {
        let out = match fs::canonicalize(dir) {
            Ok(out) => out,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                let Some(name) = dir.file_name() else {
                    return Err(SetError::Unnamed { dir: dir.to_path_buf() });
                };
                let parent = dir.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
                let made = fs::create_dir_all(parent).and_then(|_| fs::canonicalize(parent));
                made.map_err(|source| SetError::Parent { parent: parent.to_path_buf(), source })?.join(name)
            }
            Err(source) => return Err(SetError::Open { dir: dir.to_path_buf(), source }),
        };
        let (Some(parent), Some(name)) = (out.parent(), out.file_name()) else {
            return Err(SetError::Root { dir: dir.to_path_buf() });
        };
        let work = parent.join(format!(".{}.gyro-sim", name.to_string_lossy()));
        if let Err(source) = fs::create_dir(&work) {
            if source.kind() != std::io::ErrorKind::AlreadyExists {
                return Err(SetError::Work { work, source });
            }
        }
        Ok(Place { shown: dir.to_path_buf(), out, work })
    }

    /// Takes the commit lock (held while the result lives) and settles abandoned staging (an
    /// interrupted commit's earlier set put back); the output folder exists after.
    fn enter(&self) -> Result<File, SetError> {
        let path = self.work.join(COMMIT_LOCK);
        let open = OpenOptions::new().read(true).write(true).create(true).truncate(false).open(&path);
        let lock = open.map_err(|e| SetError::io(&path, e))?;
        lock.lock().map_err(|e| SetError::io(&path, e))?;
        owner::remove_abandoned(&self.work, &self.out);
        let made = fs::create_dir_all(&self.out);
        made.map_err(|source| SetError::Make { dir: self.shown.clone(), source })?;
        Ok(lock)
    }
}

/// An error unless `out` and `work` are on one filesystem (a set is swapped in by a rename).
fn same_filesystem(out: &Path, work: &Path) -> Result<(), SetError> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let dev = |p: &Path| fs::metadata(p).map(|m| m.dev()).map_err(|e| SetError::io(p, e));
        if dev(out)? != dev(work)? {
            return Err(SetError::OtherFilesystem { out: out.to_path_buf(), work: work.to_path_buf() });
        }
    }
    let _ = (out, work);
    Ok(())
}

/// A set staged for a folder; removed unless [`Staging::commit`] put it in place.
pub(crate) struct Staging {
    place: Place,
    owner: Owner,
}

impl Staging {
    /// A new staging folder for the output folder `dir` (made if missing).
    pub(crate) fn new(dir: &Path) -> Result<Staging, SetError> {
        let place = Place::of(dir)?;
        if fs::symlink_metadata(&place.out).is_err() {
            drop(place.enter()?);
        }
        if !place.out.is_dir() {
            return Err(SetError::NotAFolder { dir: dir.to_path_buf() });
        }
        same_filesystem(&place.out, &place.work)?;
        foreign::refuse_folders(&place.out)?;
        let owner = Owner::create(&place.work, &place.out)?;
        Ok(Staging { place, owner })
    }

    /// Where to write the file that will be `dir/name`.
    pub(crate) fn path(&self, name: &str) -> PathBuf {
        self.owner.dir().join(name)
    }

    /// Puts the staged file `name` in place as `dir/as_name` by one rename, leaving the folder's
    /// set as it is; the rest of the staging is dropped.
    pub(crate) fn commit_one(self, name: &str, as_name: &str) -> Result<PathBuf, SetError> {
        let _lock = self.place.enter()?;
        let target = self.place.out.join(as_name);
        fs::rename(self.path(name), &target).map_err(|e| SetError::io(&target, e))?;
        let shown = self.place.shown.join(as_name);
        drop(self);
        Ok(shown)
    }

    /// Makes the staged set the folder's set in one atomic step, the folder's other files kept.
    pub(crate) fn commit(self) -> Result<(), SetError> {
        let _lock = self.place.enter()?;
        let (stage, out) = (self.owner.dir(), &self.place.out);
        foreign::link_into(out, stage)?;
        let permissions = fs::metadata(out).map_err(|e| SetError::io(out, e))?.permissions();
        fs::set_permissions(stage, permissions).map_err(|e| SetError::io(stage, e))?;
        swap::swap(stage, out, &self.owner.old())?;
        // The owner, dropped under the lock, finds the earlier set in its place and removes it.
        drop(self);
        Ok(())
    }
}
