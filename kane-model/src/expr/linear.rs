//! Coefficients of expressions linear in a set of symbols, and of a polynomial's powers.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId};

impl Arena {
    /// Splits `e = sum(c_i * s_i) + r` for `e` linear in `syms`; returns `(c, r)`.
    ///
    /// This is how a mass matrix is read off the equations: the coefficients of `u'`.
    pub fn linear_coefficients(
        &mut self,
        e: ExprId,
        syms: &[SymbolId],
    ) -> Result<(Vec<ExprId>, ExprId), ExprError> {
        let mut coeffs = Vec::with_capacity(syms.len());
        for &s in syms {
            let c = self.diff(e, s)?;
            let free = self.free_symbols(&[c]);
            if let Some(&bad) = syms.iter().find(|x| free.contains(x)) {
                // A large expression's text would take longer to print than to read.
                let expr = match self.graph_size(e) {
                    n if n <= 200 => format!("`{}`", self.to_text(e)),
                    n => format!("an expression of {n} nodes"),
                };
                return Err(ExprError::NotLinear { expr, symbol: self.symbol_info(bad).name.clone() });
            }
            coeffs.push(c);
        }
        let zero = self.zero();
        let mut map = FxHashMap::default();
        for &s in syms {
            map.insert(self.symbol_expr(s), zero);
        }
        let rest = self.subs(e, &map)?;
        Ok((coeffs, rest))
    }
}

impl Arena {
    /// The coefficient of `s^k` (`k >= 0`) in `e` multiplied out, other symbols taken as
    /// constants: `coefficient(a x^2 + b x + x y, x, 1)` is `b + y`.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// let mut ar = Arena::new();
    /// let [a, b, x] = ["a", "b", "x"].map(|n| ar.constant(n).unwrap());
    /// let x2 = ar.powi(x, 2).unwrap();
    /// let ax2 = ar.mul(&[a, x2]).unwrap();
    /// let bx = ar.mul(&[b, x]).unwrap();
    /// let e = ar.add(&[ax2, bx]).unwrap();
    /// let s = ar.as_symbol(x).unwrap();
    /// let c = ar.coefficient(e, s, 2).unwrap();
    /// assert_eq!(ar.to_text(c), "a");
    /// ```
    pub fn coefficient(&mut self, e: ExprId, s: SymbolId, k: i64) -> Result<ExprId, ExprError> {
        let expanded = self.expand(e)?;
        let x = self.symbol_expr(s);
        let mut kept = Vec::new();
        for t in self.terms(expanded) {
            let mut power = 0;
            let mut rest = Vec::new();
            for f in self.factors(t) {
                match *self.node(f) {
                    _ if f == x => power += 1,
                    Node::Pow([b, n]) if b == x => match self.as_rational(n).and_then(|r| r.as_i64()) {
                        Some(n) => power += n,
                        None => return Err(self.not_polynomial(e, s)),
                    },
                    _ if self.free_symbols(&[f]).contains(&s) => return Err(self.not_polynomial(e, s)),
                    _ => rest.push(f),
                }
            }
            if power == k {
                kept.push(self.mul(&rest)?);
            }
        }
        self.add(&kept)
    }

    fn not_polynomial(&self, e: ExprId, s: SymbolId) -> ExprError {
        let expr = match self.graph_size(e) {
            n if n <= 200 => format!("`{}`", self.to_text(e)),
            n => format!("an expression of {n} nodes"),
        };
        ExprError::NotPolynomial { expr, symbol: self.symbol_info(s).name.clone() }
    }

    /// Solves equations (each `= 0`, linear in `unknowns`) for the unknowns by Gauss-Jordan
    /// elimination with the first structurally non-zero pivot.
    pub fn solve_linear(
        &mut self,
        equations: &[ExprId],
        unknowns: &[SymbolId],
    ) -> Result<Vec<ExprId>, ExprError> {
        let m = unknowns.len();
        if equations.len() != m {
            return Err(ExprError::NotSquare { equations: equations.len(), unknowns: m });
        }
        let (mut a, mut b) = (Vec::with_capacity(m), Vec::with_capacity(m));
        for &g in equations {
            let (coeffs, rest) = self.linear_coefficients(g, unknowns)?;
            a.push(coeffs);
            b.push(vec![self.neg(rest)?]);
        }
        Ok(self.solve_matrix(&a, &b)?.into_iter().map(|x| x[0]).collect())
    }
}

