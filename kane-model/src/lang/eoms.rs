//! `kane eoms`: a model's equations of motion printed for reading, simplified and in the
//! file's names, as text or as a LaTeX `align*` block.

use crate::expr::{Collected, ExprError, ExprId};

use super::interp::LoadedModel;
use super::present::Presenter;

/// Terms per line of a long LaTeX equation.
const TERMS_PER_LINE: usize = 4;

/// A model's equations, simplified and collected.
pub struct PrintedEoms {
    /// Coordinate names.
    pub coordinates: Vec<String>,
    /// Speed names.
    pub speeds: Vec<String>,
    /// `q'` right-hand sides.
    pub kinematics: Vec<Collected>,
    /// The mass matrix `M` of `M u' = f`.
    pub mass_matrix: Vec<Vec<Collected>>,
    /// The forcing `f`.
    pub forcing: Vec<Collected>,
    /// `Fr + Fr* = f - M u'`, row by row.
    pub equations: Vec<Collected>,
}

/// The equations of `m` (which must hold them), simplified.
pub fn printed_eoms(m: &mut LoadedModel) -> Result<Option<PrintedEoms>, ExprError> {
    let Some(e) = m.equations.clone() else { return Ok(None) };
    let p: Presenter = m.presenter()?;
    let ar = &mut m.model.ar;
    let name = |ar: &crate::expr::Arena, s: &crate::expr::SymbolId| ar.symbol_info(*s).name.clone();
    let tidy = |ar: &mut crate::expr::Arena, xs: &[ExprId]| -> Result<Vec<Collected>, ExprError> {
        xs.iter().map(|x| p.tidy(ar, *x)).collect()
    };
    let mut equations = Vec::with_capacity(e.forcing.len());
    for (r, f) in e.forcing.iter().enumerate() {
        let mut terms = vec![*f];
        for (s, u) in e.speed_derivatives.iter().enumerate() {
            let u = ar.symbol_expr(*u);
            let t = ar.mul(&[e.mass_matrix[r][s], u])?;
            terms.push(ar.neg(t)?);
        }
        equations.push(ar.add(&terms)?);
    }
    let mut mass_matrix = Vec::with_capacity(e.mass_matrix.len());
    for row in &e.mass_matrix {
        mass_matrix.push(tidy(ar, row)?);
    }
    Ok(Some(PrintedEoms {
        coordinates: e.coordinates.iter().map(|s| name(ar, s)).collect(),
        speeds: e.speeds.iter().map(|s| name(ar, s)).collect(),
        kinematics: tidy(ar, &e.kinematics)?,
        mass_matrix,
        forcing: tidy(ar, &e.forcing)?,
        equations: tidy(ar, &equations)?,
    }))
}

impl PrintedEoms {
    /// Plain text: kinematic equations, mass matrix, forcing, and the equations collected.
    pub fn to_text(&self, ar: &crate::expr::Arena) -> String {
        let mut s = String::from("% Kinematic equations\n");
        for (q, k) in self.coordinates.iter().zip(&self.kinematics) {
            s.push_str(&format!("{q}' = {}\n", ar.collected_text(k)));
        }
        s.push_str("\n% Mass matrix M (M u' = f)\n");
        for (i, row) in self.mass_matrix.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                s.push_str(&format!("M[{},{}] = {}\n", i + 1, j + 1, ar.collected_text(x)));
            }
        }
        s.push_str("\n% Forcing f\n");
        for (i, x) in self.forcing.iter().enumerate() {
            s.push_str(&format!("f[{}] = {}\n", i + 1, ar.collected_text(x)));
        }
        s.push_str("\n% Equations of motion Fr + Fr* = f - M u' = 0, collected by state monomial\n");
        for (i, x) in self.equations.iter().enumerate() {
            s.push_str(&format!("ZERO[{}] = {}\n", i + 1, ar.collected_text(x)));
        }
        s
    }

    /// A LaTeX `align*` block (amsmath): kinematic equations, then `0 = Fr + Fr*` row by row,
    /// long rows broken after every few terms.
    pub fn to_latex(&self, ar: &mut crate::expr::Arena) -> String {
        let mut lines = Vec::new();
        for (q, k) in self.coordinates.iter().zip(&self.kinematics) {
            let lhs = ar.lookup(&format!("{q}'")).map(|s| ar.symbol_expr(s));
            let lhs = lhs.map_or_else(|| format!("\\dot{{{q}}}"), |x| ar.to_latex(x));
            lines.push(format!("{lhs} &= {}", ar.collected_latex(k)));
        }
        for x in &self.equations {
            let chunks: Vec<Collected> =
                x.terms.chunks(TERMS_PER_LINE).map(|t| Collected { terms: t.to_vec() }).collect();
            if chunks.is_empty() {
                lines.push("0 &= 0".into());
            }
            for (i, c) in chunks.iter().enumerate() {
                let text = ar.collected_latex(c);
                let sign = if i > 0 && !c.terms[0].negative { "+ " } else { "" };
                let lead = if i == 0 { "0 &= " } else { "&\\quad " };
                lines.push(format!("{lead}{sign}{text}"));
            }
        }
        format!(
            "% Equations of motion (needs \\usepackage{{amsmath}})\n\\begin{{align*}}\n{}\n\\end{{align*}}\n",
            lines.join(" \\\\\n")
        )
    }
}
