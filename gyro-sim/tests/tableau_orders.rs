//! The tableaux against Butcher's order conditions: for every rooted tree `t` up to a method's
//! order, `sum_j b_j Phi_j(t) = 1 / gamma(t)`, and the same for the embedded weights `b - e` to
//! their order and for the continuous extension's weights `b_j(theta)` (`theta^|t| / gamma(t)`).
//! The trees are generated here; their counts (1, 1, 2, 4, 9, 20, 48, 115, 286, 719) are checked
//! against the known sequence.

use gyro_sim::tableau::{self, Tableau};
use gyro_sim::{DenseOutput, METHODS};

/// A rooted tree: its subtrees, sorted, so that equal trees compare equal.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Tree(Vec<Tree>);

impl Tree {
    /// Number of vertices.
    fn order(&self) -> usize {
        1 + self.0.iter().map(Tree::order).sum::<usize>()
    }

    /// Butcher's density: the order times the densities of the subtrees.
    fn gamma(&self) -> f64 {
        self.0.iter().map(Tree::gamma).product::<f64>() * self.order() as f64
    }

    /// Every tree with one more vertex, hung below some vertex of this one.
    fn grown(&self) -> Vec<Tree> {
        let mut out = vec![Tree::sorted(self.0.iter().cloned().chain([Tree(vec![])]).collect())];
        for (i, child) in self.0.iter().enumerate() {
            for g in child.grown() {
                let mut children = self.0.clone();
                children[i] = g;
                out.push(Tree::sorted(children));
            }
        }
        out
    }

    fn sorted(mut children: Vec<Tree>) -> Tree {
        children.sort();
        Tree(children)
    }
}

/// The trees of each order 1..=max, without repeats.
fn trees(max: usize) -> Vec<Vec<Tree>> {
    let mut all = vec![vec![Tree(vec![])]];
    while all.len() < max {
        let mut next: Vec<Tree> = all.last().unwrap().iter().flat_map(Tree::grown).collect();
        next.sort();
        next.dedup();
        all.push(next);
    }
    all
}

/// A tableau's stages and the continuous extension's extra stages as one strictly lower matrix.
fn full_a(tab: &Tableau) -> Vec<Vec<f64>> {
    let extra = tab.dense.as_ref().map_or(&[][..], |d| d.a);
    tab.a.iter().chain(extra).map(|row| row.to_vec()).collect()
}

/// `Phi_j(t)` for every stage `j`: 1 for the one-vertex tree, else the product over subtrees of
/// `sum_k a_jk Phi_k(subtree)`.
fn phi(a: &[Vec<f64>], t: &Tree) -> Vec<f64> {
    let mut v = vec![1.0; a.len()];
    for child in &t.0 {
        let w = phi(a, child);
        for (vi, row) in v.iter_mut().zip(a) {
            *vi *= row.iter().zip(&w).map(|(x, y)| x * y).sum::<f64>();
        }
    }
    v
}

/// Largest residual `|sum_j w_j Phi_j(t) - scale^|t| / gamma(t)|` over the trees of `order`.
fn residual(a: &[Vec<f64>], w: &[f64], trees: &[Tree], scale: f64) -> f64 {
    trees
        .iter()
        .map(|t| {
            let sum: f64 = w.iter().zip(phi(a, t)).map(|(x, y)| x * y).sum();
            (sum - scale.powi(t.order() as i32) / t.gamma()).abs()
        })
        .fold(0.0, f64::max)
}

/// Orders of the weights, the embedded weights and the interpolant of each built-in method.
fn orders(name: &str) -> (usize, usize, usize) {
    match name {
        "rk4" => (4, 0, 0),
        "dopri5" => (5, 4, 4),
        "dop853" => (8, 5, 7),
        "vern7" => (7, 6, 6),
        "vern9" => (9, 8, 9),
        other => panic!("no orders listed for {other}"),
    }
}

/// Agreement expected of a condition in double precision (the coefficients reach 10^2 or so).
const TOL: f64 = 1e-12;

#[test]
fn the_trees_are_counted_right() {
    let counts: Vec<usize> = trees(10).iter().map(Vec::len).collect();
    assert_eq!(counts, [1, 1, 2, 4, 9, 20, 48, 115, 286, 719]);
}

#[test]
fn rows_of_a_sum_to_the_nodes() {
    // Every Runge-Kutta row (the Taylor method has no tableau).
    for tab in METHODS.iter().filter_map(|m| m.tableau) {
        let nodes = tab.c.iter().chain(tab.dense.as_ref().map_or(&[][..], |d| d.c));
        for (i, (row, c)) in full_a(tab).iter().zip(nodes).enumerate() {
            assert!((row.iter().sum::<f64>() - c).abs() < 1e-14, "{} row {i}", tab.name);
        }
    }
}

