//! UNITS and INPUT unit tags against what a quantity is: a constant that is a body's or
//! particle's mass is a mass, one that places a point along a frame's axis (`P_O_P> = L*B1>`)
//! is a length. In: a loaded model and its source. Out: an error where a unit of another
//! dimension is given to it (`UNITS L = KG`), naming the use that makes it what it is.

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, Node, SymbolKind};

use super::super::diagnostic::Diagnostic;
use super::super::interp::LoadedModel;
use super::super::token::Span;
use super::super::units::size::{unit_size, Dimension};

const MASS: Dimension = [1, 0, 0, 0, 0, 0];
const LENGTH: Dimension = [0, 1, 0, 0, 0, 0];

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

/// The error when `unit`, given to `name` at `span`, has another dimension than its use.
fn contradiction(uses: &Uses, name: &str, unit: &str, span: Span) -> Option<Diagnostic> {
    let (dimension, what) = uses.get(&name.to_ascii_uppercase())?;
    let size = unit_size(unit).ok()?;
    (size.dim != *dimension).then(|| {
        Diagnostic::error(
            span,
            format!("`{name}` is {what}, but its unit {unit} is not a {}", kind(*dimension)),
        )
        .with_help(format!("give {name} a unit of {} (or fix the statement that uses it)", kind(*dimension)))
    })
}

fn kind(d: Dimension) -> &'static str {
    if d == MASS {
        "mass"
    } else {
        "length"
    }
}

/// The constants whose dimension their use fixes.
fn uses(m: &LoadedModel) -> Uses {
    let model = &m.model;
    let ar = &model.ar;
    let mut uses = Uses::default();
    let masses = model
        .bodies()
        .iter()
        .map(|b| (&b.name, b.mass))
        .chain(model.particles.iter().map(|p| (&p.name, p.mass)));
    for (owner, mass) in masses {
        if let Some(name) = mass.and_then(|e| lone_constant(ar, e)) {
            uses.entry(name).or_insert((MASS, format!("the mass of {owner}")));
        }
    }
    for point in &model.points {
        let Some((_, vector)) = &point.position else { continue };
        for (_, measures) in &vector.terms {
            for name in measures.iter().filter_map(|e| lone_constant(ar, *e)) {
                uses.entry(name).or_insert((LENGTH, format!("a length (it places point {})", point.name)));
            }
        }
    }
    uses
}

/// The upper-cased name of the constant `e` is, or is a number times.
fn lone_constant(ar: &Arena, e: ExprId) -> Option<String> {
    let symbol = |id: ExprId| match ar.node(id) {
        Node::Symbol(s) if matches!(ar.symbol_info(*s).kind, SymbolKind::Constant) => {
            Some(ar.symbol_info(*s).name.to_ascii_uppercase())
        }
        _ => None,
    };
    match ar.node(e) {
        Node::Symbol(_) => symbol(e),
        Node::Product(factors) => {
            let numbers =
                factors.iter().filter(|f| matches!(ar.node(**f), Node::Rational(_) | Node::Float(_)));
            let rest: Vec<ExprId> = factors
                .iter()
                .copied()
                .filter(|f| !matches!(ar.node(*f), Node::Rational(_) | Node::Float(_)))
                .collect();
            (numbers.count() + 1 == factors.len() && rest.len() == 1).then(|| symbol(rest[0])).flatten()
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
