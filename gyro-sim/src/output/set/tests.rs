//! The commit's steps, and what a kill between them leaves.

use std::fs;
use std::path::{Path, PathBuf};

use super::owner::{remove_abandoned, Owner};
use super::{swap, Place, Staging};
use crate::output::unique_temporary;

/// A fresh folder `out` in a fresh test folder; its parent.
fn fresh(name: &str) -> (PathBuf, PathBuf) {
    let top = std::env::temp_dir().join(format!("gyro-sim-set-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&top);
    fs::create_dir_all(top.join("out")).unwrap();
    (top.join("out"), top)
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    names.sort();
    names
}

fn read(path: PathBuf) -> String {
    fs::read_to_string(path).unwrap()
}

/// A staging of `files` (name, text) for `out`, not committed.
fn staged(out: &Path, files: &[(&str, &str)]) -> Staging {
    let staging = Staging::new(out).unwrap();
    for (name, text) in files {
        fs::write(staging.path(name), text).unwrap();
    }
    staging
}

#[test]
fn temporaries_are_unique_and_an_uncommitted_set_leaves_nothing() {
    assert_ne!(unique_temporary("a.csv"), unique_temporary("a.csv"));
    let (out, top) = fresh("uncommitted");
    fs::write(out.join("trajectory.csv"), "old").unwrap();
    drop(staged(&out, &[("trajectory.csv", "new")]));
    assert_eq!(names(&out), ["trajectory.csv"]);
    assert_eq!(read(out.join("trajectory.csv")), "old");
    assert_eq!(names(&top.join(".out.gyro-sim")), Vec::<String>::new());
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn a_commit_replaces_the_set_whole_and_keeps_the_other_files() {
    let (out, top) = fresh("commit");
    for (name, text) in
        [("trajectory.csv", "old"), ("view.html", "old"), ("notes.txt", "mine"), (".gyro-sim.lock", "")]
    {
        fs::write(out.join(name), text).unwrap();
    }
    let notes = super::owner::inode(&out.join("notes.txt"));
    staged(&out, &[("trajectory.csv", "new"), ("trajectory.png", "new")]).commit().unwrap();
    assert_eq!(names(&out), ["notes.txt", "trajectory.csv", "trajectory.png"]);
    assert_eq!(read(out.join("trajectory.csv")), "new");
    assert_eq!(super::owner::inode(&out.join("notes.txt")), notes, "the user's file is the same file");
    assert_eq!(names(&top), [".out.gyro-sim", "out"]);
    assert_eq!(names(&top.join(".out.gyro-sim")), ["commit.lock"], "the earlier set is removed");
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn a_folder_inside_the_output_folder_is_refused_by_name() {
    let (out, top) = fresh("refused");
    fs::create_dir(out.join("keep")).unwrap();
    let error = Staging::new(&out).err().unwrap().to_string();
    assert!(error.contains("keep") && error.contains("move them elsewhere"), "{error}");
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn a_partial_csv_goes_in_beside_the_earlier_set() {
    let (out, top) = fresh("partial");
    fs::write(out.join("trajectory.csv"), "old").unwrap();
    let path =
        staged(&out, &[("trajectory.csv", "rows")]).commit_one("trajectory.csv", "trajectory.partial.csv");
    assert_eq!(path.unwrap(), out.join("trajectory.partial.csv"));
    assert_eq!(names(&out), ["trajectory.csv", "trajectory.partial.csv"]);
    assert_eq!(read(out.join("trajectory.csv")), "old");
    assert_eq!(names(&top.join(".out.gyro-sim")), ["commit.lock"]);
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn a_live_runs_staging_is_kept_and_an_abandoned_one_removed() {
    let (out, top) = fresh("liveness");
    let place = Place::of(&out).unwrap();
    let live = Owner::create(&place.work, &place.out).unwrap();
    fs::write(live.dir().join("trajectory.csv"), "rows").unwrap();
    let dead = Owner::create(&place.work, &place.out).unwrap();
    let dead_dir = dead.dir().to_path_buf();
    fs::write(dead_dir.join("trajectory.csv"), "half").unwrap();
    dead.abandon();
    assert!(dead_dir.exists());
    remove_abandoned(&place.work, &place.out);
    assert!(!dead_dir.exists(), "the killed run's staging is still there");
    assert_eq!(read(live.dir().join("trajectory.csv")), "rows", "a live run's staging was touched");
    drop(live);
    assert_eq!(names(&place.work), Vec::<String>::new());
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn a_kill_after_the_exchange_leaves_the_new_set_and_the_next_commit_gives_back_late_files() {
    let (out, top) = fresh("after_exchange");
    fs::write(out.join("trajectory.csv"), "old").unwrap();
    let staging = staged(&out, &[("trajectory.csv", "new")]);
    // A file made in the folder after its files were linked: it leaves with the earlier set.
    fs::write(out.join("late.txt"), "late").unwrap();
    swap::swap(staging.owner.dir(), &out, &staging.owner.old()).unwrap();
    let old = staging.owner.dir().to_path_buf();
    staging.owner.abandon();
    assert_eq!(names(&out), ["trajectory.csv"]);
    assert_eq!(read(out.join("trajectory.csv")), "new");
    staged(&out, &[("trajectory.csv", "newer")]).commit().unwrap();
    assert!(!old.exists());
    assert_eq!(names(&out), ["late.txt", "trajectory.csv"]);
    assert_eq!(read(out.join("late.txt")), "late");
    assert_eq!(names(&top.join(".out.gyro-sim")), ["commit.lock"]);
    fs::remove_dir_all(&top).unwrap();
}

#[test]
fn the_fallback_puts_the_set_in_by_renames_and_a_kill_between_them_is_undone() {
    let (out, top) = fresh("fallback");
    fs::write(out.join("trajectory.csv"), "old").unwrap();
    fs::write(out.join("notes.txt"), "mine").unwrap();
    // Whole: the new set in, the earlier one removed when the owner ends.
    let staging = staged(&out, &[("trajectory.csv", "new")]);
    super::foreign::link_into(&out, staging.owner.dir()).unwrap();
    swap::by_renames(staging.owner.dir(), &out, &staging.owner.old()).unwrap();
    drop(staging);
    assert_eq!(names(&out), ["notes.txt", "trajectory.csv"]);
    assert_eq!(read(out.join("trajectory.csv")), "new");
    assert_eq!(names(&top.join(".out.gyro-sim")), Vec::<String>::new());
    // Killed between the renames: no folder until the next commit puts the earlier set back.
    let staging = staged(&out, &[("trajectory.csv", "newer")]);
    fs::rename(&out, staging.owner.old()).unwrap();
    staging.owner.abandon();
    assert!(!out.exists());
    // The next run puts it back before it stages.
    let next = Staging::new(&top.join("out")).unwrap();
    assert_eq!(names(&out), ["notes.txt", "trajectory.csv"]);
    assert_eq!(read(out.join("trajectory.csv")), "new");
    drop(next);
    assert_eq!(names(&top.join(".out.gyro-sim")), ["commit.lock"]);
    fs::remove_dir_all(&top).unwrap();
}
