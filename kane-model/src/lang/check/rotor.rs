//! Assigned angular velocities against the orientations (the language reference, "Assigned
//! kinematics"). `W_B_A> = ...` must be the rate of B's orientation in A, with one idiom: a
//! frame oriented by a constant angle (`SIMPROT(B, RW1, 1, 0)`) and given an angular velocity
//! (`W_RW1_B> = U7*B1>`) turns while its direction cosines stay as written, its spin angle not
//! tracked. That is right for a rotor symmetric about the axis it turns on (its inertia the
//! same in every frame turned about it) with nothing placed or oriented off that axis by its
//! unit vectors, and wrong otherwise.
//!
//! In: a loaded model, its motions and its source. Out: an error for each angular velocity
//! that is neither, naming the assignment and the orientation, and for an untracked rotor,
//! what is not symmetric.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use crate::expr::ExprId;
use crate::mechanics::{FrameId, Model, Result, Vector};

use super::super::diagnostic::{line_column, Diagnostic};
use super::super::interp::LoadedModel;
use super::super::token::Span;
use super::marker::statement_text;
use super::zero::{Motions, Verdict};

/// States at which a rotor's axis is sampled.
const AXIS_SAMPLES: usize = 8;

/// The angular velocities the file sets that neither its orientations nor an untracked
/// symmetric rotor explain.
pub(super) fn angular_contradictions(
    m: &mut LoadedModel,
    motions: &Motions,
    source: &str,
) -> Vec<Diagnostic> {
    let mut claims: Vec<(FrameId, Span)> =
        m.sources.angular_velocities.iter().map(|(f, s)| (*f, s.clone())).collect();
    claims.sort_by_key(|c| c.1.start);
    let mut out = Vec::new();
    for (frame, span) in claims {
        if let Ok(Some(d)) = angular_claim(m, motions, source, frame, &span) {
            out.push(d);
        }
    }
    out
}

fn angular_claim(
    m: &mut LoadedModel,
    motions: &Motions,
    source: &str,
    frame: FrameId,
    span: &Span,
) -> Result<Option<Diagnostic>> {
    let model = &mut m.model;
    let f = &model.frames[frame.index()];
    let (Some(assigned), Some(_)) = (f.ang_vel.clone(), &f.orientation) else { return Ok(None) };
    let parent = f.parent.unwrap_or(model.newtonian());
    let implied = model.orientation_angular_velocity(frame)?;
    let Verdict::Differs { axis, assigned: a, implied: b } =
        motions.compare(model, &assigned, &implied, frame)?
    else {
        return Ok(None);
    };
    let orientation = m.sources.orientation_of(model, frame).cloned();
    let stmt = statement_text(source, span);
    if orientation_is_constant(model, motions, frame)? {
        return untracked_rotor(m, motions, source, frame, span, orientation.as_ref());
    }
    let from = orientation
        .as_ref()
        .map_or(String::new(), |s| format!(" by line {}", line_column(source, s.start).0));
    let message = format!(
        "`{stmt}` contradicts the angular velocity of {} in {} (the rates of its orientation) implied{from}: along {}{}> the assigned value is {a:.6} but the implied one is {b:.6} at a sampled state",
        model.frame_name(frame),
        model.frame_name(parent),
        model.frame_name(frame),
        axis + 1,
    );
    let mut d = Diagnostic::error(span.clone(), message).with_help(
        "make the two agree (the equations would take partial velocities from one and accelerations from the other), or mark a deliberate override with a trailing `% override` comment on the assignment's line",
    );
    if let Some(s) = orientation {
        d = d.with_note(s.clone(), format!("`{}` implies the other value", statement_text(source, &s)));
    }
    Ok(Some(d))
}

