//! UNITS and INPUT unit tags against what a quantity is: a constant that is a body's or
//! particle's mass is a mass, one that places a point along a frame's axis (`P_O_P> = L*B1>`)
//! is a length, an entry of an inertia is a moment of inertia, a measure of a force or torque
//! is a force or torque (once KANE(), FR() or the like has applied the loads), and a symbol
//! that rotates a frame (`SIMPROT(A, B, 3, Q)`) is an angle.
//! In: a loaded model and its source. Out: an error where a unit of another dimension is given
//! to it (`UNITS L = KG`), naming the use that makes it what it is.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, Node, SymbolKind};
use crate::mechanics::{Load, Orientation, Vector};

use super::super::diagnostic::Diagnostic;
use super::super::interp::LoadedModel;
use super::super::token::Span;
use super::super::units::size::{unit_size, Dimension};

const MASS: Dimension = [1, 0, 0, 0, 0, 0];
const LENGTH: Dimension = [0, 1, 0, 0, 0, 0];
const INERTIA: Dimension = [1, 2, 0, 0, 0, 0];
const FORCE: Dimension = [1, 1, -2, 0, 0, 0];
const TORQUE: Dimension = [1, 2, -2, 0, 0, 0];
const ANGLE: Dimension = [0, 0, 0, 1, 0, 0];
const NUMBER: Dimension = [0; 6];

/// What a constant is, by its use: its dimension and the use, in words.
type Uses = FxHashMap<String, (Dimension, String)>;

/// Errors for units whose dimension contradicts a constant's use.
pub(crate) fn units_against_use(m: &LoadedModel, source: &str) -> Vec<Diagnostic> {
    let uses = uses(m);
    let mut out = Vec::new();
    for input in &m.inputs {
        let given = input.unit.as_deref().map(|u| (u.to_string(), input.span.clone()));
        out.extend(given.and_then(|(unit, span)| contradiction(&uses, &input.name, &unit, span)));
    }
    for (name, unit) in &m.units {
        let span = units_item_span(source, name).unwrap_or(0..0);
        out.extend(contradiction(&uses, name, unit, span));
    }
    out
}

/// The error when `unit`, given to `name` at `span`, has another dimension than its use (an
/// angle may also be a plain number: radians are).
fn contradiction(uses: &Uses, name: &str, unit: &str, span: Span) -> Option<Diagnostic> {
    let (dimension, what) = uses.get(&name.to_ascii_uppercase())?;
    let size = unit_size(unit).ok()?;
    let fits = size.dim == *dimension || (*dimension == ANGLE && size.dim == NUMBER);
    (!fits).then(|| {
        let kind = kind(*dimension);
        Diagnostic::error(span, format!("`{name}` is {what}, but its unit {unit} is not {kind}"))
            .with_help(format!("give {name} a unit of {kind} (or fix the statement that uses it)"))
    })
}

/// A dimension in words, with its article.
fn kind(d: Dimension) -> &'static str {
    match d {
        MASS => "a mass",
        LENGTH => "a length",
        INERTIA => "a moment of inertia (mass times length squared)",
        FORCE => "a force",
        TORQUE => "a torque (force times length)",
        _ => "an angle",
    }
}

/// The constants (and, for angles, variables) whose dimension their use fixes; the first use
/// found names it.
fn uses(m: &LoadedModel) -> Uses {
    let model = &m.model;
    let ar = &model.ar;
    let mut uses = Uses::default();
    let mut note = |e: ExprId, dimension: Dimension, what: &dyn Fn() -> String, variables: bool| {
        if let Some(name) = lone_symbol(ar, e, variables) {
            uses.entry(name).or_insert_with(|| (dimension, what()));
        }
    };
    let masses = model
        .bodies()
        .iter()
        .map(|b| (&b.name, b.mass))
        .chain(model.particles.iter().map(|p| (&p.name, p.mass)));
    for (owner, mass) in masses {
        if let Some(e) = mass {
            note(e, MASS, &|| format!("the mass of {owner}"), false);
        }
    }
    for body in model.bodies() {
        let entries = body.inertia.iter().flat_map(|d| d.terms()).flat_map(|t| t.2.into_iter().flatten());
        for e in entries {
            note(e, INERTIA, &|| format!("a moment of inertia (of {})", body.name), false);
        }
    }
    for point in &model.points {
        let Some((_, vector)) = &point.position else { continue };
        for e in measures(vector) {
            note(e, LENGTH, &|| format!("a length (it places point {})", point.name), false);
        }
    }
    for load in model.loads() {
        let (vector, dimension, what) = match load {
            Load::Force { point, force } => {
                (force, FORCE, format!("a force (on point {})", model.point_name(*point)))
            }
            Load::Torque { frame, torque } => {
                (torque, TORQUE, format!("a torque (on {})", model.frame_name(*frame)))
            }
        };
        for e in measures(vector) {
            note(e, dimension, &|| what.clone(), false);
        }
    }
    for frame in &model.frames {
        let angles = match &frame.orientation {
            Some(Orientation::Axis { angle, .. }) => vec![*angle],
            Some(Orientation::BodyFixed { angles, .. } | Orientation::SpaceFixed { angles, .. }) => {
                angles.to_vec()
            }
            _ => Vec::new(),
        };
        for e in angles {
            note(e, ANGLE, &|| format!("an angle (it rotates {})", frame.name), true);
        }
    }
    uses
}

/// The measures of `vector` along its frames' axes.
fn measures(vector: &Vector) -> impl Iterator<Item = ExprId> + '_ {
    vector.terms.iter().flat_map(|(_, m)| m.iter().copied())
}

/// The upper-cased name of the constant (or, when `variables`, the coordinate or specified
/// quantity) `e` is, or is a number times.
fn lone_symbol(ar: &Arena, e: ExprId, variables: bool) -> Option<String> {
    let symbol = |id: ExprId| match ar.node(id) {
        Node::Symbol(s) => {
            let info = ar.symbol_info(*s);
            let wanted = matches!(info.kind, SymbolKind::Constant)
                || (variables
                    && matches!(
                        info.kind,
                        SymbolKind::Variable { order: 0 } | SymbolKind::Specified { order: 0 }
                    ));
            wanted.then(|| info.name.to_ascii_uppercase())
        }
        _ => None,
    };
    match ar.node(e) {
        Node::Symbol(_) => symbol(e),
        Node::Product(factors) => {
            let is_number = |f: &ExprId| matches!(ar.node(*f), Node::Rational(_) | Node::Float(_));
            let rest: Vec<ExprId> = factors.iter().copied().filter(|f| !is_number(f)).collect();
            (rest.len() == 1).then(|| symbol(rest[0])).flatten()
        }
        _ => None,
    }
}

/// Where `name` stands in a UNITS command of `source` (case-insensitive).
fn units_item_span(source: &str, name: &str) -> Option<Span> {
    let mut offset = 0;
    for line in source.split_inclusive('\n') {
        let upper = line.to_ascii_uppercase();
        if upper.trim_start().starts_with("UNITS ") {
            let key = name.to_ascii_uppercase();
            let at = upper.match_indices(&key).map(|(i, _)| i).find(|&i| {
                let before = upper[..i].chars().last().is_none_or(|c| !c.is_ascii_alphanumeric() && c != '_');
                let after = upper[i + key.len()..]
                    .chars()
                    .next()
                    .is_none_or(|c| !c.is_ascii_alphanumeric() && c != '_');
                before && after && i > upper.find("UNITS").unwrap_or(0) + 4
            });
            if let Some(i) = at {
                return Some(offset + i..offset + i + key.len());
            }
        }
        offset += line.len();
    }
    None
}
