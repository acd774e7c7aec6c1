//! A scene's `[[controls]]`: in come the tables as read (a name, a range, a step, a unit) and the
//! values the scene gives; out go [`Control`]s, each bound to the value it moves (a parameter,
//! an initial value or an `[axle]` entry), and scenes or scene text with moved values.

use serde::Deserialize;
use toml::Spanned;

use super::text::{line_col, SceneError, Span, Text};
use super::{AxleKey, Control, Scene, Target, Value};

/// A `[[controls]]` table as read.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ControlFile {
    name: Spanned<String>,
    min: Spanned<f64>,
    max: Spanned<f64>,
    step: Option<Spanned<f64>>,
    unit: Option<Spanned<String>>,
}

impl AxleKey {
    /// Every key, with its name in the table.
    const ALL: [(AxleKey, &'static str); 4] = [
        (AxleKey::Tilt, "tilt"),
        (AxleKey::Spin, "spin"),
        (AxleKey::Precession, "precession"),
        (AxleKey::Nutation, "nutation"),
    ];
}

impl Text<'_> {
    /// The `[[controls]]` of a scene whose values are already read: each bound to one value the
    /// scene gives, in that value's unit, with the value inside the range.
    pub(super) fn controls(
        &self,
        tables: Vec<ControlFile>,
        scene: &Scene,
    ) -> Result<Vec<Control>, SceneError> {
        let mut out: Vec<Control> = Vec::new();
        for c in tables {
            let name = c.name.get_ref().clone();
            if out.iter().any(|o| o.name.eq_ignore_ascii_case(&name)) {
                return Err(self.err(
                    c.name.span(),
                    format!("a control for `{name}` is declared twice"),
                    "keep one [[controls]] table per value",
                ));
            }
            let (target, value, value_span) = self.target(&c.name, scene)?;
            let unit = self.control_unit(&c, value, value_span)?;
            let (min, max, step) = self.range(&c)?;
            if !(min..=max).contains(&value.number) {
                return Err(self.err(
                    c.name.span(),
                    format!(
                        "the scene gives {name} = {}, outside this control's range {min} to {max}",
                        value.number
                    ),
                    "widen min and max to hold the scene's value, or change the value",
                ));
            }
            out.push(Control { name, target, min, max, step, unit, value: value.number });
        }
        Ok(out)
    }

    /// The value a control's name moves: one `[parameters]`, `[initial]` or `[axle]` entry.
    fn target<'s>(
        &self,
        name: &Spanned<String>,
        scene: &'s Scene,
    ) -> Result<(Target, &'s Value, Span), SceneError> {
        let n = name.get_ref();
        let mut found: Vec<(Target, &Value, Span)> = Vec::new();
        for (i, (p, v, span)) in scene.parameters.iter().enumerate() {
            if p.eq_ignore_ascii_case(n) {
                found.push((Target::Parameter(i), v, span.clone()));
            }
        }
        for (i, (p, v, span)) in scene.initial.iter().enumerate() {
            if p.eq_ignore_ascii_case(n) {
                found.push((Target::Initial(i), v, span.clone()));
            }
        }
        if let Some(axle) = &scene.axle {
            for (key, key_name) in AxleKey::ALL {
                if let (true, Some((v, span))) = (key_name.eq_ignore_ascii_case(n), axle.entry(key)) {
                    found.push((Target::Axle(key), v, span.clone()));
                }
            }
        }
        match found.len() {
            1 => Ok(found.remove(0)),
            0 => Err(self.err(
                name.span(),
                format!("a control for `{n}`, which the scene does not give"),
                "a control moves a value the scene gives: give it under [parameters], [initial] or [axle] (tilt, spin, precession, nutation) first",
            )),
            _ => Err(self.err(
                name.span(),
                format!("`{n}` is given in more than one table, so the control is ambiguous"),
                "give the value in one of [parameters], [initial] and [axle] only",
            )),
        }
    }

    /// The control's unit: the unit of the value it moves (`unit`, when given, must be it).
    fn control_unit(
        &self,
        c: &ControlFile,
        value: &Value,
        value_span: Span,
    ) -> Result<Option<String>, SceneError> {
        let Some(unit) = &c.unit else { return Ok(value.unit.clone()) };
        let same = value.unit.as_deref().is_some_and(|u| u.eq_ignore_ascii_case(unit.get_ref().trim()));
        if same || (value.unit.is_none() && unit.get_ref().trim().is_empty()) {
            return Ok(value.unit.clone());
        }
        let (line, column) = line_col(self.source, value_span.start);
        Err(self.err(
            unit.span(),
            format!(
                "the control's unit `{}` is not the unit of {} at line {line}, column {column} (`{}`)",
                unit.get_ref(),
                c.name.get_ref(),
                value.unit.as_deref().unwrap_or("none")
            ),
            "give the control the unit the scene gives its value in, or leave unit out",
        ))
    }

    /// `min < max`, both finite; `step` positive and no wider than the range (a hundredth of it
    /// when not given).
    fn range(&self, c: &ControlFile) -> Result<(f64, f64, f64), SceneError> {
        let (min, max) = (*c.min.get_ref(), *c.max.get_ref());
        for (what, v, span) in [("min", min, c.min.span()), ("max", max, c.max.span())] {
            if !v.is_finite() {
                return Err(self.err(
                    span,
                    format!("{what} is {v}, not a finite number"),
                    "give a finite bound",
                ));
            }
        }
        if min >= max {
            return Err(self.err(
                c.max.span(),
                format!("max = {max} is not above min = {min}"),
                "give a range with min below max",
            ));
        }
        let step = match &c.step {
            Some(s) if !(*s.get_ref() > 0.0 && *s.get_ref() <= max - min) => {
                return Err(self.err(
                    s.span(),
                    format!("step = {} is not in (0, max - min = {}]", s.get_ref(), max - min),
                    "give a positive step no wider than the range",
                ))
            }
            Some(s) => *s.get_ref(),
            None => (max - min) / 100.0,
        };
        Ok((min, max, step))
    }
}

