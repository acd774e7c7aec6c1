//! Events: times where an expression of the states, output columns, parameters and `t` crosses
//! zero, found on the integrator's dense output after each accepted step.
//!
//! A scene declares them in `[[events]]` ([`scene`] reads the tables into [`EventDecl`]s, with
//! built-in [`presets`]); [`resolve`] lowers each expression, with its time derivatives, into a
//! kane-model IR section ([`kane_model::codegen::event`]) whose positional inputs it binds to
//! the model's states, output columns (their rates by dual numbers) and parameters, in the units
//! the CSV uses; [`eval`] runs those sections; [`detect`] finds the crossings, every sign change
//! inside a step isolated by [`isolate`] and located by [`root`]; [`watch`] does both after each
//! step of an integration, [`limits`] noting where crossings outran the steps or the rows;
//! [`csv`] writes `events.csv`.

pub mod detect;
pub mod eval;
pub mod isolate;
pub mod limits;
pub mod root;
pub mod watch;

use kane_model::codegen::event::EventCode;

/// Which crossings count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// From negative to positive.
    Up,
    /// From positive to negative.
    Down,
    /// Either.
    Both,
}

/// What a crossing does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Record it and go on.
    Record,
    /// Record it and end the run there.
    Stop,
}

/// A built-in event.
#[derive(Clone, Debug, PartialEq)]
pub enum Preset {
    /// The axle (the body z axis of the `[axle]` quaternion) goes below the horizontal.
    AxleBelowHorizontal,
    /// The axle's elevation has a turning point (nutation extrema).
    NutationTurningPoints,
    /// A gimbal angle comes within `margin` of a lock angle (`lock` + k 180 deg).
    GimbalLock {
        /// The angle's state name and where it is given.
        angle: (String, std::ops::Range<usize>),
        /// The margin, radians.
        margin: f64,
        /// The angle at lock, radians.
        lock: f64,
    },
}

/// Where an event's expression comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum EventSource {
    /// `when = "..."`: its text and where the text starts in the scene (inside the quotes).
    When(String, usize),
    /// `preset = "..."`.
    Preset(Preset),
}

/// One `[[events]]` table, checked for what does not need the model.
#[derive(Clone, Debug, PartialEq)]
pub struct EventDecl {
    /// Its place in `[[events]]`, from 1.
    pub number: usize,
    /// Its name (default `event{number}`, or the preset's name).
    pub name: String,
    /// The expression or preset.
    pub source: EventSource,
    /// Where its `when` or `preset` key's value is.
    pub span: std::ops::Range<usize>,
    /// Which crossings count.
    pub direction: Direction,
    /// What a crossing does.
    pub action: Action,
    /// The run ends at this crossing (stop: default 1).
    pub count: Option<usize>,
}

impl EventDecl {
    /// `[[events]] 2 (`name`)`, for messages.
    pub fn label(&self) -> String {
        format!("[[events]] {} (`{}`)", self.number, self.name)
    }

    /// The crossing the run ends at, if any.
    pub fn stop_after(&self) -> Option<usize> {
        match self.action {
            Action::Stop => Some(self.count.unwrap_or(1)),
            Action::Record => self.count,
        }
    }
}

/// Where an event section's positional input comes from (values in the CSV's units: angles the
/// model gives in degrees scaled to degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    /// Time.
    Time,
    /// State `i` times `scale`.
    State(usize, f64),
    /// The rate of state `i` times `scale`.
    StateRate(usize, f64),
    /// Column `col` of output `k` times `scale`.
    Column(usize, usize, f64),
    /// The rate of column `col` of output `k` times `scale`.
    ColumnRate(usize, usize, f64),
    /// Parameter `i` times `scale`.
    Param(usize, f64),
}

/// An event ready to evaluate.
#[derive(Clone, Debug, PartialEq)]
pub struct EventSpec {
    /// Its name.
    pub name: String,
    /// The lowered expression.
    pub code: EventCode,
    /// What each of its inputs reads.
    pub sources: Vec<Source>,
    /// The crossings watched and when the run ends.
    pub rule: detect::Rule,
    /// The states its value depends on (directly or through outputs).
    pub reads: Vec<usize>,
}

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
