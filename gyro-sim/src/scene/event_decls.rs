//! `[[events]]` tables read: in come the TOML tables; out go [`EventDecl`]s (a name, an
//! expression or a preset, the crossings that count and what one does), or a scene error at the
//! key that is wrong (names, expressions and angles are checked against the model later, when
//! the scene is resolved).

use kane_model::lang::units::normalised;
use kane_model::lang::units::size::unit_size;
use serde::Deserialize;
use toml::Spanned;

use super::SceneError;

/// Which crossings count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// From negative to positive.
    Up,
    /// From positive to negative.
    Down,
    /// Either way.
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
    /// A built-in one: `preset = "..."`.
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

/// One `[[events]]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EventFile {
    name: Option<Spanned<String>>,
    when: Option<Spanned<String>>,
    preset: Option<Spanned<String>>,
    direction: Option<Spanned<String>>,
    action: Option<Spanned<String>>,
    count: Option<Spanned<i64>>,
    angle: Option<Spanned<String>>,
    margin: Option<Spanned<toml::Value>>,
    lock: Option<Spanned<toml::Value>>,
}

type Span = std::ops::Range<usize>;

/// The presets by name, for messages.
pub const PRESETS: &str = "axle_below_horizontal, nutation_turning_points, gimbal_lock";

/// The tables checked; `err(span, message, help)` makes an error at a span of the scene.
pub fn decls(
    tables: Vec<EventFile>,
    source: &str,
    err: &dyn Fn(Span, String, &str) -> SceneError,
) -> Result<Vec<EventDecl>, SceneError> {
    let mut out: Vec<EventDecl> = Vec::new();
    for (i, t) in tables.into_iter().enumerate() {
        let d = decl(i + 1, t, source, err)?;
        if let Some(other) = out.iter().find(|o| o.name.eq_ignore_ascii_case(&d.name)) {
            return Err(err(
                d.span.clone(),
                format!("{} has the name of [[events]] {}", d.label(), other.number),
                "give each event a name of its own (name = \"...\")",
            ));
        }
        out.push(d);
    }
    Ok(out)
}

fn decl(
    number: usize,
    t: EventFile,
    source: &str,
    err: &dyn Fn(Span, String, &str) -> SceneError,
) -> Result<EventDecl, SceneError> {
    let label = |name: &str| format!("[[events]] {number} (`{name}`)");
    let (src, span, default_name) = match (&t.when, &t.preset) {
        (Some(w), None) => {
            let start = w.span().start + quote_len(&source[w.span().start.min(source.len())..]);
            (EventSource::When(w.get_ref().clone(), start), w.span(), format!("event{number}"))
        }
        (None, Some(p)) => {
            let preset = preset(&t, p, err, &label(p.get_ref()))?;
            (EventSource::Preset(preset), p.span(), p.get_ref().to_ascii_lowercase())
        }
        (Some(w), Some(_)) => {
            return Err(err(
                w.span(),
                format!("{} gives both `when` and `preset`", label(&format!("event{number}"))),
                "keep one: when = \"expression\" or preset = \"name\"",
            ))
        }
        (None, None) => {
            let span = t.name.as_ref().map_or(0..0, |n| n.span());
            return Err(err(
                span,
                format!("[[events]] {number} has neither `when` nor `preset`"),
                &format!("add when = \"ELEVATION - 10\" (crossing zero), or preset = one of {PRESETS}"),
            ));
        }
    };
    let name = t.name.as_ref().map_or(default_name, |n| n.get_ref().clone());
    let at = label(&name);
    let fallback = match &src {
        EventSource::Preset(Preset::AxleBelowHorizontal | Preset::GimbalLock { .. }) => Direction::Down,
        _ => Direction::Both,
    };
    let direction = word(
        &t.direction,
        &at,
        "direction",
        &[("up", Direction::Up), ("down", Direction::Down), ("both", Direction::Both)],
        err,
    )?
    .unwrap_or(fallback);
    let action = word(&t.action, &at, "action", &[("record", Action::Record), ("stop", Action::Stop)], err)?
        .unwrap_or(Action::Record);
    let count = match &t.count {
        Some(c) if *c.get_ref() < 1 => {
            return Err(err(
                c.span(),
                format!("{at}: count must be at least 1, not {}", c.get_ref()),
                "give the crossing the run ends at (1: the first)",
            ))
        }
        Some(c) => Some(usize::try_from(*c.get_ref()).unwrap_or(usize::MAX)),
        None => None,
    };
    if !matches!(src, EventSource::Preset(Preset::GimbalLock { .. })) {
        if let Some((key, span)) = [
            ("angle", t.angle.as_ref().map(|a| a.span())),
            ("margin", t.margin.as_ref().map(|a| a.span())),
            ("lock", t.lock.as_ref().map(|a| a.span())),
        ]
        .into_iter()
        .find_map(|(k, s)| s.map(|s| (k, s)))
        {
            return Err(err(
                span,
                format!("{at}: `{key}` belongs to preset = \"gimbal_lock\""),
                "remove it, or use that preset",
            ));
        }
    }
    Ok(EventDecl { number, name, source: src, span, direction, action, count })
}

