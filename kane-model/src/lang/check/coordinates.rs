//! Coordinates without a kinematic equation: a variable that orients a frame or places a point
//! is a coordinate, and Kane's method needs its `q'`; without `Q2' = U2` the file's rules make
//! it a generalized speed, silently a different model. An error naming the variable, at the
//! statement it orients or places with.
//!
//! In: a loaded model (its speeds decided by FR(), FRSTAR() or KANE()). Out: one error for each
//! speed that appears in an orientation or a position.

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::Orientation;

use super::super::diagnostic::Diagnostic;
use super::super::interp::LoadedModel;
use super::super::token::Span;

/// Errors for the generalized speeds that orient a frame or place a point.
pub(crate) fn coordinates_without_kinematics(m: &LoadedModel) -> Vec<Diagnostic> {
    let model = &m.model;
    let speeds: Vec<SymbolId> = model.speeds().to_vec();
    let mut uses: Vec<(SymbolId, Span, String)> = Vec::new();
    for (i, frame) in model.frames.iter().enumerate() {
        let Some(orientation) = &frame.orientation else { continue };
        let span =
            m.sources.orientation_of(model, crate::mechanics::FrameId(i as u32)).cloned().unwrap_or(0..0);
        for s in model.ar.free_symbols(&orientation_entries(orientation)) {
            uses.push((s, span.clone(), format!("orients {}", frame.name)));
        }
    }
    for (from, to, r) in &model.position_edges {
        let span = m.sources.position_of(*from, *to).cloned().unwrap_or(0..0);
        let entries: Vec<ExprId> = r.terms.iter().flat_map(|(_, c)| *c).collect();
        for s in model.ar.free_symbols(&entries) {
            uses.push((
                s,
                span.clone(),
                format!("places {} from {}", model.point_name(*to), model.point_name(*from)),
            ));
        }
    }
    uses.sort_by_key(|(_, span, _)| span.start);
    let mut out: Vec<Diagnostic> = Vec::new();
    let mut named: Vec<SymbolId> = Vec::new();
    for (s, span, what) in uses {
        if !speeds.contains(&s) || named.contains(&s) {
            continue;
        }
        named.push(s);
        let name = &model.ar.symbol_info(s).name;
        out.push(
            Diagnostic::error(span, format!("{name} {what} but has no kinematic equation, so it was taken as a generalized speed"))
                .with_help(format!("a coordinate needs its derivative: add {name}' = <a speed> before KANE(), as Q1' = U1 does for Q1")),
        );
    }
    out
}

/// The expressions an orientation is made of.
fn orientation_entries(o: &Orientation) -> Vec<ExprId> {
    match o {
        Orientation::Axis { angle, .. } => vec![*angle],
        Orientation::BodyFixed { angles, .. } | Orientation::SpaceFixed { angles, .. } => angles.to_vec(),
        Orientation::EulerParameters(e) => e.to_vec(),
        Orientation::Rodrigues(g) => g.to_vec(),
        Orientation::Dcm(m) => m.iter().flatten().copied().collect(),
    }
}
