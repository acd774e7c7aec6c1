//! `kane eoms`: a model's equations of motion printed for reading, simplified and in the
//! file's names, as text or as a LaTeX `align*` block.
//!
//! A quantity whose collected form is small is printed collected by state monomial. One whose
//! expansion would swell (judged before expanding, from the DAG) is printed as derived, in
//! named intermediates `z1 = ...` shared by all the printed quantities, as Autolev's Z
//! variables; so the text grows with the DAG, never with its expansion.

mod render;

use std::fmt;

use crate::expr::{Arena, Collected, ExprError, ExprId};

use super::interp::LoadedModel;
use super::present::Presenter;

pub use render::EomsText;

/// Most terms a quantity's expansion may build for it to be printed collected; a larger one
/// is printed in named intermediates instead (its collected form would not read well anyway).
pub const COLLECT_BUDGET: u64 = 2_000;

/// Most terms the expansions of all the collected quantities of a model may build together
/// (bounds the time collecting takes); the smallest quantities are collected first.
pub const COLLECT_TOTAL: u64 = 10_000;

/// How one quantity is printed.
#[derive(Clone, Debug, PartialEq)]
pub enum Shown {
    /// Simplified and collected by state monomial.
    Collected(Collected),
    /// As derived, written in the named intermediates (collecting it would swell it).
    Named(ExprId),
}

/// A model's equations, each simplified and collected, or in named intermediates.
pub struct PrintedEoms {
    /// Coordinate names.
    pub coordinates: Vec<String>,
    /// Speed names.
    pub speeds: Vec<String>,
    /// `q'` right-hand sides.
    pub kinematics: Vec<Shown>,
    /// The mass matrix `M` of `M u' = f`.
    pub mass_matrix: Vec<Vec<Shown>>,
    /// The forcing `f`.
    pub forcing: Vec<Shown>,
    /// `Fr + Fr* = f - M u'`, row by row.
    pub equations: Vec<Shown>,
    /// The dependent speeds' names (motion constraints), after the independent ones in `M`.
    pub dependent: Vec<String>,
    /// The motion constraints `A_d u_d + A_i u_i + b`, each `= 0`.
    pub constraints: Vec<Shown>,
    /// The loads KANE solves for with the rates (their terms are in `equations`, not `f`).
    pub loads: Vec<String>,
    /// The auxiliary speeds, whose equations follow the speeds' in `equations`.
    pub auxiliary: Vec<String>,
}

/// A failure to print one quantity, naming it.
#[derive(Clone, Debug, PartialEq)]
pub struct EomsError {
    /// The quantity, as printed (`M[1,2]`, `ZERO[3]`), or `the equations`.
    pub quantity: String,
    /// What went wrong.
    pub error: ExprError,
}

impl fmt::Display for EomsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.quantity, self.error)
    }
}

impl std::error::Error for EomsError {}

fn named(quantity: &str) -> impl Fn(ExprError) -> EomsError + '_ {
    move |error| EomsError { quantity: quantity.to_string(), error }
}

