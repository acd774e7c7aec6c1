//! Scenes: in comes a TOML file's text; out goes a validated [`Scene`] naming a model, its
//! parameters, the initial state (with units, and optionally a top's motion EJS style in an
//! `[axle]` table, converted when the scene is resolved), the time span, the integrator and the
//! outputs wanted; or a [`SceneError`] at the file's line and column.
//!
//! Files: this one what a scene holds; `parse` reading and checking the TOML; `text` errors at a
//! span of it; `controls` the `[[controls]]` and moving their values; `event_decls` the
//! `[[events]]` tables; `specified_table` a SPECIFIED quantity's table; `view_spec` the `[view]`, `view_drawing`
//! a model's default drawing in it;
//! `grid` the output times.

mod controls;
mod event_decls;
mod grid;
mod parse;
mod specified_table;
mod text;
mod typed;
mod view_drawing;
mod view_length;
mod view_spec;

pub use event_decls::{Direction, EventDecl, EventSource, Preset};
pub use grid::{output_times, plot_times, too_many_rows};
pub(crate) use text::keep;
pub use text::SceneError;
pub use view_spec::{
    ArrowView, BodyView, Length, Orientation, PointView, Shape, TraceView, ViewError, ViewSpec,
};

use std::path::PathBuf;

use text::{error_at, Span};

use crate::ode::MethodInfo;

/// A scene, validated.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The file it came from.
    pub path: PathBuf,
    /// Its text (for error locations).
    pub source: String,
    /// A title for plots.
    pub title: String,
    /// The model's name.
    pub model: String,
    /// Where the model is named.
    pub model_span: std::ops::Range<usize>,
    /// Parameters to set: name, value in the model's units, where.
    pub parameters: Vec<(String, Value, std::ops::Range<usize>)>,
    /// Initial values to set.
    pub initial: Vec<(String, Value, std::ops::Range<usize>)>,
    /// Formulas for a model file's SPECIFIED quantities (`[specified]`, `T = "-K*Q"`): model
    /// text, in the file's names, appended to the file.
    pub specified: Vec<(String, String, std::ops::Range<usize>)>,
    /// A symmetric top's initial motion, EJS style (`[axle]`).
    pub axle: Option<Axle>,
    /// A 3-D view to write beside the results (`[view]`, see [`ViewSpec`]).
    pub view: Option<ViewSpec>,
    /// Where `[view]` is (empty when none).
    pub view_span: std::ops::Range<usize>,
    /// End time (start is 0).
    pub t_final: f64,
    /// Output step.
    pub output_step: f64,
    /// Points per output interval the figures are drawn from (dense output; 1: the rows alone);
    /// none given: dense where the integrator steps several times per row.
    pub plot_points: Option<usize>,
    /// Outputs asked for (state or output names); empty means all.
    pub outputs: Vec<(String, std::ops::Range<usize>)>,
    /// The integrator and its settings (`[integrator]`).
    pub integrator: Integrator,
    /// Events to find (`[[events]]`, each an `EventDecl`).
    pub events: Vec<EventDecl>,
    /// Values a user may move (`[[controls]]`, the sliders of `gyro-sim serve`).
    pub controls: Vec<Control>,
}

/// A number, with the unit it was given in.
#[derive(Clone, Debug, PartialEq)]
pub struct Value {
    /// The number as written.
    pub number: f64,
    /// The unit written after it, if any (`deg`, `rad/s`, ...).
    pub unit: Option<String>,
}

/// An `[axle]` table: a symmetric top's initial motion as EJS gives it (tilt of the axle from
/// +z, spin about it, precession and nutation rates), converted to Euler parameters and body
/// rates when the scene is resolved.
///
/// With `tilt`, the Euler parameters named by `quaternion` are derived from it, and, when `rates`
/// names the body-rate states, so are the rates (spin, precession, nutation absent are 0).
/// Without `tilt`, the table only says which states are the Euler parameters: `[initial]` gives
/// them, and they must have unit norm.
#[derive(Clone, Debug, PartialEq)]
pub struct Axle {
    /// The axle's angle from +z (space z up), as written.
    pub tilt: Option<(Value, std::ops::Range<usize>)>,
    /// Body rate about the axle (omega3).
    pub spin: Option<(Value, std::ops::Range<usize>)>,
    /// Precession rate (phidot0).
    pub precession: Option<(Value, std::ops::Range<usize>)>,
    /// Nutation rate (thetadot0).
    pub nutation: Option<(Value, std::ops::Range<usize>)>,
    /// The model's Euler-parameter states, scalar first, body -> space (four).
    pub quaternion: Vec<(String, std::ops::Range<usize>)>,
    /// The model's body-axis angular velocity states (three), or none.
    pub rates: Vec<(String, std::ops::Range<usize>)>,
    /// Where the table's `quaternion` key is given.
    pub quaternion_span: std::ops::Range<usize>,
}

