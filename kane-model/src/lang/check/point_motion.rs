//! Assigned velocities and accelerations of points, against what Autolev's meaning of them
//! allows (the language reference, "Assigned kinematics").
//!
//! A velocity set by V2PTS is the velocity of the body's point that is at the named point now:
//! at a wheel's contact that is not the rate of the contact's position, and rolling models need
//! exactly that. So a velocity is accepted when it is the rate of the point's position from a
//! point whose velocity is set, or the velocity of a rigid body's point there (a body's mass
//! centre: of its own body; a particle: no body; a point without mass: of any frame). Only for
//! points with mass is the acceleration checked: against the rate of the velocity the model
//! uses for them.
//!
//! In: a loaded model, its motions and its source. Out: the contradictions found, each naming
//! the assignment and the lines the other value comes from.

use rustc_hash::FxHashSet;

use crate::mechanics::{FrameId, Model, PointId, Result, Vector};

use super::super::interp::{KinematicSource, LoadedModel, Sources};
use super::super::token::Span;
use super::zero::{Motions, Verdict};
use super::Contradiction;

/// Most points a velocity is compared from.
const MOST_BASES: usize = 8;

/// What carries mass at a point.
#[derive(Clone, Copy, PartialEq)]
enum Carrier {
    /// The mass centre of the body fixed in this frame.
    MassCentre(FrameId),
    /// A particle.
    Particle,
    /// Nothing.
    Massless,
}

/// The velocities the file sets that no reading of Autolev's allows.
pub(super) fn velocity_contradictions(m: &mut LoadedModel, motions: &Motions) -> Vec<Contradiction> {
    let mut claims: Vec<(PointId, FrameId, KinematicSource)> =
        m.sources.velocities.iter().map(|(&(p, f), s)| (p, f, s.clone())).collect();
    claims.sort_by_key(|c| c.2.span.start);
    let mut out = Vec::new();
    for (point, frame, source) in claims {
        if let Ok(Some(c)) = velocity_claim(&mut m.model, &m.sources, motions, point, frame, &source) {
            out.push(c);
        }
    }
    out
}

/// The contradiction of one velocity setting, if it has one.
fn velocity_claim(
    model: &mut Model,
    sources: &Sources,
    motions: &Motions,
    point: PointId,
    frame: FrameId,
    source: &KinematicSource,
) -> Result<Option<Contradiction>> {
    let Some(assigned) = model.points[point.index()].velocity.get(&frame).cloned() else { return Ok(None) };
    let carrier = carrier(model, point);
    let mut first: Option<(PointId, Vector, Verdict)> = None;
    for base in bases(model, sources, point, frame) {
        let (Ok(r), Ok(v_base)) = (model.position(point, base), model.velocity(base, frame)) else {
            continue;
        };
        let rate = model.dt_in(&r, frame)?;
        let moved = model.add_vectors(&v_base, &rate)?;
        match motions.compare(model, &assigned, &moved, frame)? {
            Verdict::Same | Verdict::Unknown => return Ok(None),
            d => {
                if first.is_none() {
                    first = Some((base, moved, d));
                }
            }
        }
        for body in rigid_frames(model, carrier, frame) {
            let Ok(w) = model.angular_velocity(body, frame) else { continue };
            let carried = model.cross(&w, &r)?;
            let carried = model.add_vectors(&v_base, &carried)?;
            if matches!(motions.compare(model, &assigned, &carried, frame)?, Verdict::Same | Verdict::Unknown)
            {
                return Ok(None);
            }
        }
    }
    let Some((base, _, Verdict::Differs { axis, assigned, implied })) = first else { return Ok(None) };
    let mut notes: Vec<Span> = model
        .position_path(point, base)
        .iter()
        .filter_map(|(a, b)| sources.position_of(*a, *b).cloned())
        .collect();
    notes.extend(sources.velocities.get(&(base, frame)).map(|s| s.span.clone()));
    let what = format!("the velocity of {} in {}", model.point_name(point), model.frame_name(frame));
    let why = match (carrier, source.theorem) {
        (Carrier::MassCentre(body), Some((_, on, _))) if on != body => Some(format!(
            "it carries the velocity of a point of {} to {}, the mass centre of {}, which moves with {}",
            model.frame_name(on),
            model.point_name(point),
            model.frame_name(body),
            model.frame_name(body)
        )),
        _ => None,
    };
    Ok(Some(Contradiction { span: source.span.clone(), what, frame, axis, assigned, implied, notes, why }))
}

/// The accelerations the file sets, of points with mass, that are not the rate of their
/// velocity.
pub(super) fn acceleration_contradictions(m: &mut LoadedModel, motions: &Motions) -> Vec<Contradiction> {
    let mut claims: Vec<(PointId, FrameId, KinematicSource)> =
        m.sources.accelerations.iter().map(|(&(p, f), s)| (p, f, s.clone())).collect();
    claims.sort_by_key(|c| c.2.span.start);
    let mut out = Vec::new();
    for (point, frame, source) in claims {
        if carrier(&m.model, point) == Carrier::Massless {
            continue;
        }
        let model = &mut m.model;
        let Some(assigned) = model.points[point.index()].acceleration.get(&frame).cloned() else { continue };
        let Ok(v) = model.velocity(point, frame) else { continue };
        // The rate is taken with the frames' motions as they stand at the end.
        let frames: Vec<FrameId> = v.terms().iter().map(|(f, _)| *f).collect();
        if frames_restated_after(model, &m.sources, &frames, m.sources.rank(source.span.start)) {
            continue;
        }
        let Ok(implied) = model.dt_in(&v, frame) else { continue };
        let Ok(Verdict::Differs { axis, assigned, implied }) =
            motions.compare(model, &assigned, &implied, frame)
        else {
            continue;
        };
        let notes = velocity_lines(model, &m.sources, point, frame);
        let what = format!("the acceleration of {} in {}", model.point_name(point), model.frame_name(frame));
        out.push(Contradiction {
            span: source.span.clone(),
            what,
            frame,
            axis,
            assigned,
            implied,
            notes,
            why: None,
        });
    }
    out
}

