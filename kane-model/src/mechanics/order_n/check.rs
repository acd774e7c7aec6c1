//! A numerical check of explicit speed rates against Kane's equations `Fr + Fr* = 0` by their
//! virtual power: at pseudo-random states and virtual speeds `w`, `w . (Fr + Fr*)` summed from
//! the model's velocities, accelerations, masses and loads. That reads what a chain's kinematics
//! already holds (O(n^2)), where forming `M u' = f` costs O(n^3); the order-n form replaces the
//! mass-matrix form only where they agree.

use rustc_hash::{FxHashMap, FxHashSet};

use crate::expr::{ExprId, SymbolId, SymbolKind};
use crate::mechanics::{FrameId, KaneEquations, Load, Model, Vector};

use super::super::error::Result;
use super::super::kane::MassMotion;

type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

/// Largest accepted `|w . (Fr + Fr*)|` relative to the sum of its terms' magnitudes (a backward
/// error, blind to the mass matrix's conditioning, which grows with a chain's length).
const TOLERANCE: f64 = 1e-9;

/// The symbolic pieces of the virtual power: the masses' motions, and each load with the
/// velocity (of its point) or angular velocity (of its body) it works through.
struct Power {
    masses: Vec<MassMotion>,
    loads: Vec<(Vector, Vector)>,
}

/// True when `rates` solve Kane's equations of `model` at two pseudo-random points.
pub(crate) fn agrees(model: &mut Model, eqs: &KaneEquations, rates: &[ExprId]) -> Result<bool> {
    let power = power_terms(model)?;
    let Some(dcms) = frame_dcms(model, &power)? else { return Ok(false) };
    let mut roots = Roots::default();
    let dcm_at: Vec<usize> = dcms.iter().map(|(_, _, m)| roots.push(m.as_flattened())).collect();
    let places = Places::of(&mut roots, &power);
    let frames = Frames { newtonian: model.newtonian, dcms: &dcms, dcm_at: &dcm_at };
    let check = Check { model, eqs, rates, roots: &roots.ids, frames, places: &places };
    Ok((0..2u64).all(|seed| check.agrees_at(seed).unwrap_or(false)))
}

fn power_terms(model: &mut Model) -> Result<Power> {
    let n = model.newtonian;
    let masses = model.mass_motions()?;
    let mut loads = Vec::new();
    for load in model.loads.clone() {
        loads.push(match load {
            Load::Force { point, force } => (force, model.velocity(point, n)?),
            Load::Torque { frame, torque } => (torque, model.angular_velocity(frame, n)?),
        });
    }
    Ok(Power { masses, loads })
}

/// A direction cosine matrix from a parent: `(parent, frame, parent_i . frame_j)`.
type ParentDcm = (FrameId, FrameId, [[ExprId; 3]; 3]);

/// Each frame the pieces name, with its ancestors, and its direction cosines from its parent;
/// `None` when a frame is not oriented in the Newtonian frame.
fn frame_dcms(model: &mut Model, power: &Power) -> Result<Option<Vec<ParentDcm>>> {
    let mut frames: Vec<FrameId> = Vec::new();
    let mut vectors: Vec<&Vector> = power.loads.iter().flat_map(|(a, b)| [a, b]).collect();
    for m in &power.masses {
        vectors.extend([&m.velocity, &m.acceleration]);
        if let Some((w, alpha, inertia)) = &m.rotation {
            vectors.extend([w, alpha]);
            frames.extend(inertia.terms.iter().flat_map(|t| [t.0, t.1]));
        }
    }
    frames.extend(vectors.iter().flat_map(|v| v.terms.iter().map(|t| t.0)));
    let mut out = Vec::new();
    let mut seen: FxHashSet<FrameId> = FxHashSet::default();
    while let Some(f) = frames.pop() {
        if f == model.newtonian || !seen.insert(f) {
            continue;
        }
        let Some(parent) = model.frames[f.index()].parent else { return Ok(None) };
        out.push((parent, f, model.dcm(parent, f)?));
        frames.push(parent);
    }
    Ok(Some(out))
}

/// Values of the symbols at one pseudo-random point: constants in [0.5, 1.5), states in [-1, 1).
fn sample(model: &Model, eqs: &KaneEquations, seed: u64) -> (FxHashMap<SymbolId, f64>, Vec<f64>) {
    let mut state = 0x9E37_79B9_7F4A_7C15u64 ^ seed.wrapping_mul(0xD1B5_4A32_D192_ED03);
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut values: FxHashMap<SymbolId, f64> = FxHashMap::default();
    for (s, info) in model.ar.symbols() {
        match info.kind {
            SymbolKind::Constant => {
                values.insert(s, 0.5 + next());
            }
            SymbolKind::Time => {
                values.insert(s, 0.375);
            }
            _ => {}
        }
    }
    for s in eqs.coordinates.iter().chain(&eqs.speeds) {
        values.insert(*s, 2.0 * next() - 1.0);
    }
    let virtual_speeds = eqs.speeds.iter().map(|_| 2.0 * next() - 1.0).collect();
    (values, virtual_speeds)
}

