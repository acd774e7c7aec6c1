//! One sweep per folder at a time: in comes a sweep's folder; out goes a lock on its
//! `sweep.lock`, held until dropped (the kernel drops it when the process dies), so a second
//! sweep into the folder is refused at once instead of sharing (and deleting) the first's journal.
//! Taking it removes the temporaries a killed sweep left there (none can be live: the lock is free).

use std::fs::{File, OpenOptions, TryLockError};
use std::path::Path;

use super::SweepError;

/// The lock file's name in a sweep's folder (left in place: removing it would race).
pub const LOCK_FILE: &str = "sweep.lock";

/// A held lock on a sweep's folder.
#[derive(Debug)]
pub struct FolderLock {
    _file: File,
}

impl FolderLock {
    /// Takes the lock on `dir` (which must exist), or says which folder is busy.
    pub fn take(dir: &Path) -> Result<FolderLock, SweepError> {
        let path = dir.join(LOCK_FILE);
        let file = OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&path)
            .map_err(|e| SweepError::io(&path, e))?;
        match file.try_lock() {
            Ok(()) => {
                let own = ["sweep.csv", "timing.csv", super::PLAN_FILE, super::sorted_runs::RUN_NAME];
                crate::output::remove_temporaries(dir, &own)?;
                Ok(FolderLock { _file: file })
            }
            Err(TryLockError::WouldBlock) => Err(SweepError::Busy { dir: dir.to_path_buf(), lock: path }),
            Err(TryLockError::Error(source)) => Err(SweepError::Lock { path, source }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_lock_on_a_folder_is_refused_until_the_first_is_dropped() {
        let dir = std::env::temp_dir().join(format!("lock-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let first = FolderLock::take(&dir).unwrap();
        let e = FolderLock::take(&dir).unwrap_err().to_string();
        assert!(e.contains(&format!("another sweep is running in {}", dir.display())), "{e}");
        drop(first);
        FolderLock::take(&dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