/// The statements the velocity of `p` in `frame` follows from: its setting, or the position
/// relations up the tree of points to a point whose velocity is set, and that setting.
pub(super) fn velocity_lines(model: &Model, sources: &Sources, p: PointId, frame: FrameId) -> Vec<Span> {
    let mut lines = Vec::new();
    let mut x = p;
    for _ in 0..=model.points.len() {
        if model.points[x.index()].velocity.contains_key(&frame) {
            lines.extend(sources.velocities.get(&(x, frame)).map(|s| s.span.clone()));
            break;
        }
        let Some((y, _)) = &model.points[x.index()].position else { break };
        lines.extend(sources.position_of(x, *y).cloned());
        x = *y;
    }
    lines
}

/// What carries mass at `p`.
fn carrier(model: &Model, p: PointId) -> Carrier {
    let massive = |m: Option<crate::expr::ExprId>| m.is_some_and(|m| !model.ar.is_zero(m));
    if let Some(b) = model.bodies.iter().find(|b| b.mass_center == p && massive(b.mass)) {
        return Carrier::MassCentre(b.frame);
    }
    if model.particles.iter().any(|q| q.point == p && massive(q.mass)) {
        return Carrier::Particle;
    }
    Carrier::Massless
}

/// The frames whose points' velocity a setting at a point carried by `carrier` may be.
fn rigid_frames(model: &Model, carrier: Carrier, frame: FrameId) -> Vec<FrameId> {
    match carrier {
        Carrier::MassCentre(body) => vec![body],
        Carrier::Particle => Vec::new(),
        Carrier::Massless => {
            (0..model.frames.len()).map(|i| FrameId(i as u32)).filter(|f| *f != frame).collect()
        }
    }
}

/// The points whose set velocities `p`'s setting is compared from: the point a theorem carried
/// it from, points its value read, its neighbours in the tree of positions and the roots of
/// that tree, each with a velocity set in `frame` by an earlier statement (or by the frame's
/// origin, at rest) that does not itself follow from `p`'s, reached by positions not restated
/// since.
fn bases(model: &Model, sources: &Sources, p: PointId, frame: FrameId) -> Vec<PointId> {
    let at = sources.velocities.get(&(p, frame)).map_or(usize::MAX, |s| sources.rank(s.span.start));
    let mut candidates: Vec<PointId> =
        sources.velocities.get(&(p, frame)).map(|s| s.bases().collect()).unwrap_or_default();
    if let Some((parent, _)) = &model.points[p.index()].position {
        candidates.push(*parent);
    }
    for (from, to, _) in &model.position_edges {
        if *to == p {
            candidates.push(*from);
        } else if *from == p {
            candidates.push(*to);
        }
    }
    let component = model.position_component(p);
    candidates.extend(component.iter().filter(|x| model.points[x.index()].position.is_none()));
    let mut seen = FxHashSet::default();
    candidates
        .into_iter()
        .filter(|y| *y != p && seen.insert(*y))
        .filter(|y| model.points[y.index()].velocity.contains_key(&frame) && component.contains(y))
        // What a statement says is checked against what came before it.
        .filter(|y| sources.velocities.get(&(*y, frame)).is_none_or(|s| sources.rank(s.span.start) <= at))
        // A position restated after the claim is not the geometry the claim was made in.
        .filter(|y| {
            model
                .position_path(p, *y)
                .iter()
                .all(|(a, b)| sources.position_of(*a, *b).is_none_or(|s| sources.rank(s.start) <= at))
        })
        // So is a frame of those positions turned or oriented anew after it.
        .filter(|y| !frames_restated_after(model, sources, &model.position_path_frames(p, *y), at))
        .filter(|y| !follows_from(model, sources, *y, p, frame))
        .take(MOST_BASES)
        .collect()
}

/// Whether any of `frames`, or a frame above one in the tree of orientations, has its angular
/// velocity or orientation set by a statement after `at`.
fn frames_restated_after(model: &Model, sources: &Sources, frames: &[FrameId], at: usize) -> bool {
    let mut seen = FxHashSet::default();
    for f in frames {
        let mut next = Some(*f);
        while let Some(g) = next {
            if !seen.insert(g) {
                break;
            }
            let later = |s: Option<&Span>| s.is_some_and(|s| sources.rank(s.start) > at);
            if later(sources.angular_velocities.get(&g)) || later(sources.orientation_of(model, g)) {
                return true;
            }
            next = model.frame_parent(g);
        }
    }
    false
}

/// Whether the velocity of `y` in `frame` is set from `p`'s, directly or through others.
fn follows_from(model: &Model, sources: &Sources, y: PointId, p: PointId, frame: FrameId) -> bool {
    let mut stack = vec![y];
    let mut seen = FxHashSet::default();
    while let Some(x) = stack.pop() {
        if x == p {
            return true;
        }
        if !seen.insert(x) {
            continue;
        }
        match sources.velocities.get(&(x, frame)) {
            Some(s) => stack.extend(s.bases()),
            None if !model.points[x.index()].velocity.contains_key(&frame) => {
                stack.extend(model.points[x.index()].position.as_ref().map(|(parent, _)| *parent));
            }
            None => {}
        }
    }
    false
}
