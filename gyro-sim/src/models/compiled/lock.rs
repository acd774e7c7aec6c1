//! Whether another cargo holds the build folder a model's build needs: in comes the target
//! folder and profile; out goes what to tell the user before the build waits on it.

use std::fs::{File, TryLockError};
use std::path::Path;

/// A note for the user when another process holds cargo's lock on `target`'s folder of
/// `folder` (a profile's), None when it is free or cannot be told.
pub(super) fn wait_note(target: &Path, folder: &str) -> Option<String> {
    let lock = target.join(folder).join(".cargo-lock");
    let file = File::open(&lock).ok()?;
    match file.try_lock() {
        Err(TryLockError::WouldBlock) => Some(format!(
            "another cargo (a build or test of this workspace) is using {}; the model's build starts when it \
             finishes. `--engine jit` (the default) runs the model now, with nothing to build.",
            target.join(folder).display()
        )),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_held_build_folder_is_named_and_a_free_one_is_not() {
        let target = std::env::temp_dir().join(format!("gyro-sim-lock-{}", std::process::id()));
        std::fs::create_dir_all(target.join("release")).unwrap();
        let holder = File::create(target.join("release").join(".cargo-lock")).unwrap();
        assert_eq!(wait_note(&target, "release"), None);
        holder.lock().unwrap();
        let note = wait_note(&target, "release").expect("a held lock is reported");
        assert!(note.contains("another cargo") && note.contains("--engine jit"), "{note}");
        holder.unlock().unwrap();
        assert_eq!(wait_note(&target, "release"), None);
        assert_eq!(wait_note(&target, "debug"), None, "no lock file: nothing to wait for");
        std::fs::remove_dir_all(&target).unwrap();
    }
}
