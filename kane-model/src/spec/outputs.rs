//! The typed outputs of a spec: in come mechanics quantities (scalars, vectors, frames,
//! energies, momenta); out go [`OutputSpec`]s, each a few scalar components with column names.

use crate::expr::ExprId;
use crate::mechanics::{FrameId, PointId, Result, Vector};

use super::ModelSpec;

impl OutputKind {
    /// Whether the output is a quaternion computed from direction cosines.
    pub fn is_quaternion(&self) -> bool {
        matches!(self, OutputKind::Orientation { form: OrientationForm::Quaternion, .. })
    }
}

/// How an orientation is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrientationForm {
    /// The nine direction cosines `N_i . F_j`, row by row.
    Dcm,
    /// A unit quaternion (scalar first, frame to Newtonian), from the direction cosines at run
    /// time with a non-negative scalar part.
    Quaternion,
}

/// What an output is.
#[derive(Clone, Debug, PartialEq)]
pub enum OutputKind {
    /// One scalar expression.
    Scalar,
    /// A vector's measure numbers in `frame`.
    Vector {
        /// The frame's name.
        frame: String,
    },
    /// The orientation of `frame` in the Newtonian frame.
    Orientation {
        /// The frame's name.
        frame: String,
        /// DCM or quaternion.
        form: OrientationForm,
    },
    /// The kinetic energy in the Newtonian frame.
    KineticEnergy,
    /// The potential energy of uniform gravity.
    PotentialEnergy,
    /// The residuals of the configuration constraints (zero on the constraint manifold), with
    /// the coordinates they determine.
    ConfigurationResiduals {
        /// The dependent coordinates' names, one per residual.
        dependent: Vec<String>,
    },
    /// The residuals of the motion constraints with the dependent speeds solved from them
    /// (zero up to rounding: a check of the solve).
    MotionResiduals,
    /// The motion constraints' matrix of the dependent speeds, `A_d`, row by row (checked for
    /// rank loss where an integration fails).
    ConstraintMatrix {
        /// The number of dependent speeds (rows and columns).
        size: usize,
    },
    /// A model's default drawing: every frame's direction cosines and every point's position,
    /// in one output (so that they share their subexpressions), under these column names.
    Drawing {
        /// The column names, one per component.
        columns: Vec<String>,
    },
    /// The angular momentum about `point` in the Newtonian frame, measured in `frame`.
    AngularMomentum {
        /// The point's name.
        point: String,
        /// The frame of the measure numbers.
        frame: String,
    },
}

/// One output: its name, unit, kind and scalar components (in the states, parameters, time and
/// the speed rates `u'`).
#[derive(Clone, Debug, PartialEq)]
pub struct OutputSpec {
    /// The name (as written in the model).
    pub name: String,
    /// The unit (empty when none).
    pub unit: String,
    /// What it is.
    pub kind: OutputKind,
    /// The expressions computed.
    pub components: Vec<ExprId>,
}

impl OutputSpec {
    /// The column names it writes: the name for one value, `NAME_suffix` for several.
    pub fn columns(&self) -> Vec<String> {
        let suffixes: Vec<String> = match &self.kind {
            OutputKind::Vector { frame } | OutputKind::AngularMomentum { frame, .. } => {
                (1..=3).map(|i| format!("{frame}{i}")).collect()
            }
            OutputKind::Orientation { form: OrientationForm::Dcm, .. } => {
                (1..=3).flat_map(|i| (1..=3).map(move |j| format!("{i}{j}"))).collect()
            }
            OutputKind::Orientation { form: OrientationForm::Quaternion, .. } => {
                (0..4).map(|i| format!("E{i}")).collect()
            }
            OutputKind::ConfigurationResiduals { .. } | OutputKind::MotionResiduals => {
                (1..=self.components.len()).map(|i| i.to_string()).collect()
            }
            OutputKind::Drawing { columns } => return columns.clone(),
            OutputKind::ConstraintMatrix { size } => {
                (1..=*size).flat_map(|i| (1..=*size).map(move |j| format!("{i}{j}"))).collect()
            }
            _ => return vec![self.name.clone()],
        };
        suffixes.into_iter().map(|s| format!("{}_{s}", self.name)).collect()
    }
}