impl Arena {
    /// `X` with `A X = B` for a square `A` (rows) and `B` with any number of columns, by
    /// Gauss-Jordan elimination on the expression graph (nothing multiplied out, so the result
    /// grows with the graph, not with the terms), each pivot the first structurally non-zero.
    pub fn solve_matrix(
        &mut self,
        a: &[Vec<ExprId>],
        b: &[Vec<ExprId>],
    ) -> Result<Vec<Vec<ExprId>>, ExprError> {
        let m = a.len();
        if b.len() != m || a.iter().any(|r| r.len() != m) {
            return Err(ExprError::SingularSystem);
        }
        let mut rows: Vec<(Vec<ExprId>, Vec<ExprId>)> = a.iter().cloned().zip(b.iter().cloned()).collect();
        for col in 0..m {
            let pivot = (col..m).find(|&r| !self.is_zero(rows[r].0[col])).ok_or(ExprError::SingularSystem)?;
            rows.swap(col, pivot);
            let p = rows[col].0[col];
            for r in 0..m {
                if r == col || self.is_zero(rows[r].0[col]) {
                    continue;
                }
                let factor = self.div(rows[r].0[col], p)?;
                for k in col..m {
                    let t = self.mul(&[factor, rows[col].0[k]])?;
                    rows[r].0[k] = self.sub(rows[r].0[k], t)?;
                }
                for k in 0..rows[r].1.len() {
                    let t = self.mul(&[factor, rows[col].1[k]])?;
                    rows[r].1[k] = self.sub(rows[r].1[k], t)?;
                }
            }
        }
        let mut out = Vec::with_capacity(m);
        for (coeffs, rhs) in rows.iter().enumerate().map(|(i, r)| (r.0[i], &r.1)) {
            out.push(rhs.iter().map(|x| self.div(*x, coeffs)).collect::<Result<Vec<_>, _>>()?);
        }
        Ok(out)
    }

    /// The determinant of the square matrix `rows`, by expansion along rows over column subsets
    /// (no division: its only zeros are where the matrix is singular).
    pub fn determinant(&mut self, rows: &[Vec<ExprId>]) -> Result<ExprId, ExprError> {
        let m = rows.len();
        if m > 16 || rows.iter().any(|r| r.len() != m) {
            return Err(ExprError::SingularSystem);
        }
        // minors[S]: the determinant of the first |S| rows on the columns in S.
        let mut minors: FxHashMap<u32, ExprId> = FxHashMap::default();
        minors.insert(0, self.one());
        for row in rows {
            let mut next: FxHashMap<u32, ExprId> = FxHashMap::default();
            for (&set, &minor) in &minors {
                for (j, &a) in row.iter().enumerate() {
                    if set & (1 << j) != 0 || self.is_zero(a) || self.is_zero(minor) {
                        continue;
                    }
                    let bigger = set | (1 << j);
                    // Moving column j to the end passes the columns of `set` above j.
                    let above = (set >> j).count_ones();
                    let mut t = self.mul(&[a, minor])?;
                    if above % 2 == 1 {
                        t = self.neg(t)?;
                    }
                    let sum = match next.get(&bigger) {
                        Some(&s) => self.add(&[s, t])?,
                        None => t,
                    };
                    next.insert(bigger, sum);
                }
            }
            minors = next;
        }
        Ok(minors.get(&((1u32 << m) - 1)).copied().unwrap_or_else(|| self.zero()))
    }

