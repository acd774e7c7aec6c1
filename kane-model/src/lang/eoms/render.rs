//! Rendering [`PrintedEoms`]: plain text, strings for JSON, and a LaTeX `align*` block, each
//! with the named intermediates its quantities use defined first.

use crate::expr::{Arena, Collected, CollectedTerm, ExprId, Intermediates};

use super::{PrintedEoms, Shown};

/// Terms per line of a long LaTeX equation.
const TERMS_PER_LINE: usize = 4;

/// Longest text of a piece of a collected quantity (a factor such as `cos(Q1 + Q2 + Q3)`)
/// still written out at each use; a longer one used more than once is named.
const LONGEST_INLINE_PIECE: usize = 24;

/// The printed quantities as plain-text expressions.
#[derive(Clone, Debug, PartialEq)]
pub struct EomsText {
    /// The named intermediates, in order: each name with its definition.
    pub intermediates: Vec<(String, String)>,
    /// `q'` right-hand sides.
    pub kinematics: Vec<String>,
    /// The mass matrix, row by row.
    pub mass_matrix: Vec<Vec<String>>,
    /// The forcing.
    pub forcing: Vec<String>,
    /// `Fr + Fr*`, row by row.
    pub equations: Vec<String>,
    /// The motion constraints, each `= 0`.
    pub constraints: Vec<String>,
}

/// The intermediates for printing `xs`: the quantities printed in named intermediates, and
/// the long pieces (factors, coefficient summands) that collected quantities repeat.
fn intermediates<'a>(ar: &Arena, xs: impl IntoIterator<Item = &'a Shown>) -> Intermediates {
    let mut roots = Vec::new();
    for s in xs {
        match s {
            Shown::Named(x) => roots.push(*x),
            Shown::Collected(c) => long_pieces(ar, &c.terms, &mut roots),
        }
    }
    Intermediates::new(ar, &roots)
}

/// The pieces of `terms` whose text is longer than [`LONGEST_INLINE_PIECE`], once per use.
fn long_pieces(ar: &Arena, terms: &[CollectedTerm], out: &mut Vec<ExprId>) {
    for t in terms {
        let pieces = t.scale.iter().chain(t.coefficient.iter().map(|(_, x)| x)).chain(&t.factors);
        out.extend(pieces.filter(|x| ar.to_text(**x).len() > LONGEST_INLINE_PIECE));
        long_pieces(ar, &t.inner, out);
    }
}

fn text(ar: &Arena, z: &Intermediates, s: &Shown) -> String {
    match s {
        Shown::Collected(c) => ar.collected_text_named(c, &z.names),
        Shown::Named(x) => z.text(ar, *x),
    }
}

impl PrintedEoms {
    /// Every quantity as plain text, with the intermediates they use.
    pub fn texts(&self, ar: &Arena) -> EomsText {
        let all = self.kinematics.iter().chain(self.mass_matrix.iter().flatten());
        let z = intermediates(ar, all.chain(&self.forcing).chain(&self.equations).chain(&self.constraints));
        let each = |xs: &[Shown]| xs.iter().map(|s| text(ar, &z, s)).collect::<Vec<String>>();
        EomsText {
            intermediates: z.text_lines(ar),
            kinematics: each(&self.kinematics),
            mass_matrix: self.mass_matrix.iter().map(|r| each(r)).collect(),
            forcing: each(&self.forcing),
            equations: each(&self.equations),
            constraints: each(&self.constraints),
        }
    }

