//! Checking hand-derived equations and quantities against the derived ones, and saying how they
//! differ.
//!
//! A hand file holds one scalar equation per generalized speed, either as `U1' = ...` (the
//! speed derivatives) or as `ZERO[1] = ...` (the expressions `Fr + Fr*` that vanish, written
//! with the speed derivatives `U1'`), and may give quantities of the model: vectors such as
//! `V_P_A> = L*U1*A1> + ...` (compared per component in the frame of the first unit vector the
//! hand file writes) and named scalars such as `K1 = ...`. Points are sampled at the model's INPUT values.

mod hand;
mod judge;
mod render;

use crate::expr::{Equivalence, ExprError, ExprId};
use crate::mechanics::{KaneEquations, Model, Vector};

use super::diagnostic::{Diagnostic, Report};
use super::parser;
use super::present::Presenter;
use super::session::{report, Session};
use hand::Given;
use judge::Judge;
pub use judge::Relation;

/// The verdict on one hand-derived equation or quantity component.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// What: `U1'`, `ZERO[1]`, `V_P_A> . D2>`, `K1`.
    pub label: String,
    /// How it relates to the derived one.
    pub relation: Relation,
    /// The verdict behind the relation (for [`Relation::Differs`], the point where they differ).
    pub verdict: Equivalence,
    /// True for an equation `ZERO[r] = ...` (which means the same negated as a whole); false
    /// for a rate or a quantity, where a sign is part of the value.
    pub equation: bool,
}

/// Every comparison of a hand file, with the names of the derived rows for messages.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The comparisons, in the hand file's order (equations first).
    pub comparisons: Vec<Comparison>,
    /// The derived rows' labels (`ZERO[1]`, ...), for [`Relation::Row`].
    pub rows: Vec<String>,
    /// Whether an equation equal to a derived one negated counts as equal (asked for with
    /// `--up-to-sign`); a rate or a quantity of the opposite sign never does.
    pub up_to_sign: bool,
}

impl Outcome {
    /// True when something differs or cannot be decided: a difference, an inconclusive
    /// comparison, a rate or quantity of the opposite sign, or an equation negated unless
    /// [`Outcome::up_to_sign`]. The order of the equations does not count.
    pub fn differs(&self) -> bool {
        self.comparisons.iter().any(|c| !self.accepted(c))
    }

    /// Whether `c` counts as equal.
    pub(crate) fn accepted(&self, c: &Comparison) -> bool {
        match c.relation {
            Relation::Equal | Relation::Row { negated: false, .. } => true,
            Relation::Negated | Relation::Row { negated: true, .. } => c.equation && self.up_to_sign,
            Relation::Differs { .. } | Relation::Inconclusive => false,
        }
    }
}

/// Runs `model` (which must call KANE()), then checks each statement of `hand`: `U_r' = h_r`
/// as `sum_s M_rs h_s = f_r`, `ZERO[r] = g` as `g = f_r - sum_s M_rs u_s'`, vectors per
/// component and named scalars as they are.
pub fn compare(model_file: &str, model: &str, hand_file: &str, hand: &str) -> Result<Outcome, Report> {
    let mut s = Session::open(model_file, model)?;
    let Some(eqs) = s.it.equations.clone() else {
        return Err(report(
            model_file,
            model,
            vec![Diagnostic::error(0..0, "the model file derives no equations")
                .with_help("call KANE() in the model file")],
        ));
    };
    let (stmts, errors) = parser::parse(hand);
    if !errors.is_empty() {
        return Err(report(hand_file, hand, errors));
    }
    let given = hand::read(&mut s.it, &eqs, &stmts).map_err(|d| report(hand_file, hand, d))?;
    let fail = |e: ExprError| report(hand_file, hand, vec![Diagnostic::error(0..0, e.to_string())]);
    let cfg = s.physical_sampling();
    let presenter = s.presenter(None).map_err(fail)?;
    let rows: Vec<String> = (1..=eqs.speeds.len()).map(|r| format!("ZERO[{r}]")).collect();
    let mut out = Outcome { comparisons: Vec::new(), rows, up_to_sign: false };
    let model = &mut s.it.model;
    if given.iter().any(|g| matches!(g, Given::Udot(..))) {
        out.comparisons = udot_rows(model, &cfg, &presenter, &eqs, &given).map_err(|e| match e {
            Checked::Missing(name) => report(
                hand_file,
                hand,
                vec![Diagnostic::error(0..0, format!("no equation for {name}'"))
                    .with_help("the U' = ... form needs one equation for every generalized speed")],
            ),
            Checked::Expr(e) => fail(e),
        })?;
    }
    let derived = zero_rows(&mut model.ar, &eqs).map_err(fail)?;
    for g in &given {
        let mut judge = Judge { ar: &mut model.ar, cfg: &cfg, presenter: &presenter };
        if let Given::Zero(r, x) = g {
            let (relation, verdict) = judge.judge(*x, &derived, *r, true).map_err(fail)?;
            out.comparisons.push(Comparison {
                label: out.rows[*r].clone(),
                relation,
                verdict,
                equation: true,
            });
        }
    }
    for g in &given {
        let q = quantity(model, &cfg, &presenter, g);
        out.comparisons.extend(q.map_err(|e| report(hand_file, hand, vec![Diagnostic::error(0..0, e)]))?);
    }
    Ok(out)
}

