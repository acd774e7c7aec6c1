//! What a 3-D view shows: in comes plain data (built in Rust or read from a scene's `[view]`
//! TOML table); out go the checks against a trajectory's column names. Lengths are in model
//! units; a body turns about its origin: the support at the origin, or where its position
//! columns put it. Points are markers at their position columns.

use serde::{Deserialize, Serialize};

pub use super::view_length::Length;

/// What the page draws: bodies, arrows, traces and points.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViewSpec {
    /// The rigid bodies drawn.
    #[serde(default)]
    pub bodies: Vec<BodyView>,
    /// Vectors drawn from the origin, each with a checkbox.
    #[serde(default)]
    pub arrows: Vec<ArrowView>,
    /// Points fixed in a body whose paths are drawn.
    #[serde(default)]
    pub traces: Vec<TraceView>,
    /// Points moving in space, each a marker (and a line to the point it hangs from).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<PointView>,
    /// The space axis drawn upward: 1, 2 or 3, or -1, -2, -3 for the axis pointing down (3
    /// unless given, or the model's drawing gives it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub up: Option<i8>,
    /// The space frame's name, labelling its axes (`N` unless given, or the model's drawing
    /// gives it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame: Option<String>,
    /// Draw the model's frames (axes at their mass centres), bodies (ellipsoids of inertia) and
    /// points (markers joined to the points they were located from) besides anything else
    /// given: a model file's.
    #[serde(default, skip_serializing_if = "is_false")]
    pub draw_model: bool,
}

/// One rigid body: a shape turning with the body's orientation about the body's origin (the
/// support at the origin, unless its position columns move it).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyView {
    /// Its name (a trace names its body with it).
    pub name: String,
    /// Its shape, in body axes.
    pub shape: Shape,
    /// Its colour, `#rrggbb`.
    pub colour: String,
    /// How its axes turn in space (fixed when not given).
    #[serde(default)]
    pub orientation: Orientation,
    /// Where the shape's centre is along the body's axes from the body's origin: `[0, 0, d]` for a
    /// rotor at distance `d` along the body's z axis (`[0, 0, "D"]`: the parameter D's value).
    #[serde(default = "origin")]
    pub offset: [Length; 3],
    /// The columns giving, in space axes, where the body's origin is (at the origin when not
    /// given): a body moving through space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub position: Option<[String; 3]>,
    /// 1 opaque (the default) down to 0 unseen: below 1, arrows inside the body show through.
    #[serde(default = "one")]
    pub opacity: f64,
    /// The body axis (1, 2 or 3, the default) along which the shape's own z axis lies: a
    /// rotor spinning about body y is a cylinder with `axis = 2`.
    #[serde(default = "third")]
    pub axis: u8,
    /// The shape's axes in body axes, a rotation row by row (`B_i . S_j`), in place of `axis`:
    /// an ellipsoid of inertia's principal axes (set by [`ViewSpec::with_inertias`], not read).
    #[serde(default, skip_deserializing, skip_serializing_if = "Option::is_none")]
    pub turn: Option<[f64; 9]>,
}

/// A body's shape in its own axes; cylinders and rods lie along its z axis, rings about it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
pub enum Shape {
    /// An ellipsoid with semi-axes `a`, `b`, `c` along body x, y, z.
    Ellipsoid {
        /// Semi-axis along x.
        a: Length,
        /// Semi-axis along y.
        b: Length,
        /// Semi-axis along z.
        c: Length,
    },
    /// A cylinder about the body's z axis.
    Cylinder {
        /// Its radius.
        radius: Length,
        /// Its whole length along z.
        length: Length,
    },
    /// A box with whole edge lengths along body x, y, z.
    Box {
        /// Edge along x.
        x: Length,
        /// Edge along y.
        y: Length,
        /// Edge along z.
        z: Length,
    },
    /// A thin rod along the body's z axis, centred on the offset.
    Rod {
        /// Its length.
        length: Length,
    },
    /// A ring (torus) about the z axis, in the x-y plane: a gimbal.
    Ring {
        /// Radius of its centre line.
        radius: Length,
        /// Radius of its tube.
        tube: Length,
    },
    /// The body's axes x, y, z (red, green, blue), labelled with its name: a frame.
    Axes {
        /// Their length (unless given, 0.6 of the median distance between joined points, at
        /// most 0.3 of the drawing's size).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        length: Option<Length>,
    },
    /// The uniform solid ellipsoid of the mass and central inertia these columns give at the
    /// run's start: a model's default drawing of a body (an ellipsoid once the run is known,
    /// see [`ViewSpec::with_inertias`]; not read from a scene).
    #[serde(skip_deserializing)]
    Inertia {
        /// The column of the mass.
        mass: String,
        /// The columns of the inertia in body axes: I11, I22, I33, I12, I23, I31.
        inertia: [String; 6],
    },
}

