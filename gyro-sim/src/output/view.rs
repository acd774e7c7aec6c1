//! A 3-D view of a run: in come a [`Trajectory`] (model units, radians) and a [`ViewSpec`]
//! naming the columns it reads; out goes one self-contained HTML file (three.js, the data and
//! the script inline, nothing fetched) that plays the run with a time slider.
//!
//! The data embedded are `t` and only the columns the view reads. The page takes parameters
//! after `?` or `#`: `t=<time>` (shown, paused), `arrows=<label,label>` (the arrows shown),
//! `play=0|1`, `speed=<factor>`, `cam=<azimuth deg>,<elevation deg>,<distance>` and
//! `target=<x>,<y>,<z>` (the camera looks at the target from that direction, z up) and
//! `fov=<deg>` (the vertical field of view, 45 unless given); `ui=0` hides the panels.

use std::collections::BTreeMap;
use std::path::Path;

use super::{write_file_atomically, WriteError};
use crate::problem::Trajectory;
use crate::scene::{ViewError, ViewSpec};

/// three.js 0.170.0, `build/three.module.min.js` (see `gyro-sim/assets/three/README.md`).
const THREE_JS: &str = include_str!("../../assets/three/three.module.min.js");
/// The page with `{{TITLE}}`, `{{THREE}}`, `{{DATA}}`, `{{SCRIPT}}` and `{{EXTRA}}` (more panels
/// and scripts, `gyro-sim serve`'s; empty in a run's view) to fill.
const PAGE_HTML: &str = include_str!("view/page.html");
/// The page's script.
const PAGE_JS: &str = include_str!("view/page.js");

/// The page camera's vertical field of view unless the URL gives one, degrees.
const FIELD_OF_VIEW_DEG: f64 = 45.0;

/// Writes the view of `trajectory` as one HTML file at `path`, atomically.
pub fn write_view(trajectory: &Trajectory, view: &ViewSpec, path: &Path) -> Result<(), WriteError> {
    let html = view_html(trajectory, view)
        .map_err(|source| WriteError::View { path: path.to_path_buf(), source })?;
    write_file_atomically(path, html.as_bytes())
}

/// The page's text.
fn view_html(trajectory: &Trajectory, view: &ViewSpec) -> Result<String, ViewError> {
    let data = view_data(trajectory, view, &[])?;
    Ok(page_html(&trajectory.title, &data, ""))
}

/// The view page for `data` (from [`view_data`]) with `extra` HTML (more panels and scripts)
/// at the end of its body.
pub(crate) fn page_html(title: &str, data: &serde_json::Value, extra: &str) -> String {
    let title = escape_html(title);
    let data = script_json(data);
    fill(
        PAGE_HTML,
        &[("TITLE", &title), ("THREE", THREE_JS), ("DATA", &data), ("SCRIPT", PAGE_JS), ("EXTRA", extra)],
    )
}

/// JSON text safe inside a script element.
pub(crate) fn script_json(value: &serde_json::Value) -> String {
    // Inside a script element only `</script` (and `<!--`) could end or confuse it; in JSON a
    // `<` can only stand in a string, where `\u003c` means the same.
    value.to_string().replace('<', "\\u003c")
}

/// `{"title", "fov", "t": [..], "columns": {name: [..]}, "view": ViewSpec}` (each arrow with its
/// `tag`, each body sized by its inertia an ellipsoid from the first row), each column once:
/// those the view reads, then those of `extra` the trajectory has.
pub(crate) fn view_data(
    trajectory: &Trajectory,
    view: &ViewSpec,
    extra: &[String],
) -> Result<serde_json::Value, ViewError> {
    // Checked, and refused while a length still names a parameter.
    let view = &view.with_parameters(&|_| None)?;
    if trajectory.rows.is_empty() {
        return Err(ViewError::Empty);
    }
    let names: Vec<&str> = trajectory.columns.iter().map(|c| c.name.as_str()).collect();
    let view = &view.with_inertias(&names, &trajectory.rows[0][1..])?;
    let mut columns: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
    let column = |index: usize| trajectory.rows.iter().map(|r| r[index + 1]).collect::<Vec<f64>>();
    for (user, name) in view.columns() {
        if columns.contains_key(name) {
            continue;
        }
        let Some(index) = trajectory.columns.iter().position(|c| c.name == name) else {
            let known: Vec<&str> = trajectory.columns.iter().map(|c| c.name.as_str()).collect();
            return Err(ViewError::MissingColumn { user, column: name.to_string(), known: known.join(", ") });
        };
        columns.insert(name, column(index));
    }
    for name in extra {
        if let Some(index) = trajectory.columns.iter().position(|c| &c.name == name) {
            columns.entry(name).or_insert_with(|| column(index));
        }
    }
    let t: Vec<f64> = trajectory.rows.iter().map(|r| r[0]).collect();
    let mut data = serde_json::json!({ "title": trajectory.title, "fov": FIELD_OF_VIEW_DEG, "t": t, "columns": columns, "view": view });
    data["view"]["arrows"] = tagged_arrows(trajectory, view).into();
    Ok(data)
}

/// The view's arrows, each with the `tag` drawn for it (its label unless that reads as the
/// space axes, see [`arrow_tag::arrow_tag`]).
fn tagged_arrows(trajectory: &Trajectory, view: &ViewSpec) -> Vec<serde_json::Value> {
    let frame = view.frame.as_deref().unwrap_or("N");
    let unit_of =
        |name: &str| trajectory.columns.iter().find(|c| c.name == name).map_or("", |c| c.unit.as_str());
    view.arrows
        .iter()
        .map(|a| {
            let units = a.columns.each_ref().map(|c| unit_of(c));
            let unit = if units.iter().all(|u| *u == units[0]) { units[0] } else { "" };
            let mut arrow = serde_json::to_value(a).unwrap_or_default();
            arrow["tag"] = arrow_tag::arrow_tag(&a.label, &a.columns, unit, frame).into();
            arrow
        })
        .collect()
}

/// `template` with each `{{NAME}}` replaced by its value, in one pass (values are not searched).
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(template.len() + values.iter().map(|(_, v)| v.len()).sum::<usize>());
    let mut rest = template;
    while let Some(start) = rest.find("{{") {
        out.push_str(&rest[..start]);
        let after = &rest[start + 2..];
        let value = after
            .find("}}")
            .and_then(|end| values.iter().find(|(name, _)| *name == &after[..end]).map(|(_, v)| (end, *v)));
        match value {
            Some((end, v)) => {
                out.push_str(v);
                rest = &after[end + 2..];
            }
            None => {
                out.push_str("{{");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// Text safe between HTML tags.
fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

mod arrow_tag;

#[cfg(test)]
mod tests;
