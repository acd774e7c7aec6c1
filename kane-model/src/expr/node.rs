//! Node kinds of the expression DAG and the ids that refer to them.

use std::fmt;

use super::number::Rational;

/// A handle to an interned expression; equal ids mean structurally equal expressions.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ExprId(pub(crate) u32);

impl ExprId {
    /// Position in the arena; children always have smaller indices than parents.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl fmt::Debug for ExprId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "e{}", self.0)
    }
}

/// A handle to a declared symbol.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct SymbolId(pub(crate) u32);

impl SymbolId {
    /// Position in the symbol table.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What a symbol stands for.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum SymbolKind {
    /// A constant parameter.
    Constant,
    /// Time, `t`.
    Time,
    /// A time-dependent variable (coordinate or speed) differentiated `order` times.
    Variable {
        /// Order of the time derivative (0 for the variable itself).
        order: u32,
    },
    /// A specified function of time differentiated `order` times.
    Specified {
        /// Order of the time derivative.
        order: u32,
    },
}

impl SymbolKind {
    /// True for variables and specified functions, whose time derivative is not zero.
    pub fn depends_on_time(self) -> bool {
        !matches!(self, SymbolKind::Constant)
    }
}

/// A one-argument elementary function.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Func {
    /// The sine, `sin(x)`.
    Sin,
    /// The cosine, `cos(x)`.
    Cos,
    /// The tangent, `tan(x)`.
    Tan,
    /// Arc sine.
    Asin,
    /// Arc cosine.
    Acos,
    /// Arc tangent.
    Atan,
    /// Natural exponential.
    Exp,
    /// Natural logarithm.
    Ln,
    /// Absolute value.
    Abs,
    /// Sign (-1, 0 or 1).
    Sign,
    /// Hyperbolic sine.
    Sinh,
    /// Hyperbolic cosine.
    Cosh,
    /// Hyperbolic tangent.
    Tanh,
}

impl Func {
    /// All functions, in declaration order.
    pub const ALL: [Func; 13] = [
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Asin,
        Func::Acos,
        Func::Atan,
        Func::Exp,
        Func::Ln,
        Func::Abs,
        Func::Sign,
        Func::Sinh,
        Func::Cosh,
        Func::Tanh,
    ];

    /// Lower-case name as written in model files.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "asin",
            Func::Acos => "acos",
            Func::Atan => "atan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Abs => "abs",
            Func::Sign => "sign",
            Func::Sinh => "sinh",
            Func::Cosh => "cosh",
            Func::Tanh => "tanh",
        }
    }

    /// The function named `name` (case-insensitive).
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.into_iter().find(|f| f.name().eq_ignore_ascii_case(name))
    }

    /// Symmetry under negation of the argument.
    pub(crate) fn parity(self) -> Parity {
        match self {
            Func::Sin | Func::Tan | Func::Asin | Func::Atan | Func::Sign | Func::Sinh | Func::Tanh => {
                Parity::Odd
            }
            Func::Cos | Func::Cosh | Func::Abs => Parity::Even,
            Func::Acos | Func::Exp | Func::Ln => Parity::None,
        }
    }

    /// Numeric value at `x`, generic over the float type.
    pub fn apply<T: num_traits::Float>(self, x: T) -> T {
        match self {
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Asin => x.asin(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Abs => x.abs(),
            Func::Sign => crate::runtime::sign(x),
            Func::Sinh => x.sinh(),
            Func::Cosh => x.cosh(),
            Func::Tanh => x.tanh(),
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Parity {
    Odd,
    Even,
    None,
}

/// One node of the expression DAG, in canonical form.
///
/// Invariants kept by the constructors: a `Sum` holds at least two terms, none of them a
/// `Sum`, at most one number (first), like terms collected; a `Product` holds at least two
/// factors, none a `Product`, at most one number (first, never 0 or 1), one factor per base.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// Exact rational.
    Rational(Rational),
    /// Finite floating literal, stored by its bits (never -0.0).
    Float(u64),
    /// A symbol.
    Symbol(SymbolId),
    /// n-ary sum.
    Sum(Box<[ExprId]>),
    /// n-ary product.
    Product(Box<[ExprId]>),
    /// `[base, exponent]`; square roots are powers with exponent 1/2.
    Pow([ExprId; 2]),
    /// An elementary function applied to one argument.
    Func(Func, ExprId),
    /// Two-argument arc tangent `[y, x]`.
    Atan2([ExprId; 2]),
}

impl Node {
    /// Child ids, in order.
    pub fn children(&self) -> &[ExprId] {
        match self {
            Node::Rational(_) | Node::Float(_) | Node::Symbol(_) => &[],
            Node::Sum(c) | Node::Product(c) => c,
            Node::Pow(pair) | Node::Atan2(pair) => pair,
            Node::Func(_, a) => std::slice::from_ref(a),
        }
    }
}