/// Which columns give a body's orientation, body axes to space axes.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Orientation {
    /// The body does not turn: its axes are the space axes.
    #[default]
    Fixed,
    /// A unit quaternion, scalar first, body to space (`Q_E0, Q_E1, Q_E2, Q_E3`).
    Quaternion([String; 4]),
    /// The nine direction cosines `N_i . B_j`, row by row (`C_11, C_12, .., C_33`).
    Dcm([String; 9]),
}

impl Orientation {
    /// The column names it reads (none when fixed).
    pub fn columns(&self) -> &[String] {
        match self {
            Orientation::Fixed => &[],
            Orientation::Quaternion(c) => c,
            Orientation::Dcm(c) => c,
        }
    }
}

/// A vector in space axes drawn as an arrow from the origin.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArrowView {
    /// Its label, beside its checkbox and at its tip (`L`).
    pub label: String,
    /// Its colour, `#rrggbb`.
    pub colour: String,
    /// Its three components in space axes (`L_N1, L_N2, L_N3`).
    pub columns: [String; 3],
    /// Length drawn per unit of the vector.
    #[serde(default = "one")]
    pub scale: f64,
}

fn one() -> f64 {
    1.0
}

fn origin() -> [Length; 3] {
    [Length::Number(0.0), Length::Number(0.0), Length::Number(0.0)]
}

fn third() -> u8 {
    3
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// A point moving in space: a marker at its position, labelled with its name.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointView {
    /// Its name.
    pub name: String,
    /// Its three coordinates in space axes (`P_O_P_N1, P_O_P_N2, P_O_P_N3`).
    pub position: [String; 3],
    /// Its colour, `#rrggbb`.
    pub colour: String,
    /// Another point of the view a line joins it to (the one it was located from).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from: Option<String>,
}

/// A point fixed in a body whose path in space is drawn up to the current time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TraceView {
    /// The body's name.
    pub body: String,
    /// The point in body axes from the body's origin (the axle tip: `[0, 0, length]`).
    pub point: [Length; 3],
    /// Its colour, `#rrggbb`.
    pub colour: String,
}

/// Why a view cannot be drawn from a trajectory.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ViewError {
    /// A column the view reads is not in the trajectory.
    #[error("view: {user} reads column `{column}`, which the run does not have (it has: {known})")]
    MissingColumn {
        /// What reads it (`body rotor`).
        user: String,
        /// The column asked for.
        column: String,
        /// The trajectory's columns, comma separated.
        known: String,
    },
    /// A trace names a body the view does not have.
    #[error("view: trace reads body `{body}`, which the view does not have (it has: {known})")]
    MissingBody {
        /// The body asked for.
        body: String,
        /// The view's bodies, comma separated.
        known: String,
    },
    /// A colour is not `#rrggbb`.
    #[error("view: {user} has colour `{colour}`; write it as #rrggbb")]
    Colour {
        /// Whose colour.
        user: String,
        /// The colour given.
        colour: String,
    },
    /// A size, offset or scale is not a finite number (or a size is not positive).
    #[error("view: {user}: {what}")]
    Number {
        /// Whose number.
        user: String,
        /// What is wrong.
        what: String,
    },
    /// A point's line names a point the view does not have.
    #[error("view: {user} is joined to point `{point}`, which the view does not have (it has: {known})")]
    MissingPoint {
        /// The point joined.
        user: String,
        /// The point it names.
        point: String,
        /// The view's points, comma separated.
        known: String,
    },
    /// The trajectory has no rows.
    #[error("view: the run has no rows to show")]
    Empty,
    /// A length names a parameter whose value the view was not given.
    #[error("view: {user} reads parameter `{name}`, whose value the view was not given (ViewSpec::with_parameters)")]
    Unresolved {
        /// Whose length.
        user: String,
        /// The parameter.
        name: String,
    },
}

