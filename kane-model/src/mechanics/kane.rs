//! Kane's method: partial velocities, generalized active and inertia forces, and the equations
//! of motion `M(q, t) u' = f(q, u, t)` with `Fr + Fr* = 0`.

use std::collections::hash_map::Entry;

use rustc_hash::FxHashMap;

use crate::expr::{Arena, ExprId, Node, SymbolId, SymbolKind, Tape};

use super::error::{MechanicsError, Result};
use super::ids::{FrameId, PointId};
use super::model::{Load, Model};
use super::vector::{Dyadic, Vector};

/// Most terms an equation's collected canonical form may have: a larger one is not formed (the
/// expression is kept as derived, its shared subexpressions named, never multiplied out).
pub const COLLECT_TERMS_BUDGET: usize = 1_000;

/// Most terms the collected forms of all of a model's equations may have together.
pub const COLLECT_TERMS_TOTAL: u64 = 20_000;

/// The loads solved with the speed rates, and the equations of the auxiliary speeds.
#[derive(Clone, Debug, PartialEq)]
pub struct SolvedLoads {
    /// The unknown loads `T`, in KANE's order.
    pub loads: Vec<SymbolId>,
    /// The auxiliary speeds (zero in every motion).
    pub auxiliary: Vec<SymbolId>,
    /// The auxiliary rows of `M`, a column per speed (independent then dependent).
    pub mass_rows: Vec<Vec<ExprId>>,
    /// The auxiliary rows of `f` with the loads zero.
    pub forcing: Vec<ExprId>,
    /// `B = df/dT`, the speed rows (independent then dependent) then the auxiliary rows, a
    /// column per load.
    pub load_columns: Vec<Vec<ExprId>>,
}

/// Kane's equations of a model: `q' = kinematics`, `mass_matrix * u' = forcing`.
#[derive(Clone, Debug)]
pub struct KaneEquations {
    /// Generalized coordinates `q`.
    pub coordinates: Vec<SymbolId>,
    /// Independent generalized speeds `u`.
    pub speeds: Vec<SymbolId>,
    /// Motion constraints; with them `M` and `f` are over all speeds, the independent first.
    pub constraints: Option<SpeedConstraints>,
    /// The symbols `u'` of the independent speeds.
    pub speed_derivatives: Vec<SymbolId>,
    /// Right-hand sides of the kinematic differential equations, one per coordinate.
    pub kinematics: Vec<ExprId>,
    /// The symmetric mass matrix `M`, row by row (over the independent speeds, then the
    /// dependent ones when there are constraints).
    pub mass_matrix: Vec<Vec<ExprId>>,
    /// The forcing vector `f` (with the loads solved for zero).
    pub forcing: Vec<ExprId>,
    /// Loads solved with the speed rates from the auxiliary speeds' equations (KANE(T1, ...)).
    pub loads: Option<SolvedLoads>,
    /// False while `mass_matrix` and `forcing` are not formed (empty): a large tree whose
    /// order-n form may never need them; [`Model::form_equations`] forms them.
    pub formed: bool,
}

impl KaneEquations {
    /// Equations of nothing: no states, for a model whose code only computes quantities from
    /// inputs (Autolev's CODE ALGEBRAIC() of a file without dynamics).
    pub fn none() -> KaneEquations {
        KaneEquations {
            coordinates: Vec::new(),
            speeds: Vec::new(),
            constraints: None,
            speed_derivatives: Vec::new(),
            kinematics: Vec::new(),
            mass_matrix: Vec::new(),
            forcing: Vec::new(),
            loads: None,
            formed: true,
        }
    }

    /// Every expression of the equations with `map` substituted (formulas for specified
    /// quantities, for example).
    pub fn substitute(&mut self, ar: &mut crate::expr::Arena, map: &FxHashMap<ExprId, ExprId>) -> Result<()> {
        if map.is_empty() {
            return Ok(());
        }
        let mut each = |list: &mut Vec<ExprId>| -> Result<()> {
            *list = ar.subs_many(list, map)?;
            Ok(())
        };
        each(&mut self.kinematics)?;
        each(&mut self.forcing)?;
        self.mass_matrix.iter_mut().try_for_each(&mut each)?;
        if let Some(c) = &mut self.constraints {
            c.a_dependent.iter_mut().chain(&mut c.a_independent).try_for_each(&mut each)?;
            each(&mut c.b)?;
            each(&mut c.bias)?;
        }
        if let Some(l) = &mut self.loads {
            l.mass_rows.iter_mut().chain(&mut l.load_columns).try_for_each(&mut each)?;
            each(&mut l.forcing)?;
        }
        Ok(())
    }