/// Symbolic roots in one list, each vector's and dyadic's measure numbers at known places.
#[derive(Default)]
struct Roots {
    ids: Vec<ExprId>,
}

impl Roots {
    fn vector(&mut self, v: &Vector) -> Vec<(FrameId, usize)> {
        v.terms.iter().map(|(f, m)| (*f, self.push(m))).collect()
    }

    fn push(&mut self, m: &[ExprId]) -> usize {
        self.ids.extend(m);
        self.ids.len() - m.len()
    }
}

/// Where each piece's measure numbers are among the roots.
struct Places {
    /// Per load: the load and the (angular) velocity it works through.
    loads: Vec<(VectorAt, VectorAt)>,
    masses: Vec<MassAt>,
}

type VectorAt = Vec<(FrameId, usize)>;

/// A dyadic's terms: its two frames and where its nine measure numbers start.
type DyadicAt = Vec<(FrameId, FrameId, usize)>;

/// A mass's places: its mass, velocity and acceleration, and a body's angular velocity,
/// angular acceleration and inertia terms.
struct MassAt {
    mass: usize,
    velocity: VectorAt,
    acceleration: VectorAt,
    rotation: Option<(VectorAt, VectorAt, DyadicAt)>,
}

impl Places {
    fn of(roots: &mut Roots, power: &Power) -> Places {
        let loads = power.loads.iter().map(|(l, v)| (roots.vector(l), roots.vector(v))).collect();
        let masses = power
            .masses
            .iter()
            .map(|m| MassAt {
                mass: roots.push(&[m.mass]),
                velocity: roots.vector(&m.velocity),
                acceleration: roots.vector(&m.acceleration),
                rotation: m.rotation.as_ref().map(|(w, alpha, inertia)| {
                    let (w, alpha) = (roots.vector(w), roots.vector(alpha));
                    let terms = inertia.terms.iter().map(|(a, b, m)| (*a, *b, roots.push(m.as_flattened())));
                    (w, alpha, terms.collect())
                }),
            })
            .collect();
        Places { loads, masses }
    }
}

/// The frames' direction cosines from their parents and where their numbers are.
struct Frames<'a> {
    newtonian: FrameId,
    dcms: &'a [ParentDcm],
    dcm_at: &'a [usize],
}

/// Everything one sample reads.
struct Check<'a> {
    model: &'a Model,
    eqs: &'a KaneEquations,
    rates: &'a [ExprId],
    roots: &'a [ExprId],
    frames: Frames<'a>,
    places: &'a Places,
}

impl Check<'_> {
    /// True when `|w . (Fr + Fr*)|` is within [`TOLERANCE`] of the size of its terms at the
    /// sample `seed`; `None` when an expression has no finite value there.
    fn agrees_at(&self, seed: u64) -> Option<bool> {
        let ar = &self.model.ar;
        let (mut values, w) = sample(self.model, self.eqs, seed);
        let udot = ar.eval::<f64>(self.rates, |s| values.get(&s).copied()).ok()?;
        values.extend(self.eqs.speed_derivatives.iter().copied().zip(udot));
        let at = ar.eval::<f64>(self.roots, |s| values.get(&s).copied()).ok()?;
        let mut moved = values.clone();
        moved.extend(self.eqs.speeds.iter().copied().zip(w));
        let at_w = ar.eval::<f64>(self.roots, |s| moved.get(&s).copied()).ok()?;
        let mut still = values;
        still.extend(self.eqs.speeds.iter().map(|u| (*u, 0.0)));
        let at_0 = ar.eval::<f64>(self.roots, |s| still.get(&s).copied()).ok()?;
        let to_n = compose(self.frames.newtonian, self.frames.dcms, self.frames.dcm_at, &at);
        let n = Numeric { to_n: &to_n };
        // The velocities at the virtual speeds, less their part free of speeds.
        let virtual_of = |p: &VectorAt| sub3(&n.vector(p, &at_w), &n.vector(p, &at_0));
        let (mut total, mut size) = (0.0, 0.0);
        let mut add = |x: f64| {
            total += x;
            size += x.abs();
        };
        for (load, through) in &self.places.loads {
            add(dot(&n.vector(load, &at), &virtual_of(through)));
        }
        for m in &self.places.masses {
            add(-at[m.mass] * dot(&n.vector(&m.acceleration, &at), &virtual_of(&m.velocity)));
            if let Some((w, alpha, inertia)) = &m.rotation {
                let inertia = n.dyadic(inertia, &at);
                let (w_n, alpha_n) = (n.vector(w, &at), n.vector(alpha, &at));
                let torque = add3(&mat_vec(&inertia, &alpha_n), &cross(&w_n, &mat_vec(&inertia, &w_n)));
                add(-dot(&torque, &virtual_of(w)));
            }
        }
        Some(total.abs() <= TOLERANCE * size)
    }
}

