//! Errors of the expression engine.

use thiserror::Error;

/// What went wrong in building, transforming or evaluating an expression.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum ExprError {
    /// An exact division by zero, such as `x/0` or `0^-1`.
    #[error("division by exact zero")]
    DivisionByZero,
    /// An exact rational result does not fit in 128-bit numerator and denominator.
    #[error("rational overflow: the exact result does not fit in 128 bits; use a float literal instead")]
    RationalOverflow,
    /// A floating literal that is NaN or infinite.
    #[error("non-finite floating literal {0}")]
    NonFiniteLiteral(f64),
    /// Evaluation met a symbol that has no value.
    #[error("no value bound for symbol `{0}`")]
    MissingBinding(String),
    /// Evaluation produced NaN or infinity.
    #[error("evaluation is not finite ({value}) for `{expr}`")]
    NotFinite {
        /// The expression, printed.
        expr: String,
        /// The value produced.
        value: f64,
    },
    /// An expression asked to be linear in some symbols is not.
    #[error("{expr} is not linear in `{symbol}`")]
    NotLinear {
        /// The expression, printed in backquotes (or described, when large).
        expr: String,
        /// The symbol it is not linear in.
        symbol: String,
    },
    /// An expression asked for a coefficient of a power of a symbol is not a polynomial in it.
    #[error(
        "{expr} is not a polynomial in `{symbol}` (it appears inside a function or with a non-integer power)"
    )]
    NotPolynomial {
        /// The expression, printed in backquotes (or described, when large).
        expr: String,
        /// The symbol.
        symbol: String,
    },
    /// A linear system has no unique solution (a zero pivot).
    #[error("the linear system has no unique solution (singular coefficient matrix)")]
    SingularSystem,
    /// A linear system with more or fewer equations than unknowns.
    #[error("{equations} equations for {unknowns} unknowns: a linear system needs one equation per unknown")]
    NotSquare {
        /// The number of equations.
        equations: usize,
        /// The number of unknowns.
        unknowns: usize,
    },
    /// An expansion would produce too many terms.
    #[error("expanding this expression would give {0} terms or more; expand a smaller expression")]
    TooLarge(usize),
    /// A symbol name declared twice with different kinds.
    #[error("symbol `{0}` is already declared with another kind")]
    SymbolKindClash(String),
    /// A symbol that is not a time-dependent variable was asked for its derivative.
    #[error("symbol `{0}` does not depend on time, so it has no derivative symbol")]
    NotTimeDependent(String),
}
