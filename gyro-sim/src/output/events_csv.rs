//! `events.csv`: one row per event that happened, in time order: its name, whether its value
//! went up or down through zero, the time, then the trajectory's written columns at that time
//! in the CSV's units (the headers of `trajectory.csv`).

use std::path::Path;

use super::{column_name, write_atomically, WriteError};
use crate::problem::Trajectory;
use kane_model::lang::units::size::shown_per_internal;

/// Writes the events of `trajectory` to `path` (atomically); a header alone when none happened.
pub fn write_events_csv(trajectory: &Trajectory, path: &Path) -> Result<(), WriteError> {
    let shown: Vec<usize> =
        (0..trajectory.columns.len()).filter(|k| !trajectory.columns[*k].hidden).collect();
    write_atomically(path, |tmp| {
        let fail = |e: csv::Error| WriteError::csv(tmp, e);
        let mut w = csv::Writer::from_path(tmp).map_err(fail)?;
        let mut header = vec!["event".to_string(), "direction".to_string(), "t".to_string()];
        header.extend(shown.iter().map(|k| {
            let c = &trajectory.columns[*k];
            column_name(&c.name, &c.unit)
        }));
        w.write_record(&header).map_err(fail)?;
        for r in &trajectory.events.records {
            let mut record = vec![r.name.clone(), if r.rising { "up" } else { "down" }.to_string()];
            record.push(r.row[0].to_string());
            for k in &shown {
                let c = &trajectory.columns[*k];
                let v = r.row[k + 1];
                record.push((v * shown_per_internal(&c.unit)).to_string());
            }
            w.write_record(&record).map_err(fail)?;
        }
        w.flush().map_err(|e| WriteError::io(tmp, e))
    })
}
