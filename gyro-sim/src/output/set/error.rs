//! Why an output set could not be staged or put in place: each variant names the folder or file
//! and keeps the system's error as its source, and says what to do.

use std::path::PathBuf;

use thiserror::Error;

/// Why an output set could not be staged or put in place.
#[derive(Debug, Error)]
pub enum SetError {
    /// A file or folder of the set, or of its work folder, could not be used.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder has no name (`.`, `..` or a root).
    #[error("{}: give the output folder by its name", dir.display())]
    Unnamed {
        /// The folder as given.
        dir: PathBuf,
    },
    /// The output folder's parent could not be made.
    #[error("{}: cannot make the output folder's parent: {source}", parent.display())]
    Parent {
        /// The parent.
        parent: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder could not be opened.
    #[error("{}: cannot open the output folder: {source}", dir.display())]
    Open {
        /// The folder as given.
        dir: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder is a root, which cannot be replaced.
    #[error("{}: a run replaces its output folder whole; give a folder inside it", dir.display())]
    Root {
        /// The folder as given.
        dir: PathBuf,
    },
    /// The work folder beside the output folder could not be made.
    #[error("{}: cannot make the folder sets are staged in, beside the output folder: {source}; the output folder's parent must be writable", work.display())]
    Work {
        /// The work folder.
        work: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder could not be made.
    #[error("{}: cannot make the output folder: {source}", dir.display())]
    Make {
        /// The folder as given.
        dir: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder is not on its parent's filesystem.
    #[error("{}: a mount point or on another filesystem than its parent; a run's set is staged in {} and swapped in whole, which needs one filesystem: give a folder inside it as the output", out.display(), work.display())]
    OtherFilesystem {
        /// The output folder.
        out: PathBuf,
        /// The work folder.
        work: PathBuf,
    },
    /// The output is not a folder.
    #[error("{}: not a folder; give a folder as the output", dir.display())]
    NotAFolder {
        /// The output as given.
        dir: PathBuf,
    },
    /// The output folder holds folders, which a set cannot carry across.
    #[error("{}: holds folders that are not part of a run's results ({}); a run replaces its output folder whole and keeps only the files in it: move them elsewhere or give another output folder", out.display(), folders.join(", "))]
    HoldsFolders {
        /// The output folder.
        out: PathBuf,
        /// The folders' names.
        folders: Vec<String>,
    },
    /// A file of the output folder that is not a run's could not be linked into the new set.
    #[error("{}: not a run's file, and it could not be kept across the new set (a hard link as {} failed: {source}); move it out of the output folder or give another one", from.display(), to.display())]
    Keep {
        /// The file.
        from: PathBuf,
        /// The link that failed.
        to: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The staged set and the output folder could not exchange places.
    #[error("{}: the new set could not take this folder's place (exchanging it with {} failed: {source}); the earlier set is unchanged", out.display(), stage.display())]
    Exchange {
        /// The output folder.
        out: PathBuf,
        /// The staged set.
        stage: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The output folder could not be renamed out of the way.
    #[error("{}: the new set could not take this folder's place (renaming it to {} failed: {source})", out.display(), old.display())]
    SetAside {
        /// The output folder.
        out: PathBuf,
        /// Where it was to go.
        old: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// The staged set could not be renamed into the output folder's place.
    #[error("{}: the new set could not take this folder's place (renaming {} to it failed: {source}); {}", out.display(), stage.display(), put_back(old, back.as_ref()))]
    PutInPlace {
        /// The output folder.
        out: PathBuf,
        /// The staged set.
        stage: PathBuf,
        /// Where the earlier set was put.
        old: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
        /// Why the earlier set could not be renamed back, if it could not.
        back: Option<std::io::Error>,
    },
    /// No staging name was free.
    #[error("{}: every staging name tried was taken; remove the folder's leftovers", work.display())]
    NamesTaken {
        /// The work folder.
        work: PathBuf,
    },
    /// The staging folder vanished as soon as it was made.
    #[error("{}: made, then gone", dir.display())]
    Vanished {
        /// The staging folder.
        dir: PathBuf,
    },
}

impl SetError {
    /// The system's error `source` at `path`.
    pub(super) fn io(path: impl Into<PathBuf>, source: std::io::Error) -> SetError {
        SetError::Io { path: path.into(), source }
    }
}

/// Where the earlier set is after a failed rename into place: unchanged, or at `old` when
/// renaming it back failed with `back`.
fn put_back(old: &std::path::Path, back: Option<&std::io::Error>) -> String {
    match back {
        None => "the earlier set is unchanged".to_string(),
        Some(b) => format!("the earlier set is in {} ({b}); rename it back", old.display()),
    }
}
