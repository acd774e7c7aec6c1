//! The words of a comparison: one line per equation or component, then what the whole says
//! (equal, equal up to sign, equal up to the order of the equations, or how many differ).

use std::fmt;

use crate::expr::Equivalence;

use super::{Comparison, Outcome, Relation};

/// How equality was established.
fn how(v: &Equivalence) -> String {
    match v {
        Equivalence::Proven => "proven".into(),
        Equivalence::NumericallyEqual { samples, max_relative_residual, tolerance } => format!(
            "numerically, at {samples} points around the INPUT values (largest relative residual \
             {max_relative_residual:.1e}, tolerance {tolerance:.0e})"
        ),
        Equivalence::Differs { .. } | Equivalence::Inconclusive => "not shown".into(),
    }
}

/// `  at Q1 = 0.1, ...: hand 1, derived 2` for a verdict of difference.
fn where_it_differs(v: &Equivalence) -> Option<String> {
    let Equivalence::Differs { point, lhs, rhs } = v else { return None };
    let at: Vec<String> = point.iter().map(|(n, v)| format!("{n} = {v:.6}")).collect();
    Some(format!("  for example at {}: hand {lhs:.6e}, derived {rhs:.6e}", at.join(", ")))
}

impl Comparison {
    fn line(&self, rows: &[String]) -> String {
        match &self.relation {
            Relation::Equal if self.verdict == Equivalence::Proven => format!("{}: proven equal", self.label),
            Relation::Equal => format!("{}: equal {}", self.label, how(&self.verdict)),
            Relation::Negated if self.equation => {
                format!("{}: equal up to sign (hand = -derived), {}", self.label, how(&self.verdict))
            }
            Relation::Negated => {
                format!("{}: DIFFERS in sign: hand = -derived, {}", self.label, how(&self.verdict))
            }
            Relation::Row { row, negated } => format!(
                "{}: equals derived {}{} (the order of the equations differs), {}",
                self.label,
                if *negated { "-" } else { "" },
                rows.get(*row).map_or("?", String::as_str),
                how(&self.verdict)
            ),
            Relation::Differs { difference } => {
                let mut s = format!("{}: DIFFERS: hand - derived = {difference}", self.label);
                if let Some(w) = where_it_differs(&self.verdict) {
                    s.push('\n');
                    s.push_str(&w);
                }
                s
            }
            Relation::Inconclusive => {
                format!("{}: inconclusive: no point where both sides are finite", self.label)
            }
        }
    }
}

impl Outcome {
    /// What the comparisons say together.
    pub fn summary(&self) -> String {
        let c = &self.comparisons;
        if c.is_empty() {
            return "nothing to compare".into();
        }
        let negated =
            |x: &&Comparison| matches!(x.relation, Relation::Negated | Relation::Row { negated: true, .. });
        let rejected = c.iter().filter(|x| !self.accepted(x)).count();
        if rejected > 0 {
            let signs = c.iter().filter(negated).filter(|x| !self.accepted(x)).count();
            let mut s = format!("{rejected} of {} differ", c.len());
            if signs > 0 {
                s.push_str(&format!(
                    " ({signs} only in sign: hand = -derived{})",
                    if c.iter().filter(negated).all(|x| x.equation) {
                        "; an equation negated as a whole is the same equation: pass --up-to-sign to accept that"
                    } else {
                        ", a rate or a quantity of the opposite sign is a different one"
                    }
                ));
            }
            return s;
        }
        let negated_count = c.iter().filter(negated).count();
        let moved = c.iter().filter(|x| matches!(x.relation, Relation::Row { .. })).count();
        let mut s = String::from("equal");
        if negated_count == c.len() {
            s.push_str(" up to sign: every equation is the derived one negated");
        } else if negated_count > 0 {
            s.push_str(&format!(" up to sign: {negated_count} of {} negated", c.len()));
        }
        if moved > 0 {
            let pairs: Vec<String> = c
                .iter()
                .filter_map(|x| match x.relation {
                    Relation::Row { row, .. } => Some(format!("{} is derived {}", x.label, self.rows[row])),
                    _ => None,
                })
                .collect();
            s.push_str(&format!(
                "{} up to the order of the equations: {}",
                if negated_count > 0 { " and" } else { "" },
                pairs.join(", ")
            ));
        }
        s
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in &self.comparisons {
            writeln!(f, "{}", c.line(&self.rows))?;
        }
        writeln!(f, "{}", self.summary())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(relations: Vec<Relation>) -> Outcome {
        let comparisons = relations
            .into_iter()
            .enumerate()
            .map(|(i, relation)| Comparison {
                label: format!("ZERO[{}]", i + 1),
                relation,
                verdict: Equivalence::Proven,
                equation: true,
            })
            .collect();
        Outcome { comparisons, rows: vec!["ZERO[1]".into(), "ZERO[2]".into()], up_to_sign: true }
    }

    #[test]
    fn the_summary_names_sign_and_order() {
        let o = outcome(vec![Relation::Negated, Relation::Negated]);
        assert_eq!(o.summary(), "equal up to sign: every equation is the derived one negated");
        let o =
            outcome(vec![Relation::Row { row: 1, negated: false }, Relation::Row { row: 0, negated: true }]);
        assert_eq!(
            o.summary(),
            "equal up to sign: 1 of 2 negated and up to the order of the equations: \
             ZERO[1] is derived ZERO[2], ZERO[2] is derived ZERO[1]"
        );
        let o = outcome(vec![Relation::Equal, Relation::Differs { difference: "x".into() }]);
        assert!(o.differs());
        assert_eq!(o.summary(), "1 of 2 differ");
        assert!(o.to_string().contains("ZERO[2]: DIFFERS: hand - derived = x\n"));
    }
}