/// The equations of `m` (which must hold them), each simplified when that keeps it small.
pub fn printed_eoms(m: &mut LoadedModel) -> Result<Option<PrintedEoms>, EomsError> {
    let Some(e) = m.equations.clone() else { return Ok(None) };
    let p: Presenter = m.presenter().map_err(named("the file's names"))?;
    let ar = &mut m.model.ar;
    let name = |ar: &Arena, s: &crate::expr::SymbolId| ar.symbol_info(*s).name.clone();
    let coordinates: Vec<String> = e.coordinates.iter().map(|s| name(ar, s)).collect();
    let mut rates = e.speed_derivatives.clone();
    let mut constraints = Vec::new();
    if let Some(c) = &e.constraints {
        rates.extend(&c.dependent_rates);
        let speeds: Vec<ExprId> = c.dependent.iter().chain(&e.speeds).map(|s| ar.symbol_expr(*s)).collect();
        for (k, b) in c.b.iter().enumerate() {
            let mut terms = vec![*b];
            for (a, u) in c.a_dependent[k].iter().chain(&c.a_independent[k]).zip(&speeds) {
                terms.push(ar.mul(&[*a, *u]).map_err(named("the constraints"))?);
            }
            constraints.push(ar.add(&terms).map_err(named("the constraints"))?);
        }
    }
    let mut equations = Vec::with_capacity(e.forcing.len());
    for (r, f) in e.forcing.iter().enumerate() {
        let mut terms = vec![*f];
        for (s, u) in rates.iter().enumerate() {
            let u = ar.symbol_expr(*u);
            let t = ar.mul(&[e.mass_matrix[r][s], u]).map_err(named("the equations"))?;
            terms.push(ar.neg(t).map_err(named("the equations"))?);
        }
        equations.push(ar.add(&terms).map_err(named("the equations"))?);
    }
    if let Some(l) = &e.loads {
        with_loads(ar, &e, l, &mut equations).map_err(named("the equations"))?;
    }
    let n = e.forcing.len();
    let mut labelled: Vec<(String, ExprId)> = Vec::new();
    labelled.extend(coordinates.iter().zip(&e.kinematics).map(|(q, k)| (format!("{q}'"), *k)));
    for (i, row) in e.mass_matrix.iter().enumerate() {
        labelled.extend(row.iter().enumerate().map(|(j, x)| (format!("M[{},{}]", i + 1, j + 1), *x)));
    }
    labelled.extend(e.forcing.iter().enumerate().map(|(i, x)| (format!("f[{}]", i + 1), *x)));
    labelled.extend(equations.iter().enumerate().map(|(i, x)| (format!("ZERO[{}]", i + 1), *x)));
    labelled.extend(constraints.iter().enumerate().map(|(i, x)| (format!("CONSTRAINT[{}]", i + 1), *x)));
    let mut shown = shown_all(ar, &p, &labelled)?.into_iter();
    let mut take = |k: usize| shown.by_ref().take(k).collect::<Vec<Shown>>();
    let kinematics = take(e.kinematics.len());
    let mass_matrix = e.mass_matrix.iter().map(|row| take(row.len())).collect();
    Ok(Some(PrintedEoms {
        coordinates,
        speeds: e.speeds.iter().map(|s| name(ar, s)).collect(),
        kinematics,
        mass_matrix,
        forcing: take(n),
        equations: take(equations.len()),
        dependent: e.constraints.iter().flat_map(|c| &c.dependent).map(|s| name(ar, s)).collect(),
        constraints: take(constraints.len()),
        loads: e.loads.iter().flat_map(|l| &l.loads).map(|s| name(ar, s)).collect(),
        auxiliary: e.loads.iter().flat_map(|l| &l.auxiliary).map(|s| name(ar, s)).collect(),
    }))
}

/// The loads' terms `B T` added to the speeds' equations, then the auxiliary speeds'
/// equations `f_a - M_a u' + B_a T` appended.
fn with_loads(
    ar: &mut Arena,
    e: &crate::mechanics::KaneEquations,
    l: &crate::mechanics::SolvedLoads,
    equations: &mut Vec<ExprId>,
) -> Result<(), ExprError> {
    let loads: Vec<ExprId> = l.loads.iter().map(|s| ar.symbol_expr(*s)).collect();
    for (a, f) in l.forcing.iter().enumerate() {
        let mut terms = vec![*f];
        for (m, u) in l.mass_rows[a].iter().zip(&e.speed_derivatives) {
            let u = ar.symbol_expr(*u);
            let t = ar.mul(&[*m, u])?;
            terms.push(ar.neg(t)?);
        }
        let row = ar.add(&terms)?;
        equations.push(row);
    }
    for (r, row) in equations.iter_mut().enumerate() {
        let mut terms = vec![*row];
        for (b, t) in l.load_columns[r].iter().zip(&loads) {
            terms.push(ar.mul(&[*b, *t])?);
        }
        *row = ar.add(&terms)?;
    }
    Ok(())
}

