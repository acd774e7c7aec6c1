//! A model read as a tree of links: each moving frame turns about one axis of its parent by a
//! coordinate whose rate is one generalized speed; each point is fixed in one link (or in the
//! Newtonian frame) at a parameter-only offset from that link's pivot. `None` when the model is
//! not such a tree.

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId, SymbolKind};
use crate::mechanics::{FrameId, KaneEquations, Model, Orientation, PointId, Vector};

use super::super::error::Result;
use super::spatial::{add, V3};

/// One link: a frame turning about one of its parent's axes.
#[derive(Clone, Debug)]
pub(crate) struct Link {
    /// The link's frame.
    pub frame: FrameId,
    /// The parent link; `None` for a link turning in the Newtonian frame.
    pub parent: Option<usize>,
    /// The rotation axis, 0, 1 or 2, the same in both frames.
    pub axis: usize,
    /// +1 or -1: the rotation is `sign * q` about the axis.
    pub sign: i8,
    /// Position in the equations' speeds of this link's speed `u = q'`.
    pub speed: usize,
    /// The pivot from the parent's pivot, in parent components (zero for a root link).
    pub offset: V3,
}

/// Where a point is fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Attach {
    /// Fixed in the Newtonian frame.
    Base,
    /// Fixed in a link at an offset from its pivot, in link components.
    Link(usize, V3),
}

/// The links of a model, parents before children, and where its points are.
pub(crate) struct Links {
    /// The links.
    pub links: Vec<Link>,
    /// The link of each frame.
    pub of_frame: FxHashMap<FrameId, usize>,
    /// Where each reachable point is.
    pub points: FxHashMap<PointId, Attach>,
}

/// The links of `model` when it is a tree of simple rotations whose speeds are the joint rates.
pub(crate) fn links(model: &mut Model, eqs: &KaneEquations) -> Result<Option<Links>> {
    let Some((mut links, of_frame)) = frames(model, eqs) else { return Ok(None) };
    let Some(points) = attach_points(model, &mut links, &of_frame)? else { return Ok(None) };
    Ok(Some(Links { links, of_frame, points }))
}

/// True when every moving frame is a simple rotation by a coordinate with `q' = u` and the
/// model has no constraints (reads the model only).
pub(crate) fn is_candidate(model: &Model, eqs: &KaneEquations) -> bool {
    frames(model, eqs).is_some()
}

/// The links of `model` without their points (reads the model only); `None` when it is not a
/// tree of simple rotations whose speeds are the joint rates.
pub(crate) fn frames_of(model: &Model, eqs: &KaneEquations) -> Option<Vec<Link>> {
    frames(model, eqs).map(|(links, _)| links)
}

fn frames(model: &Model, eqs: &KaneEquations) -> Option<(Vec<Link>, FxHashMap<FrameId, usize>)> {
    let n = eqs.speeds.len();
    let constrained = model.constraints.is_some()
        || !model.configuration_constraints.is_empty()
        || !model.auxiliary.speeds.is_empty();
    if constrained || eqs.constraints.is_some() || eqs.coordinates.len() != n || n == 0 {
        return None;
    }
    let ar = &model.ar;
    let mut found: Vec<(FrameId, FrameId, usize, i8, usize)> = Vec::new();
    let mut used = vec![false; n];
    for (i, f) in model.frames.iter().enumerate().skip(1) {
        let (Some(parent), Some(Orientation::Axis { axis, angle })) = (f.parent, &f.orientation) else {
            if f.parent.is_none() && f.orientation.is_none() && f.ang_vel.is_none() {
                continue;
            }
            return None;
        };
        let q = ar.as_symbol(*angle)?;
        let qi = eqs.coordinates.iter().position(|c| *c == q)?;
        let u = ar.as_symbol(eqs.kinematics[qi])?;
        let ui = eqs.speeds.iter().position(|s| *s == u)?;
        if f.ang_vel.is_some() || used[ui] {
            return None;
        }
        used[ui] = true;
        found.push((FrameId(i as u32), parent, usize::from(axis.unsigned_abs()) - 1, axis.signum(), ui));
    }
    if used.iter().any(|u| !u) {
        return None;
    }
    order(model, found)
}

/// The links sorted parents first; `None` when a link's parent is neither the Newtonian frame
/// nor a link.
fn order(
    model: &Model,
    found: Vec<(FrameId, FrameId, usize, i8, usize)>,
) -> Option<(Vec<Link>, FxHashMap<FrameId, usize>)> {
    let mut sorted = found;
    sorted.sort_by_key(|l| (depth(model, l.0), l.0));
    let mut of_frame = FxHashMap::default();
    let mut links = Vec::with_capacity(sorted.len());
    let z = model.ar.zero();
    for (frame, parent, axis, sign, speed) in sorted {
        let parent = if parent == model.newtonian { None } else { Some(*of_frame.get(&parent)?) };
        of_frame.insert(frame, links.len());
        links.push(Link { frame, parent, axis, sign, speed, offset: [z; 3] });
    }
    Some((links, of_frame))
}

