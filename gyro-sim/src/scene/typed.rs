//! A scene's text read into its typed tables with every unknown key reported at once: in come
//! the text and the table types; out go the typed form of the text without its unknown keys and
//! an error for each (with the nearest known key), or the first other mistake. An unknown key's
//! entry is blanked and the text read again, so positions stay those of the file.

use serde::de::DeserializeOwned;

use super::text::{SceneError, Span, Text};

/// At most this many mistakes are reported from one reading.
const MOST_REPORTED: usize = 20;

/// What every table of a scene may hold, for an error that is not an unknown key.
const KEYS_HELP: &str = "keys are title, model, t_final, output_step, outputs, [integrator] (method, rtol, atol, step, accuracy, max_steps), [parameters], [initial], [specified], [axle] (tilt, spin, precession, nutation, quaternion, rates), [view], [[events]] (name, when, preset, direction, action, count, angle, margin, lock), [[controls]] (name, min, max, step, unit), plot_points";

/// A scene's tables read past their unknown keys.
pub(super) struct Typed<T> {
    /// The tables without the unknown keys.
    pub(super) tables: T,
    /// An error per unknown key.
    pub(super) unknown: Vec<SceneError>,
    /// The known keys suggested for them (a missing one of these is not a further mistake).
    pub(super) suggested: Vec<String>,
}

/// The scene's tables as `T` past their unknown keys, or every unknown key and the first other
/// mistake.
pub(super) fn read_typed<T: DeserializeOwned>(text: &Text<'_>) -> Result<Typed<T>, SceneError> {
    let mut source = text.source.to_string();
    let (mut unknown, mut suggested) = (Vec::new(), Vec::new());
    let mut blanked: Vec<Span> = Vec::new();
    while unknown.len() < MOST_REPORTED {
        let e = match toml::from_str::<T>(&source) {
            Ok(tables) => return Ok(Typed { tables, unknown, suggested }),
            Err(e) => e,
        };
        let span = e.span().unwrap_or(0..0);
        // A mistake where an entry was blanked, or a field missing after one was (a line of an
        // inline table blanked whole), follows from the blanking.
        let follows = blanked.iter().any(|b| b.start <= span.start && span.start <= b.end)
            || (!blanked.is_empty() && e.message().starts_with("missing field"));
        if follows {
            break;
        }
        let Some((key, expected)) = unknown_key(e.message()) else {
            unknown.push(text.err(span, e.message().to_string(), KEYS_HELP));
            break;
        };
        let near = kane_model::lang::nearest_word(&key, expected.iter().map(String::as_str));
        let help = match near {
            Some(k) => format!("did you mean `{k}`?"),
            None => "remove it, or write one of the keys expected".to_string(),
        };
        suggested.extend(near.map(str::to_string));
        unknown.push(text.err(span.clone(), e.message().to_string(), &help));
        let entry = entry_span(&source, span.start);
        if entry.is_empty() {
            break;
        }
        blank(&mut source, &entry);
        blanked.push(entry);
    }
    Err(SceneError::all(unknown))
}

/// The key and the keys expected of serde's "unknown field `k`, expected one of `a`, `b`".
fn unknown_key(message: &str) -> Option<(String, Vec<String>)> {
    let rest = message.strip_prefix("unknown field `")?;
    let (key, rest) = rest.split_once('`')?;
    let expected = rest.split('`').skip(1).step_by(2).map(str::to_string).collect();
    Some((key.to_string(), expected))
}

/// The span of the entry whose key starts at `at`: a table header's whole table, or a key's
/// line with the lines its brackets continue over.
fn entry_span(source: &str, at: usize) -> Span {
    let start = source[..at.min(source.len())].rfind('\n').map_or(0, |i| i + 1);
    let mut lines = source[start..].split_inclusive('\n');
    let Some(first) = lines.next() else { return start..start };
    let mut end = start + first.len();
    if first.trim_start().starts_with('[') {
        for line in lines {
            if line.trim_start().starts_with('[') {
                break;
            }
            end += line.len();
        }
        return start..end;
    }
    let mut depth = bracket_depth(first);
    for line in lines {
        if depth <= 0 {
            break;
        }
        depth += bracket_depth(line);
        end += line.len();
    }
    start..end
}

/// Opening minus closing brackets and braces of `line`, outside strings and comments.
fn bracket_depth(line: &str) -> i32 {
    let (mut depth, mut quote) = (0, None);
    for c in line.chars() {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), _) if c == q => quote = None,
            (None, '#') => break,
            (None, '[' | '{') => depth += 1,
            (None, ']' | '}') => depth -= 1,
            _ => {}
        }
    }
    depth
}

/// `source` with `span` turned into spaces (newlines kept, so lines and columns stay).
fn blank(source: &mut String, span: &Span) {
    let blanked: String = source[span.clone()]
        .chars()
        .map(|c| if c == '\n' { "\n".to_string() } else { " ".repeat(c.len_utf8()) })
        .collect();
    source.replace_range(span.clone(), &blanked);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serdes_unknown_field_message_is_read() {
        let (key, expected) = unknown_key("unknown field `tilts`, expected one of `tilt`, `spin`").unwrap();
        assert_eq!((key.as_str(), expected), ("tilts", vec!["tilt".to_string(), "spin".to_string()]));
        let (_, two) = unknown_key("unknown field `x`, expected `a` or `b`").unwrap();
        assert_eq!(two, ["a", "b"]);
        assert_eq!(unknown_key("invalid type: string \"a\", expected f64"), None);
    }

    #[test]
    fn an_entry_is_its_line_with_the_lines_its_brackets_continue_and_a_table_is_its_body() {
        let src = "a = 1\nb = [1,\n  2]\nc = \"[\"\n[t]\nx = 1\n[u]\n";
        let b = src.find('b').unwrap();
        assert_eq!(&src[entry_span(src, b)], "b = [1,\n  2]\n");
        let c = src.find('c').unwrap();
        assert_eq!(&src[entry_span(src, c)], "c = \"[\"\n");
        let t = src.find("[t]").unwrap() + 1;
        assert_eq!(&src[entry_span(src, t)], "[t]\nx = 1\n");
        let mut blanked = src.to_string();
        blank(&mut blanked, &entry_span(src, b));
        assert_eq!(blanked.len(), src.len());
        assert_eq!(blanked.lines().count(), src.lines().count());
    }
}
