//! Events resolved: in come a scene's [`EventDecl`]s and the model; out go [`EventSpec`]s, each
//! its expression lowered (derivatives taken symbolically) with its inputs bound to states,
//! output columns and parameters in the CSV's units, or a scene error naming the event and the
//! place in its expression.

use kane_model::lang::event::{lower_event, EventName};
use kane_model::lang::units::size::shown_per_internal;
use kane_model::program::event::EventSlot;
use kane_model::runtime::ModelInfo;

use super::presets;
use crate::problem::{EventSpec, Rule, Source};
use crate::scene::{EventDecl, EventSource, Scene, SceneError};

/// What a name of an event expression is.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Named {
    State(usize),
    Column(usize, usize),
    Param(usize),
}

/// The events of `scene` for the model `info`.
pub fn events(scene: &Scene, info: &ModelInfo) -> Result<Vec<EventSpec>, SceneError> {
    if scene.events.is_empty() {
        return Ok(Vec::new());
    }
    if !scene.integrator.method.dense_output() {
        let d = &scene.events[0];
        return Err(scene.error_at(
            d.span.clone(),
            format!(
                "{}: events are found on the integrator's dense output, and method = \"{}\" has none",
                d.label(),
                scene.integrator.method.name()
            ),
            "set method under [integrator] to one with dense output (dopri5, dop853, vern7, vern9), or remove [[events]]",
        ));
    }
    let (names, named) = names(info);
    scene.events.iter().map(|d| event(scene, info, d, &names, &named)).collect()
}

/// The names an expression may read: states, output columns (a state listed as an output is
/// read as the state), parameters.
fn names(info: &ModelInfo) -> (Vec<EventName>, Vec<Named>) {
    let mut names = Vec::new();
    let mut named = Vec::new();
    let mut add = |name: &str, varies: bool, n: Named| {
        if !names.iter().any(|e: &EventName| e.name.eq_ignore_ascii_case(name)) {
            names.push(EventName { name: name.to_string(), varies });
            named.push(n);
        }
    };
    for (i, s) in info.state_names.iter().enumerate() {
        add(s, true, Named::State(i));
    }
    for (k, o) in info.outputs.iter().enumerate() {
        for (c, col) in o.columns.iter().enumerate() {
            add(col, true, Named::Column(k, c));
        }
    }
    for (i, p) in info.param_names.iter().enumerate() {
        add(p, false, Named::Param(i));
    }
    (names, named)
}

fn event(
    scene: &Scene,
    info: &ModelInfo,
    d: &EventDecl,
    names: &[EventName],
    named: &[Named],
) -> Result<EventSpec, SceneError> {
    let (text, at) = match &d.source {
        EventSource::When(text, start) => (text.clone(), Some(*start)),
        EventSource::Preset(p) => (presets::when_text(d, p, scene, info)?, None),
    };
    let code = lower_event(&text, names).map_err(|e| {
        let span = match at {
            Some(start) => start + e.span.start..start + e.span.end.max(e.span.start),
            None => d.span.clone(),
        };
        scene.error_at(span, format!("{}: {}", d.label(), e.message), &e.help)
    })?;
    let mut sources = Vec::with_capacity(code.slots.len());
    let mut reads: Vec<usize> = Vec::new();
    for slot in &code.slots {
        let source = match *slot {
            EventSlot::Time => Source::Time,
            EventSlot::Value(i) | EventSlot::Rate(i) => {
                let rate = matches!(slot, EventSlot::Rate(_));
                match named[i] {
                    Named::State(s) => {
                        reads.push(s);
                        let f = shown_per_internal(info.state_units[s]);
                        if rate {
                            Source::StateRate(s, f)
                        } else {
                            Source::State(s, f)
                        }
                    }
                    Named::Column(k, c) => {
                        let o = &info.outputs[k];
                        reads.extend(o.reads);
                        if rate && o.needs_rates {
                            return Err(scene.error_at(
                                d.span.clone(),
                                format!("{}: the rate of `{}` is not available: the output reads the speed rates u', so its rate needs u''", d.label(), names[i].name),
                                "use the rate of a quantity of the states alone, or the output itself",
                            ));
                        }
                        let f = shown_per_internal(o.unit);
                        if rate {
                            Source::ColumnRate(k, c, f)
                        } else {
                            Source::Column(k, c, f)
                        }
                    }
                    Named::Param(p) => Source::Param(p, shown_per_internal(info.param_units[p])),
                }
            }
        };
        sources.push(source);
    }
    reads.sort_unstable();
    reads.dedup();
    let rule = Rule { direction: d.direction, stop_after: d.stop_after() };
    Ok(EventSpec { name: d.name.clone(), code, sources, rule, reads })
}