/// Each quantity collected when its expansion stays within [`COLLECT_BUDGET`] terms and, the
/// smallest first, all the collected ones within [`COLLECT_TOTAL`]; the others kept as derived,
/// to be printed in named intermediates.
fn shown_all(ar: &mut Arena, p: &Presenter, labelled: &[(String, ExprId)]) -> Result<Vec<Shown>, EomsError> {
    let roots: Vec<ExprId> = labelled.iter().map(|(_, x)| *x).collect();
    let bounds = ar.expansion_bounds(&roots);
    let mut by_size: Vec<usize> = (0..roots.len()).collect();
    by_size.sort_by_key(|i| (bounds[*i], *i));
    let mut collect = vec![false; roots.len()];
    let mut spent = 0u64;
    for i in by_size {
        spent = spent.saturating_add(bounds[i]);
        if bounds[i] > COLLECT_BUDGET || spent > COLLECT_TOTAL {
            break;
        }
        collect[i] = true;
    }
    // Collected in file order: the order of a collected sum's terms depends on it.
    let mut out = Vec::with_capacity(roots.len());
    for (((label, x), bound), wanted) in labelled.iter().zip(bounds).zip(collect) {
        let c = if wanted { p.tidy_within(ar, *x, bound).map_err(named(label))? } else { None };
        out.push(c.map_or(Shown::Named(*x), Shown::Collected));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::{printed_eoms, PrintedEoms, Shown};

    fn shown(p: &PrintedEoms) -> impl Iterator<Item = &Shown> {
        let m = p.kinematics.iter().chain(p.mass_matrix.iter().flatten());
        m.chain(&p.forcing).chain(&p.equations).chain(&p.constraints)
    }

    /// A planar chain of `n` point masses on pin joints, each angle relative to the link before.
    fn chain(n: usize) -> String {
        let frame = |i: usize| if i == 0 { "N".to_string() } else { format!("F{i}") };
        let mut s = format!("NEWTONIAN N\nFRAMES F{{{n}}}\nPOINTS O\nPARTICLES P{{{n}}}\n");
        s += &format!("CONSTANTS L{{{n}}}, M{{{n}}}, G\nVARIABLES Q{{{n}}}', U{{{n}}}'\nV_O_N> = 0>\n");
        for i in 1..=n {
            let before = if i == 1 { "O".to_string() } else { format!("P{}", i - 1) };
            s += &format!("SIMPROT({}, F{i}, 3, Q{i})\nQ{i}' = U{i}\n", frame(i - 1));
            s += &format!(
                "P_{before}_P{i}> = L{i}*F{i}1>\nV2PTS(N, F{i}, {before}, P{i})\nMASS P{i} = M{i}\n"
            );
        }
        s + "GRAVITY(-G*N2>)\nZERO = FR() + FRSTAR()\nKANE()\n"
    }

    #[test]
    fn a_small_model_is_collected_throughout() {
        let src = include_str!("../../../models/heavy_top.al");
        let mut m = crate::lang::load("heavy_top.al", src).unwrap();
        let p = printed_eoms(&mut m).unwrap().unwrap();
        assert!(shown(&p).all(|s| matches!(s, Shown::Collected(_))));
        let text = p.to_text(&m.model.ar);
        assert!(text.starts_with("% Kinematic equations\n") && !text.contains("z1"), "{text}");
    }

    #[test]
    fn what_would_swell_is_printed_in_intermediates() {
        // Relative angles compose into angle sums, so a chain swells only from a dozen links.
        let mut m = crate::lang::load("chain16.al", &chain(16)).unwrap();
        let p = printed_eoms(&mut m).unwrap().unwrap();
        assert!(matches!(p.kinematics[0], Shown::Collected(_)), "a short quantity stays collected");
        assert!(matches!(p.equations[0], Shown::Named(_)));
        let text = p.to_text(&m.model.ar);
        assert!(text.starts_with("% Intermediates") && text.contains("\nz1 = "), "{text}");
        assert!(text.len() < 1_500_000, "{}", text.len());
        let latex = p.to_latex(&mut m.model.ar);
        assert!(latex.contains("\nz_{1} &= "), "{latex}");
    }
}