    /// The sizes of `M` and `f`: each compiled as one tape (shared subexpressions once).
    pub fn op_counts(&self, ar: &Arena) -> EquationOps {
        let ops = |roots: &[ExprId]| Tape::compile(ar, roots, Some).map_or(0, |t| t.op_count());
        let m: Vec<ExprId> = self.mass_matrix.iter().flatten().copied().collect();
        EquationOps { n: self.mass_matrix.len(), mass_matrix: ops(&m), forcing: ops(&self.forcing) }
    }
}

/// Arithmetic operations of Kane's equations as derived: the tape of `M` and that of `f`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EquationOps {
    /// The order of `M`.
    pub n: usize,
    /// Operations computing every entry of `M`.
    pub mass_matrix: usize,
    /// Operations computing every entry of `f`.
    pub forcing: usize,
}

impl std::fmt::Display for EquationOps {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let n = self.n;
        write!(f, "M {n}x{n} in {} operations, f in {}", self.mass_matrix, self.forcing)
    }
}

/// Motion constraints in Kane's equations: `A_d u_d + A_i u_i + b = 0` and, differentiated,
/// `A_d u_d' + A_i u_i' + bias = 0`. They reduce `M` and `f` (over all speeds) to the
/// independent speeds numerically where the equations are evaluated.
#[derive(Clone, Debug)]
pub struct SpeedConstraints {
    /// The dependent speeds `u_d`.
    pub dependent: Vec<SymbolId>,
    /// Their rates `u_d'`.
    pub dependent_rates: Vec<SymbolId>,
    /// `A_d`, a row per constraint.
    pub a_dependent: Vec<Vec<ExprId>>,
    /// `A_i`, a row per constraint and a column per independent speed.
    pub a_independent: Vec<Vec<ExprId>>,
    /// `b`, free of speeds.
    pub b: Vec<ExprId>,
    /// `d/dt (A u + b)` with every speed rate zero: a function of the coordinates, all speeds
    /// and time.
    pub bias: Vec<ExprId>,
}

/// The motion of one mass: a rigid body or a particle (no inertia, no rotation).
pub(crate) struct MassMotion {
    pub(crate) mass: ExprId,
    /// Velocity and acceleration of the mass centre in the Newtonian frame.
    pub(crate) velocity: Vector,
    pub(crate) acceleration: Vector,
    /// Angular velocity and acceleration, and the central inertia, for bodies.
    pub(crate) rotation: Option<(Vector, Vector, Dyadic)>,
}

/// Partial velocities of one mass with respect to each speed.
struct Partials {
    linear: Vec<Vector>,
    angular: Vec<Vector>,
}

impl Model {
    fn speed_derivative_symbols(&mut self) -> Result<Vec<SymbolId>> {
        let speeds = self.kane_speeds();
        Ok(speeds.into_iter().map(|u| self.ar.derivative_symbol(u)).collect::<std::result::Result<_, _>>()?)
    }

    fn check_ready(&self) -> Result<()> {
        if self.speeds.is_empty() {
            return Err(MechanicsError::NoSpeeds);
        }
        if let Some(q) = self.coordinates.iter().find(|q| !self.kinematics.contains_key(q)) {
            return Err(MechanicsError::MissingKinematics(self.ar.symbol_info(*q).name.clone()));
        }
        Ok(())
    }

    /// Every mass's motion in the Newtonian frame, with its mass and, for a body, its inertia.
    pub(crate) fn mass_motions(&mut self) -> Result<Vec<MassMotion>> {
        let n = self.newtonian;
        let mut out = Vec::new();
        for view in self.masses().collect::<Vec<_>>() {
            let mass = view.mass()?;
            let (velocity, acceleration) = self.point_motion(view.point)?;
            let rotation = match view.frame {
                Some(frame) => {
                    let w = self.angular_velocity(frame, n)?;
                    let w = self.eliminate_dependent_vector(&w)?;
                    let alpha = self.dt_in(&w, n)?;
                    let alpha = self.eliminate_dependent_vector(&alpha)?;
                    let inertia = self.rebase_inertia(&view.inertia.unwrap_or_default());
                    Some((w, alpha, inertia))
                }
                None => None,
            };
            out.push(MassMotion { mass, velocity, acceleration, rotation });
        }
        Ok(out)
    }

    /// Velocity and acceleration of a point in the Newtonian frame, dependent speeds eliminated.
    pub(crate) fn point_motion(&mut self, point: PointId) -> Result<(Vector, Vector)> {
        let n = self.newtonian;
        let v = self.velocity(point, n)?;
        let v = self.eliminate_dependent_vector(&v)?;
        let a = match self.points[point.index()].acceleration.get(&n) {
            Some(a) => a.clone(),
            None => self.dt_in(&v, n)?,
        };
        Ok((v.clone(), self.eliminate_dependent_vector(&a)?))
    }

