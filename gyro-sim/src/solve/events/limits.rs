//! What a run's events outran: in come each crossing recorded and each step where an event's
//! isolation stayed unsettled; out go, per event, the first place its sign changes came closer
//! together than the steps could resolve ([`Unsettled`]) and the most crossings that fell
//! between two output rows ([`Crowded`]), for the summary's warnings.

use crate::problem::{Crowded, EventLog, Unsettled};

/// One event's crossings in the current output interval.
#[derive(Clone, Copy, Debug, Default)]
struct Interval {
    /// The output time ending it (its index in the output times).
    ends_at: usize,
    /// Crossings in it so far.
    count: usize,
    /// The last one's time.
    last: f64,
}

/// The limits met so far.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    intervals: Vec<Option<Interval>>,
    unsettled: Vec<Option<Unsettled>>,
    crowded: Vec<Option<Crowded>>,
    /// Something was noted since the last [`Limits::write_into`].
    changed: bool,
}

impl Limits {
    /// For `events` events.
    pub fn new(events: usize) -> Limits {
        Limits {
            intervals: vec![None; events],
            unsettled: vec![None; events],
            crowded: vec![None; events],
            changed: false,
        }
    }

    /// Event `event` stayed unsettled in a part of `width` starting at `t`.
    pub fn unsettled(&mut self, event: usize, t: f64, width: f64) {
        let u = self.unsettled[event].get_or_insert(Unsettled { event, t, width, steps: 0 });
        u.steps += 1;
        u.width = u.width.min(width);
        self.changed = true;
    }

    /// Event `event` crossed at `t`; `times` are the run's output times.
    pub fn crossing(&mut self, event: usize, t: f64, times: &[f64]) {
        let ends_at = times.partition_point(|x| *x < t);
        let slot = &mut self.intervals[event];
        let Some(interval) = slot.as_mut().filter(|i| i.ends_at == ends_at) else {
            *slot = Some(Interval { ends_at, count: 1, last: t });
            return;
        };
        interval.count += 1;
        let gap = t - interval.last;
        interval.last = t;
        let rows = ends_at.checked_sub(1).and_then(|k| Some((times[k], *times.get(ends_at)?)));
        let (from, to) = rows.unwrap_or((f64::NAN, f64::NAN));
        let c = self.crowded[event].get_or_insert(Crowded { event, from, to, most: 0, gap });
        if interval.count > c.most {
            (c.from, c.to, c.most) = (from, to, interval.count);
        }
        c.gap = c.gap.min(gap);
        self.changed = true;
    }

    /// The limits met into `log` (each event's at most once per kind, in event order), when
    /// any was noted since the last call.
    pub fn write_into(&mut self, log: &mut EventLog) {
        if std::mem::take(&mut self.changed) {
            log.unsettled = self.unsettled.iter().flatten().copied().collect();
            log.crowded = self.crowded.iter().flatten().copied().collect();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_between_two_rows_are_counted_and_their_closest_gap_kept() {
        let times = [0.0, 1.0, 2.0, 3.0];
        let mut l = Limits::new(2);
        for t in [0.5, 1.2, 1.5, 1.6, 2.5] {
            l.crossing(0, t, &times);
        }
        l.crossing(1, 0.5, &times);
        l.crossing(1, 1.5, &times);
        l.unsettled(1, 2.25, 1e-9);
        l.unsettled(1, 2.75, 1e-10);
        let mut log = EventLog::default();
        l.write_into(&mut log);
        assert_eq!(log.crowded.len(), 1);
        let c = &log.crowded[0];
        assert_eq!((c.event, c.from, c.to, c.most), (0, 1.0, 2.0, 3));
        assert!((c.gap - 0.1).abs() < 1e-12, "{}", c.gap);
        assert_eq!(log.unsettled, [Unsettled { event: 1, t: 2.25, width: 1e-10, steps: 2 }]);
    }
}