impl ViewSpec {
    /// Checks colours, numbers, axes and body names (columns are checked against a trajectory).
    pub fn check(&self) -> Result<(), ViewError> {
        if let Some(up) = self.up {
            check_axis("up", up.unsigned_abs())?;
        }
        for b in &self.bodies {
            let user = format!("body {}", b.name);
            check_axis(&format!("{user}: axis"), b.axis)?;
            check_colour(&user, &b.colour)?;
            check_finite(&user, "offset", &numbers(&b.offset))?;
            check_shape(&user, &b.shape)?;
            check_finite(&user, "turn", b.turn.as_ref().map_or(&[], |t| &t[..]))?;
            if !(0.0..=1.0).contains(&b.opacity) {
                return Err(ViewError::Number {
                    user,
                    what: format!("opacity {} is not in 0..1", b.opacity),
                });
            }
        }
        for a in &self.arrows {
            let user = format!("arrow {}", a.label);
            check_colour(&user, &a.colour)?;
            check_finite(&user, "scale", &[a.scale])?;
        }
        for t in &self.traces {
            let user = format!("trace of {}", t.body);
            check_colour(&user, &t.colour)?;
            check_finite(&user, "point", &numbers(&t.point))?;
            if !self.bodies.iter().any(|b| b.name == t.body) {
                let known: Vec<&str> = self.bodies.iter().map(|b| b.name.as_str()).collect();
                return Err(ViewError::MissingBody { body: t.body.clone(), known: known.join(", ") });
            }
        }
        for p in &self.points {
            let user = format!("point {}", p.name);
            check_colour(&user, &p.colour)?;
            let known = || self.points.iter().map(|p| p.name.as_str()).collect::<Vec<_>>().join(", ");
            match &p.from {
                Some(from) if !self.points.iter().any(|q| &q.name == from) => {
                    return Err(ViewError::MissingPoint { user, point: from.clone(), known: known() })
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// Every column the view reads, each with what reads it, in the order the view gives them.
    pub fn columns(&self) -> Vec<(String, &str)> {
        let bodies = self.bodies.iter().flat_map(|b| {
            let position = b.position.iter().flatten();
            let sizes = match &b.shape {
                Shape::Inertia { mass, inertia } => Some(std::iter::once(mass).chain(inertia)),
                _ => None,
            };
            b.orientation
                .columns()
                .iter()
                .chain(position)
                .chain(sizes.into_iter().flatten())
                .map(move |c| (format!("body {}", b.name), c.as_str()))
        });
        let arrows = self
            .arrows
            .iter()
            .flat_map(|a| a.columns.iter().map(move |c| (format!("arrow {}", a.label), c.as_str())));
        let points = self
            .points
            .iter()
            .flat_map(|p| p.position.iter().map(move |c| (format!("point {}", p.name), c.as_str())));
        bodies.chain(arrows).chain(points).collect()
    }
}

fn check_axis(user: &str, axis: u8) -> Result<(), ViewError> {
    if (1..=3).contains(&axis) {
        Ok(())
    } else {
        Err(ViewError::Number { user: user.to_string(), what: format!("axis {axis} is not 1, 2 or 3") })
    }
}

fn check_colour(user: &str, colour: &str) -> Result<(), ViewError> {
    let hex = colour.strip_prefix('#').unwrap_or("");
    if hex.len() == 6 && hex.chars().all(|c| c.is_ascii_hexdigit()) {
        Ok(())
    } else {
        Err(ViewError::Colour { user: user.to_string(), colour: colour.to_string() })
    }
}

fn check_finite(user: &str, what: &str, values: &[f64]) -> Result<(), ViewError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(ViewError::Number { user: user.to_string(), what: format!("{what} {values:?} is not finite") })
    }
}

/// The numbers among `lengths` (parameters are checked once their values are known).
fn numbers(lengths: &[Length]) -> Vec<f64> {
    lengths.iter().filter_map(Length::number).collect()
}

impl Shape {
    /// Its sizes, in the order written (a shape is a few numbers: copied for the check).
    fn sizes(&self) -> Vec<Length> {
        self.clone().sizes_mut().into_iter().map(|l| l.clone()).collect()
    }

    /// Its sizes to set, in the order written.
    fn sizes_mut(&mut self) -> Vec<&mut Length> {
        match self {
            Shape::Ellipsoid { a, b, c } => vec![a, b, c],
            Shape::Cylinder { radius, length } => vec![radius, length],
            Shape::Box { x, y, z } => vec![x, y, z],
            Shape::Rod { length } => vec![length],
            Shape::Ring { radius, tube } => vec![radius, tube],
            Shape::Axes { length } => length.iter_mut().collect(),
            Shape::Inertia { .. } => Vec::new(),
        }
    }
}

impl ViewSpec {
    /// This view with every length a number: parameters' values from `value_of` (a run's), then
    /// checked as [`ViewSpec::check`] does.
    pub fn with_parameters(&self, value_of: &dyn Fn(&str) -> Option<f64>) -> Result<ViewSpec, ViewError> {
        let mut view = self.clone();
        let resolve = |user: String, length: &mut Length| {
            let value =
                length.with_parameters(value_of).map_err(|name| ViewError::Unresolved { user, name })?;
            *length = Length::Number(value);
            Ok::<(), ViewError>(())
        };
        for b in &mut view.bodies {
            let user = format!("body {}", b.name);
            for length in b.offset.iter_mut().chain(b.shape.sizes_mut()) {
                resolve(user.clone(), length)?;
            }
        }
        for t in &mut view.traces {
            for length in &mut t.point {
                resolve(format!("trace of {}", t.body), length)?;
            }
        }
        view.check()?;
        Ok(view)
    }
}

fn check_shape(user: &str, shape: &Shape) -> Result<(), ViewError> {
    let sizes: Vec<f64> = shape.sizes().into_iter().filter_map(|l| l.number()).collect();
    if sizes.iter().all(|s| s.is_finite() && *s > 0.0) {
        Ok(())
    } else {
        Err(ViewError::Number {
            user: user.to_string(),
            what: format!("shape sizes {sizes:?} must be positive"),
        })
    }
}
