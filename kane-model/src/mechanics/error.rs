//! Errors of the mechanics layer: each names the entity at fault and why.

use thiserror::Error;

use crate::expr::ExprError;

/// What went wrong while building a model or deriving its equations.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum MechanicsError {
    /// An expression operation failed.
    #[error(transparent)]
    Expr(#[from] ExprError),
    /// A name is used twice for frames, points or bodies.
    #[error("`{0}` is already defined")]
    Duplicate(String),
    /// An angular velocity assigned to a frame oriented through a chain does not determine
    /// its coordinates' rates.
    #[error(
        "W_{frame}_{reference}> given in speeds determines the rates of three coordinates of \
         {frame}'s orientation, but {found} of them are without a kinematic equation ({names})"
    )]
    AngularVelocityUnderdetermined {
        /// The frame.
        frame: String,
        /// The frame it turns in.
        reference: String,
        /// How many coordinate rates without kinematic equations appear.
        found: usize,
        /// Their names.
        names: String,
    },
    /// The speed rates of a model whose equations solve for loads too are not formed as
    /// expressions.
    #[error("the speed rates of a model that solves for loads with them (KANE(T1, ...)) are solved numerically only")]
    RatesWithLoads,
    /// Orienting a frame would close a loop of orientations.
    #[error("orienting {frame} relative to {parent} closes a loop: the two are already related through other frames")]
    OrientationCycle {
        /// The frame.
        frame: String,
        /// The proposed parent.
        parent: String,
    },
    /// Two frames are not connected by orientations.
    #[error(
        "no orientation path between frames {a} and {b}: orient {b} (or {a}) relative to a connected frame"
    )]
    NoOrientationPath {
        /// One frame.
        a: String,
        /// The other.
        b: String,
    },
    /// A point's velocity cannot be found in a frame.
    #[error("velocity of point {point} has not been defined in frame {frame}: give its position from a point whose velocity is known, or set the velocity")]
    VelocityUndefined {
        /// The point.
        point: String,
        /// The frame.
        frame: String,
    },
    /// Positions of points form a loop.
    #[error("point {0} is located relative to itself through a chain of positions")]
    PositionCycle(String),
    /// A point has no position chain to another point.
    #[error("no position path between points {a} and {b}")]
    NoPositionPath {
        /// One point.
        a: String,
        /// The other.
        b: String,
    },
    /// A body or particle has no mass.
    #[error("{0} has no mass: give it one (MASS {0} = ...)")]
    MissingMass(String),
    /// A coordinate has no kinematic differential equation.
    #[error("coordinate {0} has no kinematic differential equation ({0}' = ...)")]
    MissingKinematics(String),
    /// A symbol used as a generalized coordinate or speed is not a time-dependent variable.
    #[error("{0} is not a time-dependent variable, so it cannot be a generalized coordinate or speed")]
    NotAVariable(String),
    /// No generalized speeds were declared.
    #[error("no generalized speeds: declare at least one")]
    NoSpeeds,
    /// Kane's equations are not linear in the speed derivatives.
    #[error("equation {0} is not linear in the derivatives of the generalized speeds")]
    NotLinearInAccelerations(usize),
    /// The mass matrix is singular at the point asked for.
    #[error("the mass matrix is singular at this point")]
    SingularMassMatrix,
    /// A constraint matrix cannot be solved for the dependent speeds.
    #[error("the constraints cannot be solved for the dependent speeds (singular coefficient matrix)")]
    SingularConstraints,
    /// The configuration constraints do not name as many dependent coordinates as there are
    /// constraints.
    #[error(
        "{constraints} configuration constraints (CONFIG[...]) but {found} dependent coordinates ({names}): \
         a configuration constraint needs a coordinate whose rate is a dependent speed (Q' = U with U in \
         CONSTRAIN(DEPENDENT[...])) and that the constraint reads"
    )]
    ConfigurationUnderdetermined {
        /// How many configuration constraints.
        constraints: usize,
        /// How many dependent coordinates they read.
        found: usize,
        /// Their names.
        names: String,
    },
    /// An auxiliary speed that is not one of the model's speeds.
    #[error("`{0}` is not a generalized speed of the model, so it cannot be auxiliary")]
    NotASpeed(String),
    /// KANE's arguments and the auxiliary speeds differ in number.
    #[error("KANE solves for {loads} loads but the model has {auxiliary} auxiliary speeds: their equations determine one load each, so name as many loads in KANE(...) as there are speeds in CONSTRAIN(AUXILIARY[...])")]
    AuxiliaryCount {
        /// Auxiliary speeds.
        auxiliary: usize,
        /// Loads named in KANE.
        loads: usize,
    },
    /// A load KANE solves for also has a formula.
    #[error("{0} is solved for by KANE({0}, ...) and also given a formula: remove one of them")]
    LoadHasFormula(String),
    /// A load solved for enters an equation nonlinearly.
    #[error("the load {0} enters equation {1} nonlinearly, so KANE cannot solve for it")]
    LoadNotLinear(String, usize),
    /// The constraints' matrix of dependent speeds is (nearly) singular at the point asked for.
    #[error(
        "the constraints lose rank at {at}: their matrix of dependent speeds has reciprocal condition \
         number {rcond:e}, so the dependent speeds are not determined there; choose other dependent \
         speeds, or a configuration away from this one"
    )]
    ConstraintRankLoss {
        /// `A_d`'s smallest over largest singular value.
        rcond: f64,
        /// The coordinates' values.
        at: String,
    },
}

/// Result of the mechanics layer.
pub type Result<T> = std::result::Result<T, MechanicsError>;
