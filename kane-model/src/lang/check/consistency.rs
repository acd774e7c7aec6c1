//! Consistency of assigned kinematics with Autolev's meaning of them (the language reference,
//! "Assigned kinematics"): a velocity, acceleration or angular velocity set in the file must be
//! one the positions and orientations allow, where both are known. Kane's method takes partial
//! velocities from one and accelerations from the other, so a contradiction silently mixes two
//! different models; Autolev's own idioms (a wheel's material contact point by V2PTS, a
//! symmetric rotor whose angle is not tracked) are not contradictions.
//!
//! In: a loaded model and its source. Out: an error for each contradiction, at the assignment,
//! with a note at each line the other value comes from; an assignment marked `% override` is
//! accepted.

use crate::mechanics::FrameId;

use super::super::diagnostic::{line_column, Diagnostic};
use super::super::interp::LoadedModel;
use super::super::token::Span;
use super::marker::{is_override, statement_text, MARKER};
use super::zero::Motions;
use super::{point_motion, rotor};

/// An assignment and the other value it contradicts.
pub(super) struct Contradiction {
    /// The assignment.
    pub(super) span: Span,
    /// "the velocity of P in N", for the message.
    pub(super) what: String,
    /// The frame the two values were compared in.
    pub(super) frame: FrameId,
    /// The frame's axis (0, 1, 2) along which they differ, and the two values there.
    pub(super) axis: usize,
    pub(super) assigned: f64,
    pub(super) implied: f64,
    /// The lines the other value comes from.
    pub(super) notes: Vec<Span>,
    /// Why the assignment cannot be right, when more can be said.
    pub(super) why: Option<String>,
}

/// The contradictions between assigned and implied kinematics, as errors.
pub(crate) fn consistency(m: &mut LoadedModel, source: &str) -> Vec<Diagnostic> {
    let still = m.unstated_variables();
    let Ok(motions) = Motions::of(&mut m.model, &still) else { return Vec::new() };
    let mut found = point_motion::velocity_contradictions(m, &motions);
    found.extend(point_motion::acceleration_contradictions(m, &motions));
    let mut errors: Vec<Diagnostic> = found
        .into_iter()
        .filter(|c| !is_override(source, &c.span))
        .map(|c| contradiction(m, source, &c))
        .collect();
    errors.extend(
        rotor::angular_contradictions(m, &motions, source)
            .into_iter()
            .filter(|d| !is_override(source, &d.span)),
    );
    errors
}

fn contradiction(m: &LoadedModel, source: &str, c: &Contradiction) -> Diagnostic {
    let unit = format!("{}{}>", m.model.frame_name(c.frame), c.axis + 1);
    let lines: Vec<String> =
        c.notes.iter().map(|s| format!("line {}", line_column(source, s.start).0)).collect();
    let from = if lines.is_empty() { String::new() } else { format!(" by {}", lines.join(", ")) };
    let why = c.why.as_ref().map_or(String::new(), |w| format!(" ({w})"));
    let message = format!(
        "`{}` contradicts {} implied{from}{why}: along {unit} the assigned value is {:.6} but the implied one is {:.6} at a sampled state",
        statement_text(source, &c.span),
        c.what,
        c.assigned,
        c.implied,
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

#[cfg(test)]
mod tests {
    use super::*;

    const PENDULUM: &str = "NEWTONIAN N\nBODIES B\nPOINT O\nVARIABLES Q', U'\nCONSTANTS L\n\
        SIMPROT(N, B, 3, Q)\nQ' = U\nV_O_N> = 0>\nA_O_N> = 0>\nP_O_BO> = L*B1>\nV2PTS(N, B, O, BO)\nMASS B = 1\n";

    fn errors(src: &str) -> Vec<Diagnostic> {
        let mut m = crate::lang::load("t.al", src).unwrap();
        consistency(&mut m, src)
    }

    #[test]
    fn consistent_assignments_pass() {
        assert!(errors(PENDULUM).is_empty());
        let more = format!("{PENDULUM}A_BO_N> = -L*U^2*B1> + L*U'*B2>\nW_B_N> = U*B3>\nW_B_N> = Q'*N3>\n");
        assert!(errors(&more).is_empty(), "{:?}", errors(&more));
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