    /// The partial velocities of `v`, remembered: FR(), FRSTAR() and KANE() ask for the same.
    fn partials_of(&mut self, v: &Vector) -> Result<Vec<Vector>> {
        let speeds = self.kane_speeds();
        let key = (v.terms.clone(), speeds);
        if let Some(p) = self.kinematics_cache.partials.get(&key) {
            return Ok(p.clone());
        }
        let p = key.1.iter().map(|u| self.partial(v, *u)).collect::<Result<Vec<Vector>>>()?;
        self.kinematics_cache.partials.insert(key, p.clone());
        Ok(p)
    }

    fn mass_partials(&mut self, m: &MassMotion) -> Result<Partials> {
        let linear = self.partials_of(&m.velocity)?;
        let angular = match &m.rotation {
            Some((w, _, _)) => self.partials_of(w)?,
            None => vec![Vector::zero(); self.kane_speeds().len()],
        };
        Ok(Partials { linear, angular })
    }

    /// Partial velocities of a point (Autolev's partial velocity table, one row per speed).
    pub fn partial_velocities(&mut self, point: PointId) -> Result<Vec<Vector>> {
        let v = self.velocity(point, self.newtonian)?;
        let v = self.eliminate_dependent_vector(&v)?;
        self.partials_of(&v)
    }

    /// Partial angular velocities of a frame in the Newtonian frame.
    pub fn partial_angular_velocities(&mut self, frame: FrameId) -> Result<Vec<Vector>> {
        let w = self.angular_velocity(frame, self.newtonian)?;
        let w = self.eliminate_dependent_vector(&w)?;
        self.partials_of(&w)
    }

    /// The generalized active forces `Fr`, one per independent speed.
    pub fn generalized_active_forces(&mut self) -> Result<Vec<ExprId>> {
        let full = self.active_forces_all_speeds()?;
        self.constrain_symbolically(&full)
    }

    /// `Fr` over every Kane speed, constraints aside.
    fn active_forces_all_speeds(&mut self) -> Result<Vec<ExprId>> {
        self.check_ready()?;
        let mut per_point: FxHashMap<PointId, Vec<Vector>> = FxHashMap::default();
        let mut per_frame: FxHashMap<FrameId, Vec<Vector>> = FxHashMap::default();
        let mut terms: Vec<Vec<ExprId>> = vec![Vec::new(); self.kane_speeds().len()];
        for load in self.loads.clone() {
            let (partials, vector) = match load {
                Load::Force { point, force } => match per_point.entry(point) {
                    Entry::Occupied(e) => (e.get().clone(), force),
                    Entry::Vacant(e) => (e.insert(self.partial_velocities(point)?).clone(), force),
                },
                Load::Torque { frame, torque } => match per_frame.entry(frame) {
                    Entry::Occupied(e) => (e.get().clone(), torque),
                    Entry::Vacant(e) => (e.insert(self.partial_angular_velocities(frame)?).clone(), torque),
                },
            };
            for (r, pv) in partials.iter().enumerate() {
                let d = self.dot(pv, &vector)?;
                terms[r].push(d);
            }
        }
        terms.into_iter().map(|t| Ok(self.ar.add(&t)?)).collect()
    }

    /// The generalized inertia forces `Fr*`, one per independent speed.
    pub fn generalized_inertia_forces(&mut self) -> Result<Vec<ExprId>> {
        self.check_ready()?;
        let motions = self.mass_motions()?;
        let full = self.inertia_forces(&motions, false)?;
        self.constrain_symbolically(&full)
    }