#[test]
fn weights_meet_every_condition_up_to_their_order_and_not_beyond() {
    let all = trees(10);
    // Every Runge-Kutta row (the Taylor method has no tableau).
    for tab in METHODS.iter().filter_map(|m| m.tableau) {
        let (p, p_hat, _) = orders(tab.name);
        assert_eq!(p, tab.order as usize, "{}", tab.name);
        let a = full_a(tab);
        for (q, ts) in all.iter().enumerate().take(p) {
            let r = residual(&a, tab.b, ts, 1.0);
            assert!(r < TOL, "{}: order {} residual {r:e}", tab.name, q + 1);
        }
        assert!(residual(&a, tab.b, &all[p], 1.0) > 1e-8, "{} has a higher order than {p}", tab.name);
        let Some(e) = tab.e else { continue };
        let b_hat: Vec<f64> = tab.b.iter().zip(e).map(|(b, e)| b - e).collect();
        for (q, ts) in all.iter().enumerate().take(p_hat) {
            let r = residual(&a, &b_hat, ts, 1.0);
            assert!(r < TOL, "{}: embedded order {} residual {r:e}", tab.name, q + 1);
        }
        assert!(residual(&a, &b_hat, &all[p_hat], 1.0) > 1e-8, "{}: embedded order above {p_hat}", tab.name);
    }
}

/// The extension's weight polynomials at `theta`: `y(t + theta h) = y0 + h sum_j b_j(theta) k_j`.
/// The nested form's rows are the coefficients of `theta`, `theta (1 - theta)`,
/// `theta^2 (1 - theta)`, ... with the cubic Hermite part in the first three (the slope at the
/// step's end is the last stage of a first-same-as-last tableau).
fn dense_weights(tab: &Tableau, dense: &DenseOutput, theta: f64) -> Vec<f64> {
    let total = tab.c.len() + dense.c.len();
    let end = tab.c.len() - 1;
    assert!(tab.fsal, "{}: the end slope is a stage", tab.name);
    let mut rows = vec![vec![0.0; total]; 3];
    for (j, b) in tab.b.iter().enumerate() {
        rows[0][j] = *b;
        rows[1][j] = -b;
        rows[2][j] = 2.0 * b;
    }
    rows[1][0] += 1.0;
    rows[2][0] -= 1.0;
    rows[2][end] -= 1.0;
    for d in dense.d {
        let mut row = d.to_vec();
        row.resize(total, 0.0);
        rows.push(row);
    }
    let mut weights = vec![0.0; total];
    let mut basis = 1.0;
    for (r, row) in rows.iter().enumerate() {
        basis *= if r % 2 == 0 { theta } else { 1.0 - theta };
        for (w, x) in weights.iter_mut().zip(row) {
            *w += basis * x;
        }
    }
    weights
}

#[test]
fn continuous_extensions_meet_the_conditions_of_their_order() {
    let all = trees(10);
    // Every Runge-Kutta row (the Taylor method has no tableau).
    for tab in METHODS.iter().filter_map(|m| m.tableau) {
        let Some(dense) = &tab.dense else { continue };
        let q = orders(tab.name).2;
        let a = full_a(tab);
        for theta in [0.1, 1.0 / 3.0, 0.5, 0.77, 1.0] {
            let w = dense_weights(tab, dense, theta);
            for (k, ts) in all.iter().enumerate().take(q) {
                let r = residual(&a, &w, ts, theta);
                assert!(r < TOL, "{} at theta {theta}: order {} residual {r:e}", tab.name, k + 1);
            }
        }
        // At the end of the step the extension is the step's own weights.
        let w = dense_weights(tab, dense, 1.0);
        assert!(w.iter().zip(tab.b).all(|(x, b)| (x - b).abs() < 1e-13), "{}", tab.name);
    }
}

#[test]
fn verner_7_s_interpolant_misses_order_7_only_by_its_published_digits() {
    // Verner's seventh-order interpolant for the 7(6) pair: the order-7 conditions hold to a few
    // parts in 10^7 with the published coefficients (also in 40-digit arithmetic), so it is of
    // order 6 in the strict sense with a tiny seventh-order defect.
    let all = trees(7);
    let a = full_a(&tableau::VERN7);
    let dense = tableau::VERN7.dense.as_ref().unwrap();
    for theta in [1.0 / 3.0, 0.5, 0.7] {
        let r = residual(&a, &dense_weights(&tableau::VERN7, dense, theta), &all[6], theta);
        assert!(1e-9 < r && r < 1e-6, "theta {theta}: order-7 residual {r:e}");
    }
}
