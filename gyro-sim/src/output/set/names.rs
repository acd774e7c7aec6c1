//! The names in a set's folder and its work folder (the set's files, the commit lock), shared by
//! the set's parts.

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