impl Axle {
    /// Whether the Euler parameters (and, with `rates`, the rates) are derived from the table.
    pub fn derives(&self) -> bool {
        self.tilt.is_some()
    }
}

/// What a scene takes where it says nothing: a model file's TFINAL, INTEGSTP, ABSERR and RELERR.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneDefaults {
    /// `t_final`.
    pub t_final: Option<f64>,
    /// `output_step`.
    pub output_step: Option<f64>,
    /// `[integrator] rtol`.
    pub rtol: Option<f64>,
    /// `[integrator] atol`.
    pub atol: Option<f64>,
}

/// Integrator settings given outside the scene file (`gyro-sim run --method --rtol --atol`):
/// each one given replaces the `[integrator]` table's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IntegratorOverrides {
    /// The method's name (`auto` picks one by the tolerances).
    pub method: Option<String>,
    /// Relative tolerance.
    pub rtol: Option<f64>,
    /// Absolute tolerance.
    pub atol: Option<f64>,
}

/// Integrator settings.
#[derive(Clone, Debug)]
pub struct Integrator {
    /// The method the scene names, found when it is read: `dop853`, `dopri5`, `vern7`, `vern9`,
    /// `taylor` or `rk4` (`auto`, the default, is picked by the tolerances).
    pub method: &'static MethodInfo,
    /// Relative tolerance (adaptive methods).
    pub rtol: f64,
    /// Absolute tolerance (adaptive methods).
    pub atol: f64,
    /// Step (fixed-step methods).
    pub step: f64,
    /// The accuracy asked of the trajectory (largest error relative to max(1, |value|)),
    /// reached by refining the tolerances until two runs agree to it (adaptive methods).
    pub accuracy: Option<f64>,
    /// Most accepted steps of one integration (`max_steps`, default
    /// [`crate::ode::DEFAULT_MAX_STEPS`]).
    pub max_steps: usize,
}

/// A value of the scene that a user may move within a range (a slider on `gyro-sim serve`'s page).
#[derive(Clone, Debug, PartialEq)]
pub struct Control {
    /// The name as written (`spin`, `U3`, `Y`).
    pub name: String,
    /// The value it moves.
    pub target: Target,
    /// Least value, in `unit`.
    pub min: f64,
    /// Greatest value, in `unit`.
    pub max: f64,
    /// The slider's step, in `unit`.
    pub step: f64,
    /// The unit the value is given in (the scene's, `deg`, `rad/s`), if any.
    pub unit: Option<String>,
    /// The value the scene gives, in `unit`.
    pub value: f64,
}

/// The value a control moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The parameter at this index of [`Scene::parameters`].
    Parameter(usize),
    /// The initial value at this index of [`Scene::initial`].
    Initial(usize),
    /// An entry of the `[axle]` table.
    Axle(AxleKey),
}

/// An `[axle]` entry a control can move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxleKey {
    /// The axle's angle from +z.
    Tilt,
    /// The spin rate.
    Spin,
    /// The precession rate.
    Precession,
    /// The nutation rate.
    Nutation,
}

impl Scene {
    /// An error at a span of this scene's text.
    pub fn error_at(&self, span: Span, message: String, help: &str) -> SceneError {
        error_at(&self.path.display().to_string(), &self.source, span, message, help)
    }

    /// Whether its view draws the model's frames and points (`[view] draw_model = true`).
    pub fn draws_model(&self) -> bool {
        self.view.as_ref().is_some_and(|v| v.draw_model)
    }
}