    /// Plain text: the intermediates (when any), kinematic equations, mass matrix, forcing,
    /// and the equations.
    pub fn to_text(&self, ar: &Arena) -> String {
        let t = self.texts(ar);
        let mut s = String::new();
        if !t.intermediates.is_empty() {
            s.push_str("% Intermediates (Autolev's Z variables): quantities too large to collect use them\n");
            for (name, def) in &t.intermediates {
                s.push_str(&format!("{name} = {def}\n"));
            }
            s.push('\n');
        }
        s.push_str("% Kinematic equations\n");
        for (q, k) in self.coordinates.iter().zip(&t.kinematics) {
            s.push_str(&format!("{q}' = {k}\n"));
        }
        if !self.dependent.is_empty() {
            s.push_str(&format!(
                "\n% Motion constraints (each = 0), solved numerically for the dependent speeds {} wherever the\n% equations are evaluated; M and f are over {} (the equations of motion are\n% C^T (f - M u') = 0 with C = d(u)/d(independent speeds))\n",
                self.dependent.join(", "),
                self.speeds.iter().chain(&self.dependent).cloned().collect::<Vec<_>>().join(", ")
            ));
            for (i, x) in t.constraints.iter().enumerate() {
                s.push_str(&format!("CONSTRAINT[{}] = {x}\n", i + 1));
            }
        }
        s.push_str("\n% Mass matrix M (M u' = f)\n");
        for (i, row) in t.mass_matrix.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                s.push_str(&format!("M[{},{}] = {x}\n", i + 1, j + 1));
            }
        }
        s.push_str("\n% Forcing f\n");
        for (i, x) in t.forcing.iter().enumerate() {
            s.push_str(&format!("f[{}] = {x}\n", i + 1));
        }
        if !self.loads.is_empty() {
            s.push_str(&format!(
                "\n% Loads solved with the speed rates (KANE): {}, from the equations of the auxiliary speeds {}\n% (zero in every motion): ZERO[{}..{}] below; f is with these loads zero, ZERO has their terms\n",
                self.loads.join(", "),
                self.auxiliary.join(", "),
                self.speeds.len() + 1,
                self.speeds.len() + self.auxiliary.len()
            ));
        }
        s.push_str("\n% Equations of motion Fr + Fr* = f - M u' = 0, collected by state monomial");
        s.push_str(if t.intermediates.is_empty() { "\n" } else { " where short\n" });
        for (i, x) in t.equations.iter().enumerate() {
            s.push_str(&format!("ZERO[{}] = {x}\n", i + 1));
        }
        s
    }

    /// A LaTeX `align*` block (amsmath): the intermediates the block uses, kinematic
    /// equations, then `0 = Fr + Fr*` row by row, long collected rows broken after every few
    /// terms.
    pub fn to_latex(&self, ar: &mut Arena) -> String {
        let mut lhs = Vec::with_capacity(self.coordinates.len());
        for q in &self.coordinates {
            let dot = ar.lookup(&format!("{q}'")).map(|s| ar.symbol_expr(s));
            lhs.push(dot.map_or_else(|| format!("\\dot{{{q}}}"), |x| ar.to_latex(x)));
        }
        let ar = &*ar;
        let z = intermediates(ar, self.kinematics.iter().chain(&self.equations).chain(&self.constraints));
        let mut lines: Vec<String> =
            z.latex_lines(ar).into_iter().map(|(name, def)| format!("{name} &= {def}")).collect();
        for (lhs, k) in lhs.iter().zip(&self.kinematics) {
            let rhs = match k {
                Shown::Collected(c) => ar.collected_latex_named(c, &z.names),
                Shown::Named(x) => z.latex(ar, *x),
            };
            lines.push(format!("{lhs} &= {rhs}"));
        }
        for x in self.equations.iter().chain(&self.constraints) {
            match x {
                Shown::Collected(c) => lines.extend(latex_rows(ar, &z, c)),
                Shown::Named(x) => lines.push(format!("0 &= {}", z.latex(ar, *x))),
            }
        }
        format!(
            "% Equations of motion (needs \\usepackage{{amsmath}})\n\\begin{{align*}}\n{}\n\\end{{align*}}\n",
            lines.join(" \\\\\n")
        )
    }
}

/// `0 = c` as rows of a few terms each.
fn latex_rows(ar: &Arena, z: &Intermediates, c: &Collected) -> Vec<String> {
    let chunks: Vec<Collected> =
        c.terms.chunks(TERMS_PER_LINE).map(|t| Collected { terms: t.to_vec() }).collect();
    if chunks.is_empty() {
        return vec!["0 &= 0".into()];
    }
    let mut lines = Vec::with_capacity(chunks.len());
    for (i, c) in chunks.iter().enumerate() {
        let text = ar.collected_latex_named(c, &z.names);
        let sign = if i > 0 && !c.terms[0].negative { "+ " } else { "" };
        let lead = if i == 0 { "0 &= " } else { "&\\quad " };
        lines.push(format!("{lead}{sign}{text}"));
    }
    lines
}
