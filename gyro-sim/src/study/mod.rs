//! Studies of many runs of one scene: in come a scene and what to vary or measure; out go
//! tables and figures. `sweep` runs members with varied values (a grid or a Latin hypercube,
//! sharded, journaled, merged into `sweep.csv`); `batch` integrates members in lock step through
//! a generated model's lanes; `work_precision` measures every method's error against its time.

pub(crate) mod batch;
pub(crate) mod sweep;
pub(crate) mod work_precision;