impl ModelSpec {
    /// Adds a scalar output.
    pub fn add_scalar(&mut self, name: &str, e: ExprId, unit: &str) {
        self.push(name, unit, OutputKind::Scalar, vec![e]);
    }

    /// Adds the residuals of the model's configuration constraints as the output `name` (one
    /// column each), when it has any.
    pub fn add_configuration_residuals(&mut self, name: &str, unit: &str) -> Result<()> {
        let dependent = self.model.dependent_coordinates()?;
        if dependent.is_empty() {
            return Ok(());
        }
        let dependent = dependent.iter().map(|q| self.symbol_name(*q).to_string()).collect();
        let residuals = self.model.configuration_residuals().to_vec();
        self.push(name, unit, OutputKind::ConfigurationResiduals { dependent }, residuals);
        Ok(())
    }

    /// Adds the residuals of the model's motion constraints as the output `name`, when it has
    /// any.
    pub fn add_motion_residuals(&mut self, name: &str, unit: &str) {
        let residuals = self.model.motion_residuals().to_vec();
        if !residuals.is_empty() {
            self.push(name, unit, OutputKind::MotionResiduals, residuals);
        }
    }

    /// Adds the matrix of the dependent speeds in the motion constraints as the output `name`,
    /// when the equations have constraints.
    pub fn add_constraint_matrix(&mut self, name: &str) {
        let Some(c) = &self.equations.constraints else { return };
        let size = c.dependent.len();
        let entries = c.a_dependent.iter().flatten().copied().collect();
        self.push(name, "", OutputKind::ConstraintMatrix { size }, entries);
    }

    /// Adds a vector output measured in `frame`.
    pub fn add_vector(&mut self, name: &str, v: &Vector, frame: FrameId, unit: &str) -> Result<()> {
        let m = self.model.express(v, frame)?;
        let components = self.all_in_states(&m)?;
        let frame = self.model.frame_name(frame).to_string();
        self.push(name, unit, OutputKind::Vector { frame }, components);
        Ok(())
    }

    /// Adds the orientation of `frame` in the Newtonian frame.
    pub fn add_orientation(&mut self, name: &str, frame: FrameId, form: OrientationForm) -> Result<()> {
        let n = self.model.newtonian();
        let dcm = self.model.dcm(n, frame)?;
        let components: Vec<ExprId> = dcm.iter().flatten().copied().collect();
        let frame = self.model.frame_name(frame).to_string();
        self.push(name, "", OutputKind::Orientation { frame, form }, components);
        Ok(())
    }

    /// Adds the kinetic energy.
    pub fn add_kinetic_energy(&mut self, name: &str, unit: &str) -> Result<()> {
        let ke = self.model.kinetic_energy()?;
        let ke = self.in_states(ke)?;
        self.push(name, unit, OutputKind::KineticEnergy, vec![ke]);
        Ok(())
    }

    /// Adds the potential energy of uniform gravity `g`, zero at `origin`.
    pub fn add_potential_energy(
        &mut self,
        name: &str,
        g: &Vector,
        origin: PointId,
        unit: &str,
    ) -> Result<()> {
        let pe = self.model.gravity_potential(g, origin)?;
        self.push(name, unit, OutputKind::PotentialEnergy, vec![pe]);
        Ok(())
    }

    /// Adds the angular momentum about `point` (Newtonian frame), measured in `frame`.
    pub fn add_angular_momentum(
        &mut self,
        name: &str,
        point: PointId,
        frame: FrameId,
        unit: &str,
    ) -> Result<()> {
        let n = self.model.newtonian();
        let h = self.model.angular_momentum(point, n)?;
        let m = self.model.express(&h, frame)?;
        let components = self.all_in_states(&m)?;
        let kind = OutputKind::AngularMomentum {
            point: self.model.point_name(point).to_string(),
            frame: self.model.frame_name(frame).to_string(),
        };
        self.push(name, unit, kind, components);
        Ok(())
    }

    fn all_in_states(&mut self, es: &[ExprId]) -> Result<Vec<ExprId>> {
        es.iter().map(|e| self.in_states(*e)).collect()
    }

    pub(super) fn push(&mut self, name: &str, unit: &str, kind: OutputKind, components: Vec<ExprId>) {
        self.outputs.push(OutputSpec { name: name.to_string(), unit: unit.to_string(), kind, components });
    }
}
