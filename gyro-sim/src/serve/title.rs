//! The title of a run with moved controls: in come the scene's title and its controls before and
//! after; out goes the title showing the values run. A moved value is written in place of the
//! old one where the title shows that value once, after the control's name (`spin 10 rad/s`,
//! `U3 = 100 rad/s`) or before its unit (`60 deg`); the others follow the title
//! (`... Y = Z = 10 N m — now Y = 5`).

use std::ops::Range;

use crate::scene::Control;

/// `title` for the values of `after`, the controls of `before` being those `title` describes.
pub(super) fn moved_title(title: &str, before: &[Control], after: &[Control]) -> String {
    let mut edits: Vec<(Range<usize>, String)> = Vec::new();
    let mut rest: Vec<String> = Vec::new();
    for (old, new) in before.iter().zip(after) {
        if old.value == new.value {
            continue;
        }
        match place(title, old, before) {
            Some(at) if !edits.iter().any(|(r, _)| r.start < at.end && at.start < r.end) => {
                edits.push((at, number(new.value)));
            }
            _ => rest.push(match &new.unit {
                Some(unit) => format!("{} = {} {unit}", new.name, number(new.value)),
                None => format!("{} = {}", new.name, number(new.value)),
            }),
        }
    }
    edits.sort_by_key(|(r, _)| std::cmp::Reverse(r.start));
    let mut text = title.to_string();
    for (at, value) in edits {
        text.replace_range(at, &value);
    }
    if rest.is_empty() {
        text
    } else {
        format!("{text} — now {}", rest.join(", "))
    }
}

/// A value as the title writes it (`10`, `0.5`, `-2.25`).
fn number(value: f64) -> String {
    format!("{value}")
}

/// Where `title` writes the value of `control`: the one number equal to it after its name, else
/// the one before its unit (when no other control has that value and unit).
fn place(title: &str, control: &Control, all: &[Control]) -> Option<Range<usize>> {
    let equal: Vec<Range<usize>> =
        numbers(title).filter(|(_, v)| same(*v, control.value)).map(|(r, _)| r).collect();
    let named: Vec<&Range<usize>> =
        equal.iter().filter(|r| after_name(&title[..r.start], &control.name)).collect();
    if let [only] = named[..] {
        return Some(only.clone());
    }
    let unit = control.unit.as_deref().filter(|u| !u.trim().is_empty())?;
    let shared =
        all.iter().filter(|c| same(c.value, control.value) && c.unit.as_deref() == Some(unit)).count();
    let before_unit: Vec<&Range<usize>> =
        equal.iter().filter(|r| before_unit(&title[r.end..], unit)).collect();
    match (shared, &before_unit[..]) {
        (1, [only]) => Some((*only).clone()),
        _ => None,
    }
}

/// Whether two values are the same number as written.
fn same(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

/// The numbers written in `text` (not inside a name such as `U3`) and where each is.
fn numbers(text: &str) -> impl Iterator<Item = (Range<usize>, f64)> + '_ {
    let bytes = text.as_bytes();
    let mut i = 0;
    std::iter::from_fn(move || {
        while i < bytes.len() {
            let start = i;
            let word = start > 0 && (bytes[start - 1].is_ascii_alphanumeric() || bytes[start - 1] == b'_');
            let sign = bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit);
            if !bytes[i].is_ascii_digit() && !sign {
                i += 1;
                continue;
            }
            i += 1;
            while i < bytes.len()
                && (bytes[i].is_ascii_digit() || (bytes[i] == b'.' && digit_at(bytes, i + 1)))
            {
                i += 1;
            }
            if word || bytes.get(i).is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_') {
                continue;
            }
            if let Ok(value) = text[start..i].parse::<f64>() {
                return Some((start..i, value));
            }
        }
        None
    })
}

/// Whether `bytes[i]` is a digit.
fn digit_at(bytes: &[u8], i: usize) -> bool {
    bytes.get(i).is_some_and(u8::is_ascii_digit)
}