/// How many quote characters open the TOML string at the start of `text`.
fn quote_len(text: &str) -> usize {
    if text.starts_with("\"\"\"") || text.starts_with("'''") {
        3
    } else {
        1
    }
}

/// A keyword value (`up`, `stop`) from `choices`, or an error naming them.
fn word<T: Copy>(
    v: &Option<Spanned<String>>,
    at: &str,
    key: &str,
    choices: &[(&str, T)],
    err: &dyn Fn(Span, String, &str) -> SceneError,
) -> Result<Option<T>, SceneError> {
    let Some(v) = v else { return Ok(None) };
    match choices.iter().find(|(n, _)| n.eq_ignore_ascii_case(v.get_ref())) {
        Some((_, x)) => Ok(Some(*x)),
        None => {
            let names: Vec<String> = choices.iter().map(|(n, _)| format!("\"{n}\"")).collect();
            Err(err(
                v.span(),
                format!("{at}: unknown {key} `{}`", v.get_ref()),
                &format!("{key} is one of {}", names.join(", ")),
            ))
        }
    }
}

/// The preset `p` names, with its own keys.
fn preset(
    t: &EventFile,
    p: &Spanned<String>,
    err: &dyn Fn(Span, String, &str) -> SceneError,
    at: &str,
) -> Result<Preset, SceneError> {
    match p.get_ref().to_ascii_lowercase().as_str() {
        "axle_below_horizontal" => Ok(Preset::AxleBelowHorizontal),
        "nutation_turning_points" => Ok(Preset::NutationTurningPoints),
        "gimbal_lock" => {
            let angle = t.angle.as_ref().ok_or_else(|| {
                err(
                    p.span(),
                    format!("{at}: preset gimbal_lock needs `angle`"),
                    "add angle = \"Q2\" (the inner gimbal's angle, a state)",
                )
            })?;
            let margin = t.margin.as_ref().ok_or_else(|| {
                err(
                    p.span(),
                    format!("{at}: preset gimbal_lock needs `margin`"),
                    "add margin = \"5 deg\" (how close to lock counts)",
                )
            })?;
            let margin_rad = angle_value(margin, at, "margin", err)?;
            if !(margin_rad > 0.0 && margin_rad < std::f64::consts::FRAC_PI_2) {
                return Err(err(
                    margin.span(),
                    format!("{at}: margin must be between 0 and 90 deg"),
                    "give a margin such as \"5 deg\"",
                ));
            }
            let lock = t.lock.as_ref().map(|l| angle_value(l, at, "lock", err)).transpose()?.unwrap_or(0.0);
            Ok(Preset::GimbalLock {
                angle: (angle.get_ref().clone(), angle.span()),
                margin: margin_rad,
                lock,
            })
        }
        other => {
            Err(err(p.span(), format!("{at}: unknown preset `{other}`"), &format!("presets: {PRESETS}")))
        }
    }
}

/// An angle given as a number (degrees) or a string with a unit of angle (`"5 deg"`, `"0.1 rad"`); radians.
fn angle_value(
    v: &Spanned<toml::Value>,
    at: &str,
    key: &str,
    err: &dyn Fn(Span, String, &str) -> SceneError,
) -> Result<f64, SceneError> {
    let bad = || {
        err(
            v.span(),
            format!("{at}: `{key}` is not an angle"),
            &format!("write {key} = \"5 deg\" or \"0.1 rad\""),
        )
    };
    let x = match v.get_ref() {
        toml::Value::Float(x) => x.to_radians(),
        toml::Value::Integer(i) => (*i as f64).to_radians(),
        toml::Value::String(s) => {
            let (number, unit) = s.trim().split_once(char::is_whitespace).unwrap_or((s.trim(), ""));
            let n: f64 = number.parse().map_err(|_| bad())?;
            if unit.trim().is_empty() {
                n.to_radians()
            } else {
                // Read as INPUT lines read units: any angle (deg, degrees, rad, rev, ...).
                let size = unit_size(&normalised(unit)).map_err(|_| bad())?;
                let radian = unit_size("RAD").map_err(|_| bad())?;
                if size.dim != radian.dim {
                    return Err(bad());
                }
                n * size.si
            }
        }
        _ => return Err(bad()),
    };
    if x.is_finite() {
        Ok(x)
    } else {
        Err(bad())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn angle(text: &str) -> Result<f64, SceneError> {
        let table: toml::Table = toml::from_str(&format!("v = {text}")).unwrap();
        let v = Spanned::new(0..0, table["v"].clone());
        let err = |span: Span, message: String, help: &str| {
            crate::scene::text::error_at("s.toml", "", span, message, help)
        };
        angle_value(&v, "[[events]] 1", "margin", &err)
    }

    #[test]
    fn angles_read_units_as_input_lines_do_and_a_plain_number_is_degrees() {
        let deg = std::f64::consts::PI / 180.0;
        for (text, want) in
            [("5", 5.0 * deg), ("\"5 deg\"", 5.0 * deg), ("\"5 degrees\"", 5.0 * deg), ("\"0.1 rad\"", 0.1)]
        {
            let got = angle(text).unwrap();
            assert!((got - want).abs() <= 1e-15, "{text}: {got} against {want}");
        }
        assert!(angle("\"5 m\"").unwrap_err().message.contains("is not an angle"));
    }
}
