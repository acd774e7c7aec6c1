//! Writing parameter-only expressions in the user's own names.
//!
//! A model file names combinations of parameters (`K1 = 1/2*M3*L^2`); the derivation expands
//! them. [`Abbreviations`] takes the names back: the definitions are brought to echelon form
//! over their expanded monomials (each row with a pivot monomial no later row holds), and an
//! expression is reduced row by row, so a linear combination of the definitions comes back as
//! the same combination of the names.

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node};
use super::number::Number;

/// One echelon row: an expanded polynomial, the names it equals, and its pivot.
#[derive(Clone, Debug)]
struct Row {
    poly: ExprId,
    named: ExprId,
    pivot: ExprId,
    pivot_coeff: ExprId,
}

/// Names for parameter-only expressions, ready to rewrite expressions in them.
#[derive(Clone, Debug, Default)]
pub struct Abbreviations {
    rows: Vec<Row>,
}

/// The terms of an expanded expression as `(number, monomial)`; a number's monomial is 1.
fn terms(ar: &mut Arena, e: ExprId) -> Vec<(Number, ExprId)> {
    let ts: Vec<ExprId> = match ar.node(e) {
        Node::Sum(t) => t.to_vec(),
        _ if ar.is_zero(e) => Vec::new(),
        _ => vec![e],
    };
    ts.into_iter()
        .map(|t| match ar.as_number(t) {
            Some(n) => (n, ar.one()),
            None => ar.split_coefficient(t),
        })
        .collect()
}

/// `poly - k * row.poly` expanded, and `acc + k * row.named`, with `k` chosen to cancel the
/// row's pivot; `None` when `poly` does not hold the pivot.
fn eliminate(ar: &mut Arena, poly: ExprId, row: &Row) -> Result<Option<(ExprId, ExprId)>, ExprError> {
    let Some((c, _)) = terms(ar, poly).into_iter().find(|(_, m)| *m == row.pivot) else {
        return Ok(None);
    };
    let c = ar.number(c);
    let k = ar.div(c, row.pivot_coeff)?;
    let scaled = ar.mul(&[k, row.poly])?;
    let scaled = ar.expand(scaled)?;
    let rest = ar.sub(poly, scaled)?;
    let named = ar.mul(&[k, row.named])?;
    Ok(Some((ar.expand(rest)?, named)))
}

impl Abbreviations {
    /// Abbreviations for `defs`: each `(name, value)` pair says the expression `name` (usually
    /// a symbol) stands for the parameter-only `value`. Definitions that are combinations of
    /// earlier ones are dropped.
    ///
    /// Shorter definitions are taken first, so a combination is written with the fewest names
    /// (`IBXX - IBYY` comes back as `-IBZZ` when `IBZZ` is the shorter definition).
    pub fn new(ar: &mut Arena, defs: &[(ExprId, ExprId)]) -> Result<Abbreviations, ExprError> {
        let mut expanded = Vec::with_capacity(defs.len());
        for &(name, value) in defs {
            let poly = ar.expand(value)?;
            expanded.push((terms(ar, poly).len(), name, poly));
        }
        expanded.sort_by_key(|d| d.0);
        let mut rows: Vec<Row> = Vec::new();
        for (_, name, poly) in expanded {
            let mut poly = poly;
            let mut named = name;
            for row in &rows {
                if let Some((p, k_named)) = eliminate(ar, poly, row)? {
                    poly = p;
                    named = ar.sub(named, k_named)?;
                }
            }
            let one = ar.one();
            let Some(&(c, pivot)) = terms(ar, poly).iter().find(|(_, m)| *m != one) else {
                continue;
            };
            let pivot_coeff = ar.number(c);
            rows.push(Row { poly, named, pivot, pivot_coeff });
        }
        Ok(Abbreviations { rows })
    }

    /// True when there are no names to use.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// `e` (parameter-only) in the names where that makes it shorter: the named combination
    /// plus what the names do not cover, or `e` expanded when the names do not help.
    pub fn rewrite(&self, ar: &mut Arena, e: ExprId) -> Result<ExprId, ExprError> {
        let original = ar.expand(e)?;
        let mut poly = original;
        let mut named = Vec::new();
        for row in &self.rows {
            if let Some((p, k_named)) = eliminate(ar, poly, row)? {
                poly = p;
                named.push(k_named);
            }
        }
        if named.is_empty() {
            return Ok(original);
        }
        named.push(poly);
        let out = ar.add(&named)?;
        let out = ar.expand(out)?;
        let size = |ar: &mut Arena, x: ExprId| terms(ar, x).len();
        if ar.is_zero(poly) || size(ar, out) < size(ar, original) {
            Ok(out)
        } else {
            Ok(original)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn combinations_of_definitions_come_back_in_names() {
        let mut ar = Arena::new();
        let [m, l, h] = ["M", "L", "H"].map(|n| ar.constant(n).unwrap());
        let [k1, k2] = ["K1", "K2"].map(|n| ar.constant(n).unwrap());
        // K1 = M*L^2/2, K2 = M*L^2/4 + M*H^2/12
        let l2 = ar.powi(l, 2).unwrap();
        let h2 = ar.powi(h, 2).unwrap();
        let half = ar.rational(1, 2).unwrap();
        let quarter = ar.rational(1, 4).unwrap();
        let twelfth = ar.rational(1, 12).unwrap();
        let v1 = ar.mul(&[half, m, l2]).unwrap();
        let a = ar.mul(&[quarter, m, l2]).unwrap();
        let b = ar.mul(&[twelfth, m, h2]).unwrap();
        let v2 = ar.add(&[a, b]).unwrap();
        let ab = Abbreviations::new(&mut ar, &[(k1, v1), (k2, v2)]).unwrap();
        // K2 - K1 written out: -M*L^2/4 + M*H^2/12
        let d = ar.sub(v2, v1).unwrap();
        let r = ab.rewrite(&mut ar, d).unwrap();
        let expected = ar.sub(k2, k1).unwrap();
        assert_eq!(r, expected, "{}", ar.to_text(r));
        // Something the names do not cover stays as it is.
        let x = ar.mul(&[m, h]).unwrap();
        assert_eq!(ab.rewrite(&mut ar, x).unwrap(), x);
    }

    #[test]
    fn the_shortest_names_are_preferred() {
        // IXX = M*H^2/12, IYY = M*(W^2 + H^2)/12, IZZ = M*W^2/12: IXX - IYY is -IZZ.
        let mut ar = Arena::new();
        let [m, h, w] = ["M", "H", "W"].map(|n| ar.constant(n).unwrap());
        let [ixx, iyy, izz] = ["IXX", "IYY", "IZZ"].map(|n| ar.constant(n).unwrap());
        let k = ar.rational(1, 12).unwrap();
        let (h2, w2) = (ar.powi(h, 2).unwrap(), ar.powi(w, 2).unwrap());
        let vx = ar.mul(&[k, m, h2]).unwrap();
        let hw = ar.add(&[h2, w2]).unwrap();
        let vy = ar.mul(&[k, m, hw]).unwrap();
        let vz = ar.mul(&[k, m, w2]).unwrap();
        let ab = Abbreviations::new(&mut ar, &[(ixx, vx), (iyy, vy), (izz, vz)]).unwrap();
        let d = ar.sub(vx, vy).unwrap();
        let r = ab.rewrite(&mut ar, d).unwrap();
        assert_eq!(ar.to_text(r), "-IZZ");
    }
}