    /// The solution of `a x = rhs` by Cramer's rule, `x_j = det(a_j) / det(a)` with column `j`
    /// replaced by `rhs`: finite wherever `a` is regular, whatever its entries' zeros.
    pub fn solve_cramer(&mut self, a: &[Vec<ExprId>], rhs: &[ExprId]) -> Result<Vec<ExprId>, ExprError> {
        let det = self.determinant(a)?;
        if self.is_zero(det) {
            return Err(ExprError::SingularSystem);
        }
        let mut x = Vec::with_capacity(rhs.len());
        for j in 0..rhs.len() {
            let replaced: Vec<Vec<ExprId>> = a
                .iter()
                .zip(rhs)
                .map(|(row, r)| row.iter().enumerate().map(|(k, e)| if k == j { *r } else { *e }).collect())
                .collect();
            let num = self.determinant(&replaced)?;
            x.push(self.div(num, det)?);
        }
        Ok(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_off_coefficients() {
        let mut ar = Arena::new();
        let [a, x, y] = ["a", "x", "y"].map(|n| ar.constant(n).unwrap());
        let sx = ar.as_symbol(x).unwrap();
        let sy = ar.as_symbol(y).unwrap();
        let sa = ar.sin(a).unwrap();
        let t1 = ar.mul(&[sa, x]).unwrap();
        let three = ar.integer(3);
        let t2 = ar.mul(&[three, y]).unwrap();
        let e = ar.add(&[t1, t2, a]).unwrap();
        let (c, r) = ar.linear_coefficients(e, &[sx, sy]).unwrap();
        assert_eq!(c, vec![sa, three]);
        assert_eq!(r, a);
    }

    #[test]
    fn cramers_rule_solves_where_the_first_pivot_vanishes() {
        let mut ar = Arena::new();
        let [a, b, c, d, e] = ["a", "b", "c", "d", "e"].map(|n| ar.constant(n).unwrap());
        let sa = ar.sin(a).unwrap();
        let one = ar.one();
        let zero = ar.zero();
        // [[sin a, 1, 0], [1, 0, b], [0, c, 1]] x = [d, e, 1]: regular at a = 0.
        let m = vec![vec![sa, one, zero], vec![one, zero, b], vec![zero, c, one]];
        let x = ar.solve_cramer(&m, &[d, e, one]).unwrap();
        let vals = [("a", 0.0), ("b", 0.5), ("c", 2.0), ("d", 1.5), ("e", -0.25)];
        let xs: Vec<f64> = x.iter().map(|xi| ar.eval_named(*xi, &vals).unwrap()).collect();
        let (bv, cv, dv, ev) = (0.5, 2.0, 1.5, -0.25);
        // Row 1: x1 = d; row 2: x0 + b x2 = e; row 3: c x1 + x2 = 1.
        let x2 = 1.0 - cv * dv;
        let want = [ev - bv * x2, dv, x2];
        for (g, w) in xs.iter().zip(want) {
            assert!((g - w).abs() < 1e-14, "{xs:?} {want:?}");
        }
        // det = -sin(a) b c - 1, here at a = 0.3.
        let det = ar.determinant(&m).unwrap();
        let at = [("a", 0.3), ("b", 0.5), ("c", 2.0)];
        let want = -(0.3f64).sin() * bv * cv - 1.0;
        assert!((ar.eval_named(det, &at).unwrap() - want).abs() < 1e-14);
    }

    #[test]
    fn solves_a_linear_system() {
        let mut ar = Arena::new();
        let [a, b, x, y] = ["a", "b", "x", "y"].map(|n| ar.constant(n).unwrap());
        let (sx, sy) = (ar.as_symbol(x).unwrap(), ar.as_symbol(y).unwrap());
        // a x + b y - 1 = 0, x - y = 0  =>  x = y = 1 / (a + b)
        let ax = ar.mul(&[a, x]).unwrap();
        let by = ar.mul(&[b, y]).unwrap();
        let m1 = ar.minus_one();
        let e1 = ar.add(&[ax, by, m1]).unwrap();
        let e2 = ar.sub(x, y).unwrap();
        let sol = ar.solve_linear(&[e1, e2], &[sx, sy]).unwrap();
        let v = ar.eval_named(sol[0], &[("a", 2.0), ("b", 3.0)]).unwrap();
        assert!((v - 0.2).abs() < 1e-15);
        let z = ar.zero();
        assert_eq!(ar.solve_linear(&[z, e2], &[sx, sy]), Err(ExprError::SingularSystem));
    }

    #[test]
    fn nonlinear_is_an_error() {
        let mut ar = Arena::new();
        let x = ar.constant("x").unwrap();
        let sx = ar.as_symbol(x).unwrap();
        let e = ar.powi(x, 2).unwrap();
        assert!(matches!(ar.linear_coefficients(e, &[sx]), Err(ExprError::NotLinear { .. })));
    }
}
