//! Output sets: a run's files (CSV, figures, view) are written into a staging folder of their
//! own inside the output folder, named for the process and a counter, and then put in place
//! together under the folder's lock, the files of an earlier set that this one lacks removed.
//! Concurrent runs into one folder never share a temporary name and never interleave their
//! renames; a run that fails while writing leaves the previous set as it was, and the staging
//! left by a killed run is removed by the next run that puts a set in the folder.

use std::fs::{self, File};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The files a run may put in its folder.
pub const SET_FILES: &[&str] = &[
    "trajectory.csv",
    "events.csv",
    "trajectory.png",
    "elevation.png",
    "axle_trace.png",
    "view.html",
    PARTIAL_CSV,
];

/// Where a failed run's rows go, beside the earlier set (removed when a later set is complete).
pub const PARTIAL_CSV: &str = "trajectory.partial.csv";

/// The lock file that serialises putting sets in place.
const LOCK_FILE: &str = ".gyro-sim.lock";

static COUNTER: AtomicU64 = AtomicU64::new(0);

/// `.partial-{pid}-{n}-{name}`: a name no other process, and no other call here, uses.
pub(crate) fn unique_temporary(name: &str) -> String {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    format!(".partial-{}-{n}-{name}", std::process::id())
}

/// Removes the staging folders and files in `dir` of processes that no longer run (a killed
/// run's), found by the process id in their names; where the system does not say which
/// processes run (no `/proc`), nothing.
fn remove_abandoned(dir: &Path) {
    let proc = Path::new("/proc");
    if !proc.join("self").exists() {
        return;
    }
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().to_string();
        let pid = name.strip_prefix(".partial-").and_then(|rest| rest.split('-').next());
        let Some(pid) = pid.and_then(|p| p.parse::<u32>().ok()) else { continue };
        if pid != std::process::id() && !proc.join(pid.to_string()).exists() {
            let path = entry.path();
            let _ = fs::remove_dir_all(&path).or_else(|_| fs::remove_file(&path));
        }
    }
}

/// Files staged for a folder; removed unless [`Staging::commit`] put them in place.
pub(crate) struct Staging {
    dir: PathBuf,
    stage: PathBuf,
    committed: bool,
}

impl Staging {
    /// A new staging folder inside `dir` (both made as needed).
    pub(crate) fn new(dir: &Path) -> Result<Staging, String> {
        let stage = dir.join(unique_temporary("set"));
        fs::create_dir_all(&stage).map_err(|e| format!("{}: {e}", stage.display()))?;
        Ok(Staging { dir: dir.to_path_buf(), stage, committed: false })
    }

    /// Where to write the file that will be `dir/name`.
    pub(crate) fn path(&self, name: &str) -> PathBuf {
        self.stage.join(name)
    }

    /// Puts the staged file `name` in place as `dir/as_name` under the folder's lock, leaving
    /// the other files of the folder as they are; the rest of the staging is dropped.
    pub(crate) fn commit_one(mut self, name: &str, as_name: &str) -> Result<PathBuf, String> {
        let fail = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
        let lock_path = self.dir.join(LOCK_FILE);
        let lock = File::create(&lock_path).map_err(|e| fail(&lock_path, e))?;
        lock.lock().map_err(|e| fail(&lock_path, e))?;
        remove_abandoned(&self.dir);
        let target = self.dir.join(as_name);
        fs::rename(self.stage.join(name), &target).map_err(|e| fail(&target, e))?;
        self.committed = true;
        let _ = fs::remove_dir_all(&self.stage);
        Ok(target)
    }

    /// Puts every staged file in place under the folder's lock and removes the set files it
    /// lacks, so the folder holds one run's set.
    pub(crate) fn commit(mut self) -> Result<(), String> {
        let fail = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
        let lock_path = self.dir.join(LOCK_FILE);
        let lock = File::create(&lock_path).map_err(|e| fail(&lock_path, e))?;
        lock.lock().map_err(|e| fail(&lock_path, e))?;
        remove_abandoned(&self.dir);
        for name in SET_FILES {
            let (staged, target) = (self.stage.join(name), self.dir.join(name));
            if staged.exists() {
                fs::rename(&staged, &target).map_err(|e| fail(&target, e))?;
            } else if target.exists() {
                fs::remove_file(&target).map_err(|e| fail(&target, e))?;
            }
        }
        self.committed = true;
        let _ = fs::remove_dir_all(&self.stage);
        Ok(())
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        if !self.committed {
            let _ = fs::remove_dir_all(&self.stage);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn temporaries_are_unique_and_an_uncommitted_set_leaves_nothing() {
        assert_ne!(unique_temporary("a.csv"), unique_temporary("a.csv"));
        assert!(unique_temporary("a.csv").starts_with(&format!(".partial-{}-", std::process::id())));
        let dir = std::env::temp_dir().join(format!("gyro-sim-set-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("trajectory.csv"), "old").unwrap();
        let staging = Staging::new(&dir).unwrap();
        std::fs::write(staging.path("trajectory.csv"), "new").unwrap();
        drop(staging);
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, ["trajectory.csv"]);
        assert_eq!(std::fs::read_to_string(dir.join("trajectory.csv")).unwrap(), "old");
        let staging = Staging::new(&dir).unwrap();
        std::fs::write(staging.path("trajectory.csv"), "new").unwrap();
        staging.commit().unwrap();
        assert_eq!(std::fs::read_to_string(dir.join("trajectory.csv")).unwrap(), "new");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_killed_runs_staging_is_removed_by_the_next_set() {
        let dir = std::env::temp_dir().join(format!("gyro-sim-abandoned-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        // A process id above Linux's largest (2^22): no such process runs.
        let abandoned = dir.join(".partial-4194999-0-set");
        std::fs::create_dir_all(&abandoned).unwrap();
        std::fs::write(abandoned.join("trajectory.csv"), "half").unwrap();
        // The staging of a process that runs (this one's parent) stays.
        let parent = std::os::unix::process::parent_id();
        let running = dir.join(format!(".partial-{parent}-0-set"));
        std::fs::create_dir_all(&running).unwrap();
        let staging = Staging::new(&dir).unwrap();
        std::fs::write(staging.path("trajectory.csv"), "new").unwrap();
        staging.commit().unwrap();
        if Path::new("/proc/self").exists() {
            assert!(!abandoned.exists(), "the killed run's staging is still there");
        }
        assert!(running.exists(), "a running process's staging was removed");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