/// The number of frames above `f` in the orientation tree.
fn depth(model: &Model, mut f: FrameId) -> usize {
    let mut d = 0;
    while let Some(p) = model.frames[f.index()].parent {
        d += 1;
        f = p;
    }
    d
}

/// True when `e` reads constants only.
pub(crate) fn parameter_only(model: &Model, e: ExprId) -> bool {
    let ar = &model.ar;
    ar.free_symbols(&[e]).iter().all(|s| ar.symbol_info(*s).kind == SymbolKind::Constant)
}

/// Points reached from those at rest in the Newtonian frame through position vectors fixed in
/// one frame; each link's pivot and offset are set on the way. `None` for a position that
/// fits no link.
fn attach_points(
    model: &mut Model,
    links: &mut [Link],
    of_frame: &FxHashMap<FrameId, usize>,
) -> Result<Option<FxHashMap<PointId, Attach>>> {
    let n = model.newtonian;
    let mut at: FxHashMap<PointId, Attach> = FxHashMap::default();
    let mut queue = std::collections::VecDeque::new();
    for (i, p) in model.points.iter().enumerate() {
        let rest = p
            .velocity
            .get(&n)
            .is_some_and(|v| v.terms.iter().all(|t| t.1.iter().all(|x| model.ar.is_zero(*x))));
        if rest {
            at.insert(PointId(i as u32), Attach::Base);
            queue.push_back(PointId(i as u32));
        }
    }
    let mut pivots: Vec<Option<PointId>> = vec![None; links.len()];
    let edges = model.position_edges.clone();
    while let Some(a) = queue.pop_front() {
        for (from, to, r) in &edges {
            let (next, r) = if *from == a {
                (*to, r.clone())
            } else if *to == a {
                (*from, model.scale(r, model.ar.minus_one())?)
            } else {
                continue;
            };
            if at.contains_key(&next) {
                continue;
            }
            let step = Step { model: &mut *model, links: &mut *links, of_frame, pivots: &mut pivots };
            let Some(place) = step.through(a, at[&a], &r)? else { return Ok(None) };
            at.insert(next, place);
            queue.push_back(next);
        }
    }
    if pivots.iter().any(Option::is_none) {
        return Ok(None);
    }
    Ok(Some(at))
}

/// One position step, with the links' pivots it may set.
struct Step<'a> {
    model: &'a mut Model,
    links: &'a mut [Link],
    of_frame: &'a FxHashMap<FrameId, usize>,
    pivots: &'a mut Vec<Option<PointId>>,
}

impl Step<'_> {
    /// Where the point at `r` from `a` (placed at `place`) is: `r` must have parameter-only
    /// measure numbers in the deepest frame among its terms' and `a`'s; `None` when it fits no
    /// link.
    fn through(self, a: PointId, place: Attach, r: &Vector) -> Result<Option<Attach>> {
        let model = self.model;
        let here = match place {
            Attach::Base => None,
            Attach::Link(k, _) => Some(k),
        };
        let mut frames: Vec<FrameId> = r.terms.iter().map(|t| t.0).collect();
        frames.extend(here.map(|k| self.links[k].frame));
        let Some(target) = frames.into_iter().max_by_key(|f| (depth(model, *f), *f)) else {
            return Ok(Some(place));
        };
        let m = model.express(r, target)?;
        if !m.iter().all(|x| parameter_only(model, *x)) {
            return Ok(None);
        }
        if target == model.newtonian {
            return Ok(Some(Attach::Base));
        }
        let Some(&k) = self.of_frame.get(&target) else { return Ok(None) };
        if let Attach::Link(h, o) = place {
            if h == k {
                return Ok(Some(Attach::Link(k, add(&mut model.ar, &o, &m)?)));
            }
        }
        if self.links[k].parent != here {
            return Ok(None);
        }
        match self.pivots[k] {
            Some(p) if p != a => return Ok(None),
            Some(_) => {}
            None => {
                self.pivots[k] = Some(a);
                if let Attach::Link(_, o) = place {
                    self.links[k].offset = o;
                }
            }
        }
        Ok(Some(Attach::Link(k, m)))
    }
}

/// True when the symbols of `e` are constants or among `states`.
pub(crate) fn reads_only(model: &Model, e: ExprId, states: &[SymbolId]) -> bool {
    let ar = &model.ar;
    ar.free_symbols(&[e])
        .iter()
        .all(|s| ar.symbol_info(*s).kind == SymbolKind::Constant || states.contains(s))
}
