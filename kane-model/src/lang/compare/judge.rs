//! Judging one hand expression against the derived ones: equal, equal up to sign, equal to
//! another row (the order differs), or different, with the simplified difference.

use crate::expr::{Arena, Equivalence, EquivalenceConfig, ExprError, ExprId};

use super::super::present::Presenter;

/// How a hand expression relates to the derived ones.
#[derive(Clone, Debug, PartialEq)]
pub enum Relation {
    /// Equal to the derived expression in its place.
    Equal,
    /// Equal to the derived expression in its place, negated.
    Negated,
    /// Equal to another derived row (0-based), perhaps negated: the order differs.
    Row {
        /// The derived row it equals.
        row: usize,
        /// Whether it equals that row negated.
        negated: bool,
    },
    /// Different; `difference` holds hand minus derived, simplified.
    Differs {
        /// `hand - derived`, simplified, in the file's names.
        difference: String,
    },
    /// No point was found where both sides are finite.
    Inconclusive,
}

/// True for a verdict of equality (proven or numerical).
pub(crate) fn is_equal(v: &Equivalence) -> bool {
    matches!(v, Equivalence::Proven | Equivalence::NumericallyEqual { .. })
}

/// What is compared: the arena, the sampling, and the presenter for differences.
pub(super) struct Judge<'a> {
    pub(super) ar: &'a mut Arena,
    pub(super) cfg: &'a EquivalenceConfig,
    pub(super) presenter: &'a Presenter,
}

impl Judge<'_> {
    /// `hand` against `derived[at]`; with `reorder`, against the other rows too.
    pub(super) fn judge(
        &mut self,
        hand: ExprId,
        derived: &[ExprId],
        at: usize,
        reorder: bool,
    ) -> Result<(Relation, Equivalence), ExprError> {
        let v = self.ar.equivalent(hand, derived[at], self.cfg)?;
        if is_equal(&v) {
            return Ok((Relation::Equal, v));
        }
        if let Some(vn) = self.negated(hand, derived[at])? {
            return Ok((Relation::Negated, vn));
        }
        if reorder {
            for (j, d) in derived.iter().enumerate().filter(|(j, _)| *j != at) {
                let vj = self.ar.equivalent(hand, *d, self.cfg)?;
                if is_equal(&vj) {
                    return Ok((Relation::Row { row: j, negated: false }, vj));
                }
                if let Some(vn) = self.negated(hand, *d)? {
                    return Ok((Relation::Row { row: j, negated: true }, vn));
                }
            }
        }
        if v == Equivalence::Inconclusive {
            return Ok((Relation::Inconclusive, v));
        }
        let diff = self.ar.sub(hand, derived[at])?;
        let difference = self.shorter_difference(diff)?;
        Ok((Relation::Differs { difference }, v))
    }

    /// `diff` in the file's names, with angles reduced (so groups that are zero vanish) when that
    /// reads shorter than the difference as written.
    fn shorter_difference(&mut self, diff: ExprId) -> Result<String, ExprError> {
        let written = self.presenter.text(self.ar, diff)?;
        let Ok(reduced) = self.ar.reduce_angles(diff) else { return Ok(written) };
        let reduced = self.presenter.text(self.ar, reduced)?;
        Ok(if reduced.len() <= written.len() { reduced } else { written })
    }

    /// The verdict that `hand = -derived`, when it holds (and neither side is zero).
    fn negated(&mut self, hand: ExprId, derived: ExprId) -> Result<Option<Equivalence>, ExprError> {
        if self.ar.is_zero(derived) {
            return Ok(None);
        }
        let minus = self.ar.neg(derived)?;
        let v = self.ar.equivalent(hand, minus, self.cfg)?;
        Ok(is_equal(&v).then_some(v))
    }
}