impl super::Axle {
    /// An entry's value and where it is given, if it is.
    fn entry(&self, key: AxleKey) -> Option<&(Value, Span)> {
        match key {
            AxleKey::Tilt => self.tilt.as_ref(),
            AxleKey::Spin => self.spin.as_ref(),
            AxleKey::Precession => self.precession.as_ref(),
            AxleKey::Nutation => self.nutation.as_ref(),
        }
    }

    /// An entry, to set.
    fn entry_mut(&mut self, key: AxleKey) -> Option<&mut (Value, Span)> {
        match key {
            AxleKey::Tilt => self.tilt.as_mut(),
            AxleKey::Spin => self.spin.as_mut(),
            AxleKey::Precession => self.precession.as_mut(),
            AxleKey::Nutation => self.nutation.as_mut(),
        }
    }
}

impl Scene {
    /// The scene with the controls at these indices set to these values (in their units).
    pub fn with_controls(&self, values: &[(usize, f64)]) -> Scene {
        let mut scene = self.clone();
        for &(i, x) in values {
            let Some(c) = self.controls.get(i) else { continue };
            let value = Value { number: x, unit: c.unit.clone() };
            let slot = match c.target {
                Target::Parameter(k) => scene.parameters.get_mut(k).map(|(_, v, _)| v),
                Target::Initial(k) => scene.initial.get_mut(k).map(|(_, v, _)| v),
                Target::Axle(key) => scene.axle.as_mut().and_then(|a| a.entry_mut(key)).map(|(v, _)| v),
            };
            if let Some(v) = slot {
                *v = value;
            }
            scene.controls[i].value = x;
        }
        scene
    }

    /// The scene's text with the controls at these indices set to these values: the file a
    /// user saves (everything else, comments included, as written).
    pub fn text_with_controls(&self, values: &[(usize, f64)]) -> String {
        let mut edits: Vec<(Span, String)> = values
            .iter()
            .filter_map(|&(i, x)| {
                let c = self.controls.get(i)?;
                let span = self.span_of(c.target)?;
                let text = match &c.unit {
                    Some(unit) => format!("\"{x:?} {unit}\""),
                    None => format!("{x:?}"),
                };
                Some((span, text))
            })
            .collect();
        edits.sort_by_key(|(span, _)| std::cmp::Reverse(span.start));
        edits.dedup_by_key(|(span, _)| span.start);
        let mut text = self.source.clone();
        for (span, value) in edits {
            if span.end <= text.len() && span.start < span.end {
                text.replace_range(span, &value);
            }
        }
        text
    }

    /// Where the value a control moves is written.
    fn span_of(&self, target: Target) -> Option<Span> {
        match target {
            Target::Parameter(k) => self.parameters.get(k).map(|(_, _, s)| s.clone()),
            Target::Initial(k) => self.initial.get(k).map(|(_, _, s)| s.clone()),
            Target::Axle(key) => self.axle.as_ref()?.entry(key).map(|(_, s)| s.clone()),
        }
    }

    /// The index of the control named `name` (any case).
    pub fn control(&self, name: &str) -> Option<usize> {
        self.controls.iter().position(|c| c.name.eq_ignore_ascii_case(name))
    }
}

#[cfg(test)]
mod tests;
