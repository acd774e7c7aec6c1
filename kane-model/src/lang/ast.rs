//! The syntax tree of an Autolev program; every node keeps its source span.

use super::token::Span;

/// An expression with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it is.
    pub span: Span,
}

impl Expr {
    /// True when `found` holds for this expression or any expression inside it.
    pub fn any(&self, found: &impl Fn(&Expr) -> bool) -> bool {
        if found(self) {
            return true;
        }
        match &self.kind {
            ExprKind::Number { .. } | ExprKind::Name { .. } => false,
            ExprKind::Call { args, .. } | ExprKind::Index { args, .. } => args.iter().any(|a| a.any(found)),
            ExprKind::Matrix(rows) => rows.iter().flatten().any(|a| a.any(found)),
            ExprKind::Neg(a) => a.any(found),
            ExprKind::Binary(_, a, b) | ExprKind::Range(a, b) | ExprKind::NamedArg(a, b) => {
                a.any(found) || b.any(found)
            }
        }
    }
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `^`
    Pow,
}

/// Expression kinds.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A number as written, with trailing `>` count (`0>` is the zero vector, `1>>` the unit dyadic).
    Number {
        /// The literal's value.
        value: f64,
        /// Number of `>`.
        suffix: u8,
    },
    /// A name with primes (time derivatives) and `>` count.
    Name {
        /// The name as written.
        name: String,
        /// Number of `'`.
        primes: u8,
        /// Number of `>`.
        suffix: u8,
    },
    /// `NAME(args)`.
    Call {
        /// Function name as written.
        name: String,
        /// The call's arguments, in order.
        args: Vec<Expr>,
    },
    /// `NAME[i, j]`, possibly with primes inside (`DEPENDENT[Q1']`).
    Index {
        /// Array name.
        name: String,
        /// The index expressions, in order.
        args: Vec<Expr>,
    },
    /// `[a, b; c, d]`.
    Matrix(Vec<Vec<Expr>>),
    /// `-x`.
    Neg(Box<Expr>),
    /// `a op b`.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `a:b` in arguments.
    Range(Box<Expr>, Box<Expr>),
    /// `X = value` in arguments (`Q1' = 0`, `SIN(X) = S`): what is replaced, and by what.
    NamedArg(Box<Expr>, Box<Expr>),
}

/// Kinds of declaration statements.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeclKind {
    /// NEWTONIAN
    Newtonian,
    /// FRAMES
    Frames,
    /// BODIES
    Bodies,
    /// PARTICLES
    Particles,
    /// POINTS
    Points,
    /// CONSTANTS
    Constants,
    /// VARIABLES
    Variables,
    /// MOTIONVARIABLES
    MotionVariables,
    /// SPECIFIED
    Specified,
    /// IMAGINARY
    Imaginary,
}

/// One declared name: `Q{3}'`, `S2+`, `F = 3`, `P{1:2,1:3}`.
#[derive(Clone, Debug, PartialEq)]
pub struct DeclItem {
    /// The base name.
    pub name: String,
    /// Index ranges `{lo:hi, ...}`, expanded into names by the interpreter.
    pub ranges: Vec<(i64, i64)>,
    /// What follows the ranges in each name (`O` in `RRF{2}O`: RRF1O, RRF2O).
    pub tail: String,
    /// Derivative order declared with `'`.
    pub primes: u8,
    /// Sign suffix `+` or `-`.
    pub sign: Option<char>,
    /// Value given with `=`.
    pub value: Option<Expr>,
    /// Where the declared name is in the file.
    pub span: Span,
}

/// Assignment operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AssignOp {
    /// `=`
    Set,
    /// `+=`
    Add,
    /// `:=`
    Define,
}

/// The target of an assignment.
#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    /// Name as written.
    pub name: String,
    /// Primes (`Q1' = U1`).
    pub primes: u8,
    /// `>` count.
    pub suffix: u8,
    /// Indices (`EQN[1] = ...`).
    pub index: Option<Vec<Expr>>,
    /// Where the target is in the file.
    pub span: Span,
}