/// Why the U' rows could not be checked.
enum Checked {
    Missing(String),
    Expr(ExprError),
}

impl From<ExprError> for Checked {
    fn from(e: ExprError) -> Checked {
        Checked::Expr(e)
    }
}

/// The rows `f_r - sum_s M_rs u_s'` of `Fr + Fr* = 0`.
fn zero_rows(ar: &mut crate::expr::Arena, eqs: &KaneEquations) -> Result<Vec<ExprId>, ExprError> {
    let udot: Vec<ExprId> = eqs.speed_derivatives.iter().map(|s| ar.symbol_expr(*s)).collect();
    let mut rows = Vec::with_capacity(eqs.forcing.len());
    for (r, f) in eqs.forcing.iter().enumerate() {
        let mut terms = vec![*f];
        for (s, u) in udot.iter().enumerate() {
            let t = ar.mul(&[eqs.mass_matrix[r][s], *u])?;
            terms.push(ar.neg(t)?);
        }
        rows.push(ar.add(&terms)?);
    }
    Ok(rows)
}

/// `U_r' = h_r` checked as `sum_s M_rs h_s = f_r`, row by row.
fn udot_rows(
    model: &mut Model,
    cfg: &crate::expr::EquivalenceConfig,
    presenter: &Presenter,
    eqs: &KaneEquations,
    given: &[Given],
) -> Result<Vec<Comparison>, Checked> {
    let n = eqs.speeds.len();
    let mut h: Vec<Option<ExprId>> = vec![None; n];
    for g in given {
        if let Given::Udot(r, x) = g {
            h[*r] = Some(*x);
        }
    }
    let ar = &mut model.ar;
    if let Some(missing) = h.iter().position(Option::is_none) {
        return Err(Checked::Missing(ar.symbol_info(eqs.speeds[missing]).name.clone()));
    }
    let h: Vec<ExprId> = h.into_iter().flatten().collect();
    let mut lhs = Vec::with_capacity(n);
    for r in 0..n {
        let terms = (0..n).map(|s| ar.mul(&[eqs.mass_matrix[r][s], h[s]])).collect::<Result<Vec<_>, _>>()?;
        lhs.push(ar.add(&terms)?);
    }
    let mut out = Vec::with_capacity(n);
    for (r, x) in lhs.iter().enumerate() {
        let mut judge = Judge { ar, cfg, presenter };
        let (relation, verdict) = judge.judge(*x, &eqs.forcing, r, false)?;
        let name = &ar.symbol_info(eqs.speeds[r]).name;
        let label = format!("{name}' (row {} of M u' = f, hand = M*(hand u'), derived = f)", r + 1);
        out.push(Comparison { label, relation, verdict, equation: false });
    }
    // Rates equal up to sign only all together (u' = -h); one negated row is a wrong rate.
    if !out.iter().all(|c| c.relation == Relation::Negated) {
        for (r, c) in out.iter_mut().enumerate().filter(|(_, c)| c.relation == Relation::Negated) {
            let diff = ar.sub(lhs[r], eqs.forcing[r])?;
            c.relation = Relation::Differs { difference: presenter.text(ar, diff)? };
            c.verdict = ar.equivalent(lhs[r], eqs.forcing[r], cfg)?;
        }
    }
    Ok(out)
}

/// A vector compared per component in the frame of the hand vector's first term, or a scalar.
fn quantity(
    model: &mut Model,
    cfg: &crate::expr::EquivalenceConfig,
    presenter: &Presenter,
    g: &Given,
) -> Result<Vec<Comparison>, String> {
    let (labels, hand, derived) = match g {
        Given::Scalar { name, hand, derived } => (vec![name.clone()], vec![*hand], vec![*derived]),
        Given::Vector { name, hand, derived, frame } => {
            let frame = frame.or(hand.terms().first().map(|t| t.0)).unwrap_or(model.newtonian());
            let components = |m: &mut Model, v: &Vector| m.express(v, frame).map_err(|e| e.to_string());
            let (h, d) = (components(model, hand)?, components(model, derived)?);
            let f = model.frame_name(frame).to_string();
            ((1..=3).map(|k| format!("{name} . {f}{k}>")).collect(), h.to_vec(), d.to_vec())
        }
        _ => return Ok(Vec::new()),
    };
    let mut out = Vec::with_capacity(labels.len());
    for (k, label) in labels.into_iter().enumerate() {
        let mut judge = Judge { ar: &mut model.ar, cfg, presenter };
        let (relation, verdict) = judge.judge(hand[k], &derived, k, false).map_err(|e| e.to_string())?;
        out.push(Comparison { label, relation, verdict, equation: false });
    }
    Ok(out)
}
