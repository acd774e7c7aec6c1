//! Studies of many runs.

pub(crate) mod batch;
pub(crate) mod sweep;
pub(crate) mod work_precision;