    /// `Fr*` from the motions; with `without_accelerations`, the part free of `u'`.
    fn inertia_forces(&mut self, motions: &[MassMotion], without_accelerations: bool) -> Result<Vec<ExprId>> {
        let udot = self.speed_derivative_symbols()?;
        let zero_udot: FxHashMap<ExprId, ExprId> = {
            let z = self.ar.zero();
            udot.iter().map(|s| (self.ar.symbol_expr(*s), z)).collect()
        };
        let mut terms: Vec<Vec<ExprId>> = vec![Vec::new(); self.kane_speeds().len()];
        for m in motions {
            let p = self.mass_partials(m)?;
            let mut a = m.acceleration.clone();
            if without_accelerations {
                a = self.subs_vector(&a, &zero_udot)?;
            }
            let force = self.scale(&a, m.mass)?;
            let torque = match &m.rotation {
                Some((w, alpha, inertia)) => {
                    let alpha = if without_accelerations {
                        self.subs_vector(alpha, &zero_udot)?
                    } else {
                        alpha.clone()
                    };
                    let i_alpha = self.dyadic_dot(inertia, &alpha)?;
                    let i_w = self.dyadic_dot(inertia, w)?;
                    let gyro = self.cross(w, &i_w)?;
                    Some(self.add_vectors(&i_alpha, &gyro)?)
                }
                None => None,
            };
            for (r, bucket) in terms.iter_mut().enumerate() {
                let f = self.dot(&p.linear[r], &force)?;
                bucket.push(self.ar.neg(f)?);
                if let Some(t) = &torque {
                    let d = self.dot(&p.angular[r], t)?;
                    bucket.push(self.ar.neg(d)?);
                }
            }
        }
        terms.into_iter().map(|t| Ok(self.ar.add(&t)?)).collect()
    }

    /// Replaces entries of `M` and `f` by their trigonometric canonical form in the state, terms
    /// collected by state monomial, where that takes fewer operations to evaluate: the
    /// smallest entries first, while their canonical forms stay within `COLLECT_TERMS_TOTAL`
    /// terms together (collecting costs time and, in large models, saves no operations).
    pub fn simplify_equations(&mut self, eqs: &mut KaneEquations) -> Result<()> {
        let n = eqs.forcing.len();
        let mut slots: Vec<(usize, usize)> = (0..n).flat_map(|i| (i..n).map(move |j| (i, j))).collect();
        slots.extend((0..n).map(|i| (n, i)));
        let entry = |eqs: &KaneEquations, (i, j): (usize, usize)| {
            if i == n {
                eqs.forcing[j]
            } else {
                eqs.mass_matrix[i][j]
            }
        };
        let roots: Vec<ExprId> = slots.iter().map(|s| entry(eqs, *s)).collect();
        let bounds = self.ar.expansion_bounds(&roots);
        let mut order: Vec<usize> = (0..slots.len()).collect();
        order.sort_by_key(|k| bounds[*k]);
        let mut total = 0u64;
        for k in order {
            total = total.saturating_add(bounds[k]);
            if bounds[k] > COLLECT_TERMS_BUDGET as u64 || total > COLLECT_TERMS_TOTAL {
                break;
            }
            let (i, j) = slots[k];
            let x = self.smaller_form(roots[k])?;
            if i == n {
                eqs.forcing[j] = x;
            } else {
                eqs.mass_matrix[i][j] = x;
                eqs.mass_matrix[j][i] = x;
            }
        }
        Ok(())
    }

    /// The collected canonical form of `e` where it is within [`COLLECT_TERMS_BUDGET`] terms,
    /// else `e` itself (never expanded past the budget).
    pub fn collected_form_within_budget(&mut self, e: ExprId) -> Result<ExprId> {
        if self.ar.expansion_bounds(&[e])[0] > COLLECT_TERMS_BUDGET as u64 {
            return Ok(e);
        }
        self.collected_form(e)
    }

    /// The collected canonical form of `e`: trigonometric identities applied in the state
    /// variables, terms grouped by state monomial, parameter-only parts kept whole.
    pub fn collected_form(&mut self, e: ExprId) -> Result<ExprId> {
        if matches!(self.ar.node(e), Node::Rational(_) | Node::Float(_) | Node::Symbol(_)) {
            return Ok(e);
        }
        let ar = &mut self.ar;
        let kinds: Vec<bool> = ar.symbols().map(|(_, info)| info.kind == SymbolKind::Constant).collect();
        Ok(ar.collect_state(e, |sym| kinds.get(sym.index()).copied().unwrap_or(true))?)
    }

    /// `e` or its collected canonical form, whichever has the smaller expression graph (the
    /// caller has checked the form's size against [`COLLECT_TERMS_BUDGET`]).
    fn smaller_form(&mut self, e: ExprId) -> Result<ExprId> {
        let s = self.collected_form(e)?;
        Ok(if self.ar.graph_size(s) < self.ar.graph_size(e) { s } else { e })
    }

    /// `v` with `map` substituted in its measure numbers.
    pub(crate) fn subs_vector(&mut self, v: &Vector, map: &FxHashMap<ExprId, ExprId>) -> Result<Vector> {
        let mut out = v.clone();
        for (_, m) in out.terms.iter_mut() {
            let r = self.ar.subs_many(m, map)?;
            m.copy_from_slice(&r);
        }
        Ok(out)
    }

