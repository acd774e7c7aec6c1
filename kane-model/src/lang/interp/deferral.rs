//! Work a generation run may never need, kept for later: Kane's `M` and `f`, and assignments
//! that call FR() or FRSTAR(), for a tree large enough that its order-n form is tried first
//! (forming them costs O(n^3) in the links). They are settled before any statement that could
//! change what they read or that reads them; at the end of the file `M` and `f` stay unformed
//! ([`crate::mechanics::KaneEquations::formed`]) and the deferred names stay unassigned.

use super::super::ast::{AssignOp, Expr, ExprKind, Stmt, StmtKind};
use super::{At, IResult, Interpreter};

impl Interpreter {
    /// True when `s` assigns a value that calls FR() or FRSTAR() and the model is a tree whose
    /// `M` may wait; the statement is then kept, unrun, for [`Interpreter::settle`].
    pub(super) fn defers(&mut self, s: &Stmt) -> IResult<bool> {
        let StmtKind::Assign { target, op: AssignOp::Set, value } = &s.kind else { return Ok(false) };
        if !self.defer
            || target.primes > 0
            || target.suffix > 0
            || target.index.is_some()
            || !calls_forces(value)
        {
            return Ok(false);
        }
        self.prepare(&s.span)?;
        let shape = self.model.kane_unformed().at(&s.span)?;
        if !self.model.defers_mass_matrix(&shape) {
            return Ok(false);
        }
        self.bindings.remove(&target.name.to_ascii_uppercase());
        self.deferred.push(s.clone());
        Ok(true)
    }

    /// Runs the deferred statements and forms `M` and `f`, unless `next` (the statement about
    /// to run) can neither change nor read what they depend on.
    pub(super) fn settle_before(&mut self, next: &Stmt) {
        let pending_kane = self.equations.as_ref().is_some_and(|e| !e.formed);
        if (self.deferred.is_empty() && !pending_kane) || self.inert(next) {
            return;
        }
        for s in std::mem::take(&mut self.deferred) {
            if let Err(d) = self.statement(&s) {
                self.errors.push(d);
            }
        }
        if let Some(span) = self.deferred_kane.take() {
            if let Some(mut eqs) = self.equations.take() {
                match self.model.form_equations(&mut eqs).at(&span) {
                    Ok(()) => self.equations = Some(eqs),
                    Err(d) => self.errors.push(d),
                }
            }
        }
    }

    /// True for statements that change nothing the deferred work reads and read none of it.
    fn inert(&self, s: &Stmt) -> bool {
        match &s.kind {
            StmtKind::Input(_)
            | StmtKind::Units(_)
            | StmtKind::UnitSystem(_)
            | StmtKind::Session(_)
            | StmtKind::Code { .. } => true,
            StmtKind::Output(items) | StmtKind::Encode(items) => {
                !items.iter().any(|i| i.expr.is_some() || self.is_deferred(&i.name))
            }
            StmtKind::Expr(e) => {
                matches!(&e.kind, ExprKind::Call { name, args } if name.eq_ignore_ascii_case("KANE") && args.is_empty())
            }
            _ => false,
        }
    }

    fn is_deferred(&self, name: &str) -> bool {
        let bare = name.trim_end_matches('>');
        self.deferred.iter().any(|s| match &s.kind {
            StmtKind::Assign { target, .. } => target.name.eq_ignore_ascii_case(bare),
            _ => false,
        })
    }
}

/// True when `e` calls FR() or FRSTAR().
fn calls_forces(e: &Expr) -> bool {
    e.any(&|x| {
        matches!(&x.kind, ExprKind::Call { name, .. } if name.eq_ignore_ascii_case("FR") || name.eq_ignore_ascii_case("FRSTAR"))
    })
}
