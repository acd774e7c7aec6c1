//! Consistency of assigned kinematics: a velocity, acceleration or angular velocity set in the
//! file (`V_P_N> = ...`, V2PTS, `A_P_N> = ...`, A2PTS, `W_B_N> = ...`) must equal the one the
//! positions and orientations imply, where both are known. Kane's method takes partial
//! velocities from one and accelerations from the other, so a contradiction silently mixes two
//! different models.
//!
//! In: a loaded model and its source. Out: an error for each contradiction, at the assignment,
//! with a note at each line the implied value comes from; an assignment marked `% override`
//! is accepted.

use crate::mechanics::{FrameId, Model, PointId, Result, Vector};

use super::super::diagnostic::{line_column, Diagnostic};
use super::super::interp::{LoadedModel, Sources};
use super::super::token::Span;
use super::marker::{is_override, statement_text, MARKER};
use super::zero::{compare, Verdict};

/// What an assigned quantity is checked against.
struct Claim {
    /// The assignment.
    span: Span,
    /// The frame both are compared in.
    frame: FrameId,
    assigned: Vector,
    implied: Vector,
    /// "the velocity of P in N", for the message.
    what: String,
    /// The lines the implied value comes from.
    notes: Vec<Span>,
    /// The point at rest V2PTS carried the velocity from, when that point is located only by
    /// the points positioned from it (a contact point): a difference is then a rolling contact.
    contact: Option<String>,
}

/// The contradictions between assigned and implied kinematics, as errors.
pub(crate) fn consistency(m: &mut LoadedModel, source: &str) -> Vec<Diagnostic> {
    let mut claims = Vec::new();
    claims.extend(velocity_claims(&mut m.model, &m.sources));
    claims.extend(acceleration_claims(&mut m.model, &m.sources));
    claims.extend(angular_claims(&mut m.model, &m.sources));
    // Auxiliary speeds are zero in every motion: an assignment that adds them is consistent.
    let auxiliary = m.model.auxiliary_zero_map().unwrap_or_default();
    let mut errors = Vec::new();
    for c in claims {
        if is_override(source, &c.span) {
            continue;
        }
        let (Ok(assigned), Ok(implied)) =
            (m.model.subs_vector(&c.assigned, &auxiliary), m.model.subs_vector(&c.implied, &auxiliary))
        else {
            continue;
        };
        if let Ok(Verdict::Differs { axis, assigned, implied }) =
            compare(&mut m.model, &assigned, &implied, c.frame)
        {
            let unit = format!("{}{}>", m.model.frame_name(c.frame), axis + 1);
            errors.push(match &c.contact {
                Some(point) => rolling_contact(source, &c, point),
                None => contradiction(source, &c, &unit, assigned, implied),
            });
        }
    }
    errors
}

fn contradiction(source: &str, c: &Claim, unit: &str, assigned: f64, implied: f64) -> Diagnostic {
    let lines: Vec<String> =
        c.notes.iter().map(|s| format!("line {}", line_column(source, s.start).0)).collect();
    let from = if lines.is_empty() { String::new() } else { format!(" by {}", lines.join(", ")) };
    let message = format!(
        "`{}` contradicts {} implied{from}: along {unit} the assigned value is {assigned:.6} but the implied one \
         is {implied:.6} at a sampled state",
        statement_text(source, &c.span),
        c.what,
    );
    let mut d = Diagnostic::error(c.span.clone(), message).with_help(format!(
        "make the two agree (the equations would take partial velocities from one and accelerations \
         from the other), or mark a deliberate override with a trailing `% {MARKER}` comment on the \
         assignment's line"
    ));
    for s in &c.notes {
        d = d.with_note(s.clone(), format!("`{}` implies the other value", statement_text(source, s)));
    }
    d
}

/// A velocity carried from a contact point at rest that differs from the positions' rate: the
/// contact point is the body's material point there (rolling without slip), said as a warning.
fn rolling_contact(source: &str, c: &Claim, point: &str) -> Diagnostic {
    Diagnostic::warning(
        c.span.clone(),
        format!(
            "`{}` takes {point} as the moving body's material point at rest, a rolling contact: {} is not \
             the rate of the positions, whose point {point} moves over the body",
            statement_text(source, &c.span),
            c.what
        ),
    )
    .with_help(format!(
        "if {point} is fixed in that body instead, locate {point} from a point of it; mark the line `% {MARKER}` to silence this"
    ))
}

/// The statements the velocity of `p` in `frame` follows from: position relations up the tree
/// of points to a point whose velocity is set, and that setting.
fn velocity_lines(model: &Model, sources: &Sources, p: PointId, frame: FrameId) -> Vec<Span> {
    let mut lines = Vec::new();
    let mut x = p;
    for _ in 0..=model.points.len() {
        if model.points[x.index()].velocity.contains_key(&frame) {
            lines.extend(sources.velocities.get(&(x, frame)).cloned());
            break;
        }
        let Some((y, _)) = &model.points[x.index()].position else { break };
        lines.extend(sources.position_of(x, *y).cloned());
        x = *y;
    }
    lines
}

