//! Parameter sweeps: in come a scene, the ranges to vary and the members to run (a grid or a
//! Latin-hypercube sample, optionally one shard of them); out go one row per member (the varied
//! values, a status that is `ok` or the named failure, the final state, the minimum and maximum
//! of each written column, the first time of each event, the cost) and its wall time kept apart,
//! so that the rows depend on the inputs alone. Members run in parallel; one member's failure is
//! its row, never the end. A folder holds one sweep: bound to its plan ([`identity`]), locked
//! while it runs ([`lock`]); members are made from their index, finished ones streamed to a
//! journal and from it, by an external sort, into `sweep.csv` ([`finish`](mod@finish)), so memory does not
//! grow with the members beyond one bit each (which are done).

mod error;
mod finish;
pub mod identity;
mod journal;
mod latin;
pub mod lock;
mod member_set;
mod merge;
mod plan;
mod shard;
mod sorted_runs;
pub mod table;

use std::time::Instant;

use rayon::prelude::*;

pub use error::{DesignError, ShardError, SweepError};
pub use finish::finish;
pub use identity::{SweepPlan, PLAN_FILE};
pub use journal::{scan as scan_journal, Journal, JOURNAL_FILE};
pub use member_set::MemberSet;
pub use merge::merge;
pub use plan::{parse_range, Design, Member, Members, Range, MAX_MEMBERS};
pub use shard::Shard;
pub use table::{read_rows, SweepRow};

use crate::models::Registry;
use crate::scene::{Scene, SceneError, Value};

/// The indices below `count` of `shard`'s members not in `done`, in order.
pub fn todo(count: usize, shard: Shard, done: &MemberSet) -> impl Iterator<Item = usize> + Send + '_ {
    (shard.index..count).step_by(shard.count.max(1)).filter(move |m| !done.contains(*m))
}

/// The column names of a sweep's rows after the member index and the varied names: the
/// written columns' final, min and max values, in display units.
pub fn value_columns(scene: &Scene, registry: &Registry) -> Result<Vec<String>, SceneError> {
    let problem = crate::resolve::resolve(scene, registry)?;
    let shown: Vec<String> = crate::solve::columns(&problem)
        .iter()
        .filter(|c| !c.hidden)
        .map(|c| crate::output::column_name(&c.name, &c.unit))
        .collect();
    let mut out = Vec::with_capacity(3 * shown.len());
    for what in ["final", "min", "max"] {
        out.extend(shown.iter().map(|c| format!("{what}_{c}")));
    }
    out.extend(problem.events.iter().map(|e| format!("first_t_{}", e.name)));
    Ok(out)
}

/// Runs the members of `scene` varied over `ranges` whose indices `todo` gives, in parallel,
/// calling `done` with each finished member's row and wall time (ms) as it ends. Once a stop
/// signal is requested no member starts, and one it cut short is not passed to `done`.
pub fn run_members(
    scene: &Scene,
    ranges: &[Range],
    members: &Members,
    todo: impl Iterator<Item = usize> + Send,
    registry: &Registry,
    done: &(dyn Fn(&SweepRow, f64) + Sync),
) {
    todo.par_bridge().for_each(|index| {
        if crate::ode::interrupt::requested().is_some() {
            return;
        }
        let start = Instant::now();
        let row = run_member(scene, ranges, &members.get(index), registry);
        if crate::ode::interrupt::requested().is_some() && row.status.contains("interrupted by") {
            return;
        }
        done(&row, start.elapsed().as_secs_f64() * 1e3);
    });
}

/// One member: the scene with its values, resolved and solved.
fn run_member(scene: &Scene, ranges: &[Range], m: &Member, registry: &Registry) -> SweepRow {
    let varied: Vec<f64> = m.values.iter().map(|v| v.number).collect();
    let failed = |why: String| SweepRow {
        member: m.index,
        varied: varied.clone(),
        status: why,
        values: Vec::new(),
        steps: 0,
        rhs_evals: 0,
    };
    let member_scene = with_values(scene, ranges, &m.values, registry);
    let problem = match crate::resolve::resolve(&member_scene, registry) {
        Ok(p) => p,
        Err(e) => return failed(one_line(&e.to_string())),
    };
    let trajectory = match crate::solve::solve(&problem, None) {
        Ok(t) => t,
        Err(e) => return failed(one_line(&e.to_string())),
    };
    let table = crate::output::display_table(&trajectory);
    let n = table.columns.len();
    let last = table.rows.last().map(|r| r[1..].to_vec()).unwrap_or_else(|| vec![f64::NAN; n]);
    let mut lo = vec![f64::INFINITY; n];
    let mut hi = vec![f64::NEG_INFINITY; n];
    for r in &table.rows {
        for (k, v) in r[1..].iter().enumerate() {
            lo[k] = lo[k].min(*v);
            hi[k] = hi[k].max(*v);
        }
    }
    let firsts = first_event_times(&trajectory.events);
    let values = [last, lo, hi, firsts].concat();
    SweepRow {
        member: m.index,
        varied,
        status: "ok".into(),
        values,
        steps: trajectory.stats.steps,
        rhs_evals: trajectory.stats.rhs_evals,
    }
}

/// The time each declared event first happened (NaN: never).
fn first_event_times(log: &crate::problem::EventLog) -> Vec<f64> {
    (0..log.names.len())
        .map(|i| log.records.iter().find(|r| r.event == i).map_or(f64::NAN, |r| r.row[0]))
        .collect()
}

/// `scene` with each range's value set: a state's under `[initial]`, anything else under
/// `[parameters]` (replacing what the scene gave).
fn with_values(scene: &Scene, ranges: &[Range], values: &[Value], registry: &Registry) -> Scene {
    let mut s = scene.clone();
    let is_state = |name: &str| registry.find(&scene.model).is_some_and(|e| e.info().state(name).is_some());
    for (r, v) in ranges.iter().zip(values) {
        let table = if is_state(&r.name) { &mut s.initial } else { &mut s.parameters };
        table.retain(|(n, _, _)| !n.eq_ignore_ascii_case(&r.name));
        table.push((r.name.clone(), v.clone(), 0..0));
    }
    s
}

/// An error message on one line (for a CSV cell).
fn one_line(message: &str) -> String {
    message.lines().map(str::trim).filter(|l| !l.is_empty()).collect::<Vec<_>>().join(" / ")
}