/// Each frame's direction cosines from the Newtonian frame (`n_i . frame_j`), composed down the
/// orientation tree from the numeric `parent_i . frame_j` at `dcm_at` in `at`.
fn compose(newtonian: FrameId, dcms: &[ParentDcm], dcm_at: &[usize], at: &[f64]) -> FxHashMap<FrameId, M3> {
    let local: FxHashMap<FrameId, (FrameId, M3)> = dcms
        .iter()
        .zip(dcm_at)
        .map(|((parent, f, _), k)| {
            let m = std::array::from_fn(|i| std::array::from_fn(|j| at[k + 3 * i + j]));
            (*f, (*parent, m))
        })
        .collect();
    let mut out: FxHashMap<FrameId, M3> = FxHashMap::default();
    out.insert(newtonian, std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j)))));
    for f in local.keys() {
        let mut chain = vec![*f];
        while let Some((p, _)) = local.get(chain.last().unwrap_or(f)) {
            if out.contains_key(p) {
                break;
            }
            chain.push(*p);
        }
        for g in chain.into_iter().rev() {
            let (p, m) = local[&g];
            let above = out[&p];
            out.insert(g, mat_mul(&above, &m));
        }
    }
    out
}

/// Numbers of vectors and dyadics in Newtonian components.
struct Numeric<'a> {
    to_n: &'a FxHashMap<FrameId, M3>,
}

impl Numeric<'_> {
    fn vector(&self, places: &[(FrameId, usize)], at: &[f64]) -> V3 {
        places.iter().fold([0.0; 3], |acc, (f, k)| {
            add3(&acc, &mat_vec(&self.to_n[f], &[at[*k], at[k + 1], at[k + 2]]))
        })
    }

    fn dyadic(&self, terms: &DyadicAt, at: &[f64]) -> M3 {
        let mut out = [[0.0; 3]; 3];
        for (fa, fb, k) in terms {
            let local: M3 = std::array::from_fn(|i| std::array::from_fn(|j| at[k + 3 * i + j]));
            let ab = mat_mul(&mat_mul(&self.to_n[fa], &local), &transpose(&self.to_n[fb]));
            for (row, add) in out.iter_mut().zip(ab) {
                for (x, y) in row.iter_mut().zip(add) {
                    *x += y;
                }
            }
        }
        out
    }
}

fn dot(a: &V3, b: &V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn add3(a: &V3, b: &V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub3(a: &V3, b: &V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: &V3, b: &V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn mat_vec(m: &M3, v: &V3) -> V3 {
    std::array::from_fn(|i| dot(&m[i], v))
}

fn mat_mul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

fn transpose(m: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| m[j][i]))
}

#[cfg(test)]
mod tests {
    use super::agrees;

    const CHAIN: &str = "NEWTONIAN N
BODIES A, B
POINTS O, J
CONSTANTS L, M, I, G, T
VARIABLES Q{2}', U{2}'
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 1, Q2)
Q1' = U1
Q2' = U2
V_O_N> = 0>
P_O_AO> = L/2*A1>
P_O_J> = L*A1>
P_J_BO> = L/2*B2> + L/3*B3>
V2PTS(N, A, O, AO)
V2PTS(N, A, O, J)
V2PTS(N, B, J, BO)
MASS A = M, B = 2*M
INERTIA A, I, 2*I, 3*I
INERTIA B, I, I/2, I/3, I/10, 0, I/20
GRAVITY(-G*N2>)
TORQUE_B> = T*A3>
ZERO = FR() + FRSTAR()
KANE()
";

    #[test]
    fn the_order_n_rates_agree_and_a_perturbed_rate_does_not() {
        let mut loaded = crate::lang::load("chain.al", CHAIN).unwrap_or_else(|r| panic!("{}", r.render()));
        let eqs = loaded.equations.clone().unwrap();
        let model = &mut loaded.model;
        let rates = model.order_n_rates(&eqs).unwrap().expect("a tree of joint rates");
        assert!(agrees(model, &eqs, &rates).unwrap());
        for k in 0..rates.len() {
            let mut wrong = rates.clone();
            let tiny = model.ar.float(1e-6).unwrap();
            wrong[k] = model.ar.add(&[wrong[k], tiny]).unwrap();
            assert!(!agrees(model, &eqs, &wrong).unwrap(), "u{}' off by 1e-6 passes", k + 1);
        }
    }
}