/// Whether `frame`'s direction cosines in its parent hold no time-dependent quantity.
fn orientation_is_constant(model: &mut Model, motions: &Motions, frame: FrameId) -> Result<bool> {
    let Some(parent) = model.frame_parent(frame) else { return Ok(false) };
    let dcm = model.dcm(parent, frame)?;
    let entries = motions.reading(model, &dcm.concat())?;
    let ar = &model.ar;
    Ok(ar.free_symbols(&entries).iter().all(|s| !ar.symbol_info(*s).kind.depends_on_time()))
}

/// The error for an untracked spin of `frame` that is not a symmetric rotor's, if it is not.
fn untracked_rotor(
    m: &mut LoadedModel,
    motions: &Motions,
    source: &str,
    frame: FrameId,
    span: &Span,
    orientation: Option<&Span>,
) -> Result<Option<Diagnostic>> {
    let model = &mut m.model;
    let w = model.frames[frame.index()].ang_vel.clone().unwrap_or_default();
    let Some(k) = fixed_axis(model, motions, &w, frame)? else {
        return Ok(Some(rotor_error(
            m,
            source,
            frame,
            span,
            orientation,
            None,
            "it does not turn about one axis fixed in it".into(),
        )));
    };
    let reason = asymmetry(m, motions, source, frame, k)?;
    Ok(reason.map(|r| rotor_error(m, source, frame, span, orientation, Some(k), r)))
}

/// What breaks the symmetry an untracked spin of `frame` about `k` needs, if anything.
fn asymmetry(
    m: &mut LoadedModel,
    motions: &Motions,
    source: &str,
    frame: FrameId,
    k: [f64; 3],
) -> Result<Option<String>> {
    let model = &mut m.model;
    let name = model.frame_name(frame).to_string();
    let (e1, e2) = perpendiculars(k);
    let numbers = |model: &mut Model, d: [f64; 3]| -> Result<Vector> {
        let c = d.map(|x| model.ar.float(x)).into_iter().collect::<std::result::Result<Vec<_>, _>>()?;
        Ok(Vector::new(frame, [c[0], c[1], c[2]]))
    };
    let (kv, v1, v2) = (numbers(model, k)?, numbers(model, e1)?, numbers(model, e2)?);
    if let Some(b) = model.bodies.iter().find(|b| b.frame == frame).cloned() {
        if let Some(inertia) = b.inertia {
            let ik = model.dyadic_dot(&inertia, &kv)?;
            let i1 = model.dyadic_dot(&inertia, &v1)?;
            let i2 = model.dyadic_dot(&inertia, &v2)?;
            let checks =
                [model.dot(&ik, &v1)?, model.dot(&ik, &v2)?, model.dot(&i1, &v2)?, model.dot(&i1, &v1)?];
            let i22 = model.dot(&i2, &v2)?;
            let z = model.ar.zero();
            let symmetric = motions.compare_scalars(model, &checks, &[z, z, z, i22])?;
            if !matches!(symmetric, Verdict::Same) {
                let line = m
                    .sources
                    .inertial
                    .get(&b.name.to_ascii_uppercase())
                    .map(|s| line_column(source, s.start).0);
                let at = line.map_or(String::new(), |l| format!(" (line {l})"));
                return Ok(Some(format!("the inertia of {}{at} is not symmetric about that axis", b.name)));
            }
        }
    }
    let model = &mut m.model;
    if let Some(child) =
        (0..model.frames.len()).map(|i| FrameId(i as u32)).find(|c| model.frame_parent(*c) == Some(frame))
    {
        return Ok(Some(format!(
            "frame {} is oriented from {name}, and turns with its untracked angle",
            model.frame_name(child)
        )));
    }
    for (from, to, r) in model.position_edges.clone() {
        let Some((_, c)) = r.terms.iter().find(|(f, _)| *f == frame) else { continue };
        let off = Vector::new(frame, *c);
        let across = [model.dot(&off, &v1)?, model.dot(&off, &v2)?];
        let z = model.ar.zero();
        if !matches!(motions.compare_scalars(model, &across, &[z, z])?, Verdict::Same) {
            let line = m.sources.position_of(from, to).map(|s| line_column(source, s.start).0).unwrap_or(0);
            return Ok(Some(format!(
                "line {line} places {} off that axis with {name}'s unit vectors",
                model.point_name(to)
            )));
        }
    }
    Ok(None)
}

