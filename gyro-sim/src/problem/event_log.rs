//! The events of a run, as the trajectory carries them: every crossing found, the one that
//! ended the run, and where the crossings outran the steps or the rows.

/// An event that happened.
#[derive(Clone, Debug, PartialEq)]
pub struct EventRecord {
    /// Which event (an index into the problem's events).
    pub event: usize,
    /// Its name.
    pub name: String,
    /// Whether its value went up through zero.
    pub rising: bool,
    /// The time, then the columns, as a trajectory row.
    pub row: Vec<f64>,
}

/// The events of a run.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EventLog {
    /// The names of the events declared, in order.
    pub names: Vec<String>,
    /// Every crossing, in time order.
    pub records: Vec<EventRecord>,
    /// The event that ended the run and when, if one did.
    pub stopped: Option<(String, f64)>,
    /// Events whose sign changes came closer together than the steps could resolve.
    pub unsettled: Vec<Unsettled>,
    /// Events that crossed zero more than once between two output rows.
    pub crowded: Vec<Crowded>,
}

/// Where an event's sign changes may have been missed: its isolation reached the finest split
/// of a step without settling (two sign changes closer than `width`, or a zero touched without
/// crossing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Unsettled {
    /// Which event.
    pub event: usize,
    /// Where, first.
    pub t: f64,
    /// The narrowest part left unsettled, seconds.
    pub width: f64,
    /// In how many steps.
    pub steps: usize,
}

/// An event that crossed zero more than once between two output rows, which the rows cannot
/// show (`events.csv` lists each crossing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crowded {
    /// Which event.
    pub event: usize,
    /// The output interval with the most crossings: from this row's time...
    pub from: f64,
    /// ... to this one's.
    pub to: f64,
    /// How many crossings it held.
    pub most: usize,
    /// The closest two crossings between one pair of rows, seconds apart.
    pub gap: f64,
}