/// Whether `before` (the title up to a number) ends with `name`, as `spin ` or `U3 = ` (not as
/// the last of a chain such as `Y = Z = `, which gives the value to more than one name).
fn after_name(before: &str, name: &str) -> bool {
    let text = before.trim_end();
    let text = text.strip_suffix('=').unwrap_or(text).trim_end();
    let Some(k) = text.len().checked_sub(name.len()) else { return false };
    let (Some(head), Some(tail)) = (text.get(..k), text.get(k..)) else { return false };
    let boundary = head.chars().next_back().is_none_or(|c| !c.is_alphanumeric() && c != '_');
    tail.eq_ignore_ascii_case(name) && boundary && !head.trim_end().ends_with('=')
}

/// Whether `after` (the title after a number) starts with `unit`, as ` rad/s,` or `deg)`.
fn before_unit(after: &str, unit: &str) -> bool {
    let rest = after.strip_prefix(' ').unwrap_or(after);
    let unit = unit.trim();
    rest.get(..unit.len()).is_some_and(|u| u.eq_ignore_ascii_case(unit))
        && rest[unit.len()..].chars().next().is_none_or(|c| !c.is_alphanumeric())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Target;

    fn control(name: &str, unit: Option<&str>, value: f64) -> Control {
        let unit = unit.map(String::from);
        Control {
            name: name.into(),
            target: Target::Parameter(0),
            min: -1e9,
            max: 1e9,
            step: 1.0,
            unit,
            value,
        }
    }

    /// The title with the controls (name, unit, value before) moved to the values after.
    fn moved(title: &str, controls: &[(&str, Option<&str>, f64, f64)]) -> String {
        let before: Vec<Control> = controls.iter().map(|&(n, u, v, _)| control(n, u, v)).collect();
        let after: Vec<Control> = controls.iter().map(|&(n, u, _, v)| control(n, u, v)).collect();
        moved_title(title, &before, &after)
    }

    #[test]
    fn a_value_the_title_writes_is_replaced() {
        let cusp = "EJS top: cusp (60 deg, spin 10 rad/s, at rest)";
        let controls = [("spin", Some("rad/s"), 10.0, 20.5), ("tilt", Some("deg"), 60.0, 45.0)];
        assert_eq!(moved(cusp, &controls), "EJS top: cusp (45 deg, spin 20.5 rad/s, at rest)");
        let trial = "Gimbal gyroscope, Trial 3: U3 = 100 rad/s, Y = Z = 10 N m";
        assert_eq!(
            moved(trial, &[("U3", Some("rad/s"), 100.0, 150.0)]),
            "Gimbal gyroscope, Trial 3: U3 = 150 rad/s, Y = Z = 10 N m"
        );
        assert_eq!(moved(cusp, &[("spin", Some("rad/s"), 10.0, 10.0)]), cusp, "nothing moved");
    }

    #[test]
    fn a_value_the_title_does_not_write_once_follows_it() {
        let trial = "Gimbal gyroscope, Trial 3: U3 = 100 rad/s, Y = Z = 10 N m";
        let torques = [("Y", None, 10.0, 5.0), ("Z", None, 10.0, 10.0)];
        assert_eq!(moved(trial, &torques), format!("{trial} — now Y = 5"));
        let z = [("Y", None, 10.0, 10.0), ("Z", None, 10.0, -2.5)];
        assert_eq!(moved(trial, &z), format!("{trial} — now Z = -2.5"));
        assert_eq!(
            moved("pendulum (model file)", &[("L", Some("m"), 1.0, 3.0)]),
            "pendulum (model file) — now L = 3 m"
        );
        // Two controls of the same value and unit: the title's one `0 rad/s` is neither's.
        let rates = [("precession", Some("rad/s"), 0.0, 1.0), ("nutation", Some("rad/s"), 0.0, 0.0)];
        assert_eq!(moved("top, 0 rad/s", &rates), "top, 0 rad/s — now precession = 1 rad/s");
    }

    #[test]
    fn numbers_inside_names_are_not_values() {
        let found: Vec<f64> = numbers("U3 = 100, Q_2 7 -1.5 x2 3rd (4)").map(|(_, v)| v).collect();
        assert_eq!(found, [100.0, 7.0, -1.5, 4.0]);
        assert_eq!(moved("U3 = 3", &[("U3", None, 3.0, 4.0)]), "U3 = 4");
    }
}