/// Each set velocity of a point located from another: `v_from + d/dt r` in the frame.
fn velocity_claims(model: &mut Model, sources: &Sources) -> Vec<Claim> {
    let mut claims = Vec::new();
    for (&(p, frame), span) in &sources.velocities {
        let Some(assigned) = model.points[p.index()].velocity.get(&frame).cloned() else { continue };
        let Some((from, r)) = model.points[p.index()].position.clone() else { continue };
        let Ok(implied) = implied_velocity(model, from, &r, frame) else { continue };
        let mut notes: Vec<Span> = sources.position_of(p, from).cloned().into_iter().collect();
        notes.extend(velocity_lines(model, sources, from, frame));
        let what = format!("the velocity of {} in {}", model.point_name(p), model.frame_name(frame));
        let by_v2pts = sources.carried_from.get(&(p, frame)) == Some(&from);
        let contact =
            (by_v2pts && is_contact(model, sources, from, frame)).then(|| model.point_name(from).to_string());
        claims.push(Claim { span: span.clone(), frame, assigned, implied, what, notes, contact });
    }
    claims
}

/// Whether `p` is at rest in `frame` by assignment and located by no other point.
fn is_contact(model: &Model, sources: &Sources, p: PointId, frame: FrameId) -> bool {
    let point = &model.points[p.index()];
    let at_rest = point
        .velocity
        .get(&frame)
        .is_some_and(|v| v.terms.iter().all(|(_, m)| m.iter().all(|x| model.ar.is_zero(*x))));
    at_rest && point.position.is_none() && sources.velocities.contains_key(&(p, frame))
}

fn implied_velocity(model: &mut Model, from: PointId, r: &Vector, frame: FrameId) -> Result<Vector> {
    let base = model.velocity(from, frame)?;
    let rel = model.dt_in(r, frame)?;
    model.add_vectors(&base, &rel)
}

/// Each set acceleration of a point whose velocity is known: the velocity's rate in the frame.
fn acceleration_claims(model: &mut Model, sources: &Sources) -> Vec<Claim> {
    let mut claims = Vec::new();
    for (&(p, frame), span) in &sources.accelerations {
        let Some(assigned) = model.points[p.index()].acceleration.get(&frame).cloned() else { continue };
        let Ok(v) = model.velocity(p, frame) else { continue };
        let Ok(implied) = model.dt_in(&v, frame) else { continue };
        let notes = velocity_lines(model, sources, p, frame);
        let what = format!("the acceleration of {} in {}", model.point_name(p), model.frame_name(frame));
        claims.push(Claim { span: span.clone(), frame, assigned, implied, what, notes, contact: None });
    }
    claims
}

/// Each set angular velocity of an oriented frame: the rates of its orientation.
fn angular_claims(model: &mut Model, sources: &Sources) -> Vec<Claim> {
    let mut claims = Vec::new();
    for (&frame, span) in &sources.angular_velocities {
        let f = &model.frames[frame.index()];
        let (Some(assigned), Some(_)) = (f.ang_vel.clone(), &f.orientation) else { continue };
        let Ok(implied) = model.orientation_angular_velocity(frame) else { continue };
        let notes = sources.orientations.get(&frame).cloned().into_iter().collect();
        let parent = model.frames[frame.index()].parent.unwrap_or(model.newtonian());
        let what = format!(
            "the angular velocity of {} in {} (the rates of its orientation)",
            model.frame_name(frame),
            model.frame_name(parent)
        );
        claims.push(Claim { span: span.clone(), frame, assigned, implied, what, notes, contact: None });
    }
    claims
}

#[cfg(test)]
mod tests {
    use super::*;

    const PENDULUM: &str = "NEWTONIAN N\nBODIES B\nPOINT O\nVARIABLES Q', U'\nCONSTANTS L\n\
        SIMPROT(N, B, 3, Q)\nQ' = U\nV_O_N> = 0>\nA_O_N> = 0>\nP_O_BO> = L*B1>\nV2PTS(N, B, O, BO)\n";

    fn errors(src: &str) -> Vec<Diagnostic> {
        let mut m = crate::lang::load("t.al", src).unwrap();
        consistency(&mut m, src)
    }

    #[test]
    fn consistent_assignments_pass() {
        assert!(errors(PENDULUM).is_empty());
        assert!(errors(&format!("{PENDULUM}A_BO_N> = -L*U^2*B1> + L*U'*B2>\nW_B_N> = U*B3>\n")).is_empty());
    }

    #[test]
    fn a_contradiction_names_the_lines_it_comes_from() {
        let src = format!("{PENDULUM}A_BO_N> = L*U'*B2>\n");
        let e = errors(&src);
        assert_eq!(e.len(), 1, "{e:?}");
        assert!(e[0].message.starts_with("`A_BO_N> = L*U'*B2>` contradicts the acceleration of BO in N"));
        // The acceleration follows from the V2PTS line (which set the velocity).
        assert_eq!(e[0].notes.len(), 1);
        assert_eq!(statement_text(&src, &e[0].notes[0].0), "V2PTS(N, B, O, BO)");
        let marked = format!("{PENDULUM}A_BO_N> = L*U'*B2> % override\n");
        assert!(errors(&marked).is_empty());
    }
}
