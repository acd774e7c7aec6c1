//! A request's body, never trusted: in come its bytes and the scene's controls; out go the
//! values to set (control index, value in the control's unit), or a client error naming what is
//! wrong. Nothing is run before a body passes.

use crate::scene::Control;

/// The largest request body read, bytes; a larger one is refused unread.
pub const MAX_BODY: usize = 64 * 1024;

/// A request refused: the HTTP status and the message shown on the page.
#[derive(Clone, Debug, PartialEq)]
pub struct Refused {
    /// 400, 404, 405 or 413.
    pub status: u16,
    /// What is wrong, for a person.
    pub message: String,
}

impl Refused {
    /// A 400 Bad Request with `message`.
    pub fn bad(message: String) -> Refused {
        Refused { status: 400, message }
    }
}

/// The values of a body `{"values": {"NAME": number, ...}}`: each name a control of the scene
/// (any case), each number finite and inside the control's range; controls not named keep
/// the scene's values.
pub fn values(body: &[u8], controls: &[Control]) -> Result<Vec<(usize, f64)>, Refused> {
    if body.len() > MAX_BODY {
        return Err(too_large());
    }
    let json: serde_json::Value =
        serde_json::from_slice(body).map_err(|e| Refused::bad(format!("the request is not JSON: {e}")))?;
    let shape =
        || Refused::bad("send {\"values\": {\"NAME\": number, ...}}, naming the scene's controls".into());
    let object = json.as_object().ok_or_else(shape)?;
    if object.keys().any(|k| k != "values") {
        return Err(shape());
    }
    let given = object.get("values").and_then(|v| v.as_object()).ok_or_else(shape)?;
    let mut out = Vec::with_capacity(given.len());
    for (name, value) in given {
        let Some(i) = controls.iter().position(|c| c.name.eq_ignore_ascii_case(name)) else {
            return Err(Refused::bad(format!(
                "`{}` is not a control of this scene (its controls: {})",
                shorten(name),
                controls.iter().map(|c| c.name.as_str()).collect::<Vec<_>>().join(", ")
            )));
        };
        if out.iter().any(|&(j, _)| j == i) {
            return Err(Refused::bad(format!("`{}` is given twice", controls[i].name)));
        }
        out.push((i, checked(&controls[i], value)?));
    }
    Ok(out)
}

/// The 413 for a body over [`MAX_BODY`].
pub fn too_large() -> Refused {
    Refused { status: 413, message: format!("the request body is over {MAX_BODY} bytes") }
}

/// A control's value: a finite number inside its range.
fn checked(control: &Control, value: &serde_json::Value) -> Result<f64, Refused> {
    let name = &control.name;
    let Some(x) = value.as_f64().filter(|x| x.is_finite()) else {
        let shown = shorten(&value.to_string());
        return Err(Refused::bad(format!("{name} must be a finite number, not {shown}")));
    };
    if !(control.min..=control.max).contains(&x) {
        let unit = control.unit.as_deref().map_or(String::new(), |u| format!(" {u}"));
        return Err(Refused::bad(format!(
            "{name} = {x} is outside its range, {} to {}{unit}",
            control.min, control.max
        )));
    }
    Ok(x)
}

/// At most 40 characters of `text`, for messages that repeat what a client sent.
fn shorten(text: &str) -> String {
    match text.char_indices().nth(40) {
        Some((cut, _)) => format!("{}...", &text[..cut]),
        None => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Target;

    fn controls() -> Vec<Control> {
        let c = |name: &str, min, max, unit: Option<&str>| Control {
            name: name.into(),
            target: Target::Parameter(0),
            min,
            max,
            step: 0.1,
            unit: unit.map(String::from),
            value: min,
        };
        vec![c("spin", 0.0, 40.0, Some("rad/s")), c("Y", -20.0, 20.0, None)]
    }

    fn refused(body: &str) -> Refused {
        values(body.as_bytes(), &controls()).unwrap_err()
    }

    #[test]
    fn good_values_are_read_by_name_in_any_case() {
        let v = values(br#"{"values": {"SPIN": 12.5, "y": -3}}"#, &controls()).unwrap();
        assert_eq!(v, [(0, 12.5), (1, -3.0)]);
        assert_eq!(values(br#"{"values": {}}"#, &controls()).unwrap(), []);
        assert_eq!(
            values(br#"{"values": {"spin": 40}}"#, &controls()).unwrap(),
            [(0, 40.0)],
            "max is in range"
        );
    }

    #[test]
    fn bad_bodies_are_refused_with_the_reason() {
        assert_eq!(
            refused(r#"{"values": {"spin": 41}}"#).message,
            "spin = 41 is outside its range, 0 to 40 rad/s"
        );
        assert_eq!(
            refused(r#"{"values": {"spin": -0.5}}"#).message,
            "spin = -0.5 is outside its range, 0 to 40 rad/s"
        );
        assert_eq!(
            refused(r#"{"values": {"spin": "NaN"}}"#).message,
            "spin must be a finite number, not \"NaN\""
        );
        assert_eq!(
            refused(r#"{"values": {"spin": null}}"#).message,
            "spin must be a finite number, not null"
        );
        assert_eq!(
            refused(r#"{"values": {"M": 1}}"#).message,
            "`M` is not a control of this scene (its controls: spin, Y)"
        );
        assert_eq!(refused(r#"{"values": {"spin": 1, "Spin": 2}}"#).message, "`spin` is given twice");
        assert!(refused(r#"{"values": {"spin": NaN}}"#).message.starts_with("the request is not JSON"));
        assert!(refused(r#"{"values": {"spin": 1e999}}"#).message.starts_with("the request is not JSON"));
        assert!(refused("{\"values\": ").message.starts_with("the request is not JSON"));
        assert!(refused("[1, 2]").message.starts_with("send {\"values\""));
        assert!(refused(r#"{"values": {"spin": 1}, "run": "rm"}"#).message.starts_with("send {\"values\""));
        assert!(refused(r#"{"values": [1]}"#).message.starts_with("send {\"values\""));
        let long = format!("{{\"values\": {{\"{}\": 1}}}}", "x".repeat(500));
        assert!(refused(&long).message.len() < 120, "a long name is not echoed whole");
        assert!(refused(r#"{"values": {"spin": 1, "Y": 1}"#).status == 400);
    }

    #[test]
    fn an_oversized_body_is_refused_unread() {
        let body = vec![b' '; MAX_BODY + 1];
        let e = values(&body, &controls()).unwrap_err();
        assert_eq!((e.status, e.message.as_str()), (413, "the request body is over 65536 bytes"));
    }
}