/// A statement.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// A declaration.
    Declare {
        /// Which kind of name is declared.
        kind: DeclKind,
        /// The names.
        items: Vec<DeclItem>,
    },
    /// `MASS B = M1, C = M2`.
    Mass(Vec<(String, Span, Expr)>),
    /// `INERTIA B, I11, I22, I33 [, I12, I23, I31]`, `INERTIA B(A), ...` (measure numbers in
    /// frame A) or `INERTIA B_P(A), ...` (the inertia about point P).
    Inertia {
        /// Body name (`B`, or `B_P`).
        body: String,
        /// Its span.
        body_span: Span,
        /// The frame named in parentheses, with its span.
        frame: Option<(String, Span)>,
        /// The moments.
        args: Vec<Expr>,
    },
    /// `DEGREES OFF`, `COMPLEX ON`, ...
    Setting {
        /// Setting name.
        name: String,
        /// ON or OFF.
        on: bool,
    },
    /// `UNITSYSTEM KG, METER, SEC`: upper-cased unit words and where each is.
    UnitSystem(Vec<(String, Span)>),
    /// A command of Autolev's session (`AUTOZ ON`, `ENCODE ZERO`, `SAVE F.ALL`, `PAUSE`),
    /// upper-cased; its arguments are not kept.
    Session(String),
    /// `UNITS a = unit, ...`.
    Units(Vec<UnitsItem>),
    /// `INPUT a = value [unit], ...`.
    Input(Vec<InputItem>),
    /// `OUTPUT a [unit], ...`.
    Output(Vec<OutputItem>),
    /// `ENCODE a, ...`: quantities for generated code to compute, as OUTPUT's but not printed.
    Encode(Vec<OutputItem>),
    /// `CODE KIND(args) file`.
    Code {
        /// DYNAMICS, ALGEBRAIC, NONLINEAR, ODE.
        kind: String,
        /// The arguments.
        args: Vec<Expr>,
        /// The rest of the line (file name).
        file: String,
    },
    /// `RUN FILE.AL`: another model file's statements, run here.
    Run(String),
    /// An assignment.
    Assign {
        /// The target.
        target: Target,
        /// `=`, `+=`, `:=`.
        op: AssignOp,
        /// The value.
        value: Expr,
    },
    /// A bare expression or command (`KANE()`, `SIMPROT(A,B,1,Q)`, `EXPAND(E)`).
    Expr(Expr),
}

/// A UNITS entry: one name and its unit (`[A, B] = M` gives one entry each).
#[derive(Clone, Debug, PartialEq)]
pub struct UnitsItem {
    /// The name, with its primes.
    pub name: String,
    /// The unit's text, upper-cased, `.` as `*` (`KG*M^2/S`).
    pub unit: String,
    /// Where the unit is written.
    pub span: Span,
    /// The unit's words as written, each with where it is.
    pub words: Vec<(String, Span)>,
}

/// An OUTPUT entry: a name (`Q1`, `U1'`, `L>`) or an expression (`KE + PE`, `ZERO[1]`).
#[derive(Clone, Debug, PartialEq)]
pub struct OutputItem {
    /// The name, or the expression's text without spaces.
    pub name: String,
    /// Where the item is in the file.
    pub span: Span,
    /// The unit tag after it, if any.
    pub unit: Option<String>,
    /// The expression, for an item that is not a plain name.
    pub expr: Option<Expr>,
}

/// An INPUT entry.
#[derive(Clone, Debug, PartialEq)]
pub struct InputItem {
    /// Name as written.
    pub name: String,
    /// How many primes follow the name (time derivatives).
    pub primes: u8,
    /// The value given (an expression).
    pub value: Expr,
    /// Unit word after the value (`DEG`), if any.
    pub unit: Option<String>,
    /// Where the item is in the file.
    pub span: Span,
}

/// A statement with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    /// What it is.
    pub kind: StmtKind,
    /// Where the command is in the file.
    pub span: Span,
}

/// `Q` with ranges `[(1,3)]` -> `Q1, Q2, Q3`; `P` with `[(1,2),(1,3)]` -> `P11, P12, ..., P23`.
pub(crate) fn expand_ranges(name: &str, ranges: &[(i64, i64)]) -> Vec<String> {
    let mut out = vec![name.to_string()];
    for &(lo, hi) in ranges {
        out = out.iter().flat_map(|p| (lo..=hi).map(move |i| format!("{p}{i}"))).collect();
    }
    out
}