    /// Kane's equations `M u' = f` and the kinematic differential equations.
    ///
    /// The mass matrix is formed directly and symmetrically as
    /// `M_rs = sum(m v_r . v_s + w_r . I . w_s)`; the forcing is `f = Fr + Fr*` with `u' = 0`.
    pub fn kane(&mut self) -> Result<KaneEquations> {
        self.check_ready()?;
        let n = self.kane_speeds().len();
        let motions = self.mass_motions()?;
        let mut mass_terms: Vec<Vec<Vec<ExprId>>> = vec![vec![Vec::new(); n]; n];
        for m in &motions {
            let p = self.mass_partials(m)?;
            let inertia_w: Vec<Vector> = match &m.rotation {
                Some((_, _, inertia)) => {
                    p.angular.iter().map(|w| self.dyadic_dot(inertia, w)).collect::<Result<_>>()?
                }
                None => Vec::new(),
            };
            for (r, row) in mass_terms.iter_mut().enumerate() {
                for (s, cell) in row.iter_mut().enumerate().skip(r) {
                    let vv = self.dot(&p.linear[r], &p.linear[s])?;
                    let mv = self.ar.mul(&[m.mass, vv])?;
                    cell.push(mv);
                    if !inertia_w.is_empty() {
                        let wiw = self.dot(&p.angular[r], &inertia_w[s])?;
                        cell.push(wiw);
                    }
                }
            }
        }
        let zero = self.ar.zero();
        let mut mass_matrix = vec![vec![zero; n]; n];
        for r in 0..n {
            for s in r..n {
                let e = self.ar.add(&mass_terms[r][s])?;
                mass_matrix[r][s] = e;
                mass_matrix[s][r] = e;
            }
        }
        let fr = self.active_forces_all_speeds()?;
        let frstar0 = self.inertia_forces(&motions, true)?;
        let forcing = fr
            .iter()
            .zip(&frstar0)
            .map(|(a, b)| Ok(self.ar.add(&[*a, *b])?))
            .collect::<Result<Vec<ExprId>>>()?;
        let mut eqs = self.kane_unformed()?;
        eqs.mass_matrix = mass_matrix;
        eqs.forcing = forcing;
        self.split_auxiliary(&mut eqs)?;
        eqs.formed = true;
        Ok(eqs)
    }

    /// Kane's equations without `M` and `f` (`formed` false): coordinates, speeds, their
    /// rates and the kinematic differential equations.
    pub fn kane_unformed(&mut self) -> Result<KaneEquations> {
        self.check_ready()?;
        let coordinates = self.coordinates.clone();
        let kinematics: Vec<ExprId> = coordinates.iter().map(|q| self.kinematics[q]).collect();
        // Each right-hand side read through the others' (see `kinematics_map`).
        let map = self.kinematics_map();
        let kinematics = self.ar.subs_many(&kinematics, &map)?;
        let speeds = self.independent_speeds();
        let mut rates = self.speed_derivative_symbols()?;
        rates.truncate(speeds.len() + self.dependent_speeds().len());
        let dependent_rates = rates.split_off(speeds.len());
        let constraints = self.speed_constraints(dependent_rates)?;
        Ok(KaneEquations {
            coordinates,
            speeds,
            constraints,
            speed_derivatives: rates,
            kinematics,
            mass_matrix: Vec::new(),
            forcing: Vec::new(),
            loads: None,
            formed: false,
        })
    }

    /// The constraint block of the model's motion constraints, with `u_d'` as `dependent_rates`.
    fn speed_constraints(&mut self, dependent_rates: Vec<SymbolId>) -> Result<Option<SpeedConstraints>> {
        let Some(c) = self.constraints.clone() else { return Ok(None) };
        let mut all_rates = self.speed_derivative_symbols()?;
        all_rates.retain(|r| !dependent_rates.contains(r));
        all_rates.extend(&dependent_rates);
        let zero = self.ar.zero();
        let still: FxHashMap<ExprId, ExprId> =
            all_rates.iter().map(|s| (self.ar.symbol_expr(*s), zero)).collect();
        let mut bias = Vec::with_capacity(c.residuals.len());
        for &r in &c.residuals {
            let d = self.dt(r)?;
            bias.push(self.ar.subs(d, &still)?);
        }
        Ok(Some(SpeedConstraints {
            dependent: c.dependent,
            dependent_rates,
            a_dependent: c.a_dependent,
            a_independent: c.a_independent,
            b: c.b,
            bias,
        }))
    }

    /// Forms `M` and `f` of `eqs` when they are not yet formed (the model unchanged since).
    pub fn form_equations(&mut self, eqs: &mut KaneEquations) -> Result<()> {
        if !eqs.formed {
            *eqs = self.kane()?;
        }
        Ok(())
    }
}
