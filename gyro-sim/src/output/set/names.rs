//! The names in a set's folder and its work folder (the set's files, the commit lock), and the
//! text of an error at a path, shared by the set's parts.

use std::path::Path;

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

/// The file in the work folder whose lock serialises commits.
pub(super) const COMMIT_LOCK: &str = "commit.lock";

/// `path: what failed`.
pub(super) fn fail(path: &Path, e: std::io::Error) -> String {
    format!("{}: {e}", path.display())
}