/// The direction, in `frame`'s unit vectors, of every sampled value of `w` when they are all
/// along one (None otherwise, or when `w` is zero at every sample).
fn fixed_axis(model: &mut Model, motions: &Motions, w: &Vector, frame: FrameId) -> Result<Option<[f64; 3]>> {
    let c = model.express(w, frame)?;
    let c: Vec<ExprId> = motions.reading(model, &c)?;
    let syms = model.ar.free_symbols(&c);
    let mut rng = StdRng::seed_from_u64(0x726f746f72);
    let mut axis: Option<[f64; 3]> = None;
    for _ in 0..AXIS_SAMPLES {
        let values: rustc_hash::FxHashMap<_, f64> =
            syms.iter().map(|s| (*s, rng.random_range(0.5..2.0))).collect();
        let Ok(v) = model.ar.eval(&c, |s| values.get(&s).copied()) else { continue };
        let norm = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if !norm.is_finite() || norm < 1e-12 {
            continue;
        }
        let d = [v[0] / norm, v[1] / norm, v[2] / norm];
        match axis {
            None => axis = Some(d),
            Some(k) => {
                let cross = [k[1] * d[2] - k[2] * d[1], k[2] * d[0] - k[0] * d[2], k[0] * d[1] - k[1] * d[0]];
                if cross.iter().any(|x| x.abs() > 1e-9) {
                    return Ok(None);
                }
            }
        }
    }
    Ok(axis)
}

/// Two unit vectors perpendicular to the unit vector `k` and to each other.
fn perpendiculars(k: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let i = (0..3).min_by(|a, b| k[*a].abs().total_cmp(&k[*b].abs())).unwrap_or(0);
    let mut t = [0.0; 3];
    t[i] = 1.0;
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    let e1 = cross(k, t);
    let n = (e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]).sqrt();
    let e1 = e1.map(|x| x / n);
    (e1, cross(k, e1))
}

/// `frame`'s axis `k` written with its unit vectors (`RW11>`, or `0.6*RW11> + 0.8*RW12>`).
fn axis_text(model: &Model, frame: FrameId, k: [f64; 3]) -> String {
    let name = model.frame_name(frame);
    if let Some(i) = (0..3).find(|i| (k[*i].abs() - 1.0).abs() < 1e-12) {
        return format!("{}{name}{}>", if k[i] < 0.0 { "-" } else { "" }, i + 1);
    }
    let terms: Vec<String> =
        (0..3).filter(|i| k[*i].abs() > 1e-12).map(|i| format!("{:.6}*{name}{}>", k[i], i + 1)).collect();
    terms.join(" + ")
}

fn rotor_error(
    m: &LoadedModel,
    source: &str,
    frame: FrameId,
    span: &Span,
    orientation: Option<&Span>,
    axis: Option<[f64; 3]>,
    reason: String,
) -> Diagnostic {
    let model = &m.model;
    let name = model.frame_name(frame);
    let about = axis.map_or(String::new(), |k| format!(" about {}", axis_text(model, frame, k)));
    let held =
        orientation.map_or("its orientation".to_string(), |s| format!("`{}`", statement_text(source, s)));
    let message = format!(
        "`{}` turns {name}{about} while {held} holds its direction cosines fixed (an untracked spin): that is right only for a rotor symmetric about its axis, and {reason}",
        statement_text(source, span),
    );
    let mut d = Diagnostic::error(span.clone(), message).with_help(format!(
        "track the spin with an angle (SIMPROT with a variable angle Q and Q' = the spin rate), or make {name} a rotor symmetric about the axis"
    ));
    if let Some(s) = orientation {
        d = d.with_note(s.clone(), "the orientation held fixed");
    }
    d
}
