//! Output quantities: kinetic and potential energy, angular momentum.
//!
//! In: a model's masses (through [`Model::masses`]), its kinematics, and for the potential a
//! gravity vector and a datum point. Out: scalar expressions and vectors.

use crate::expr::ExprId;

use super::error::Result;
use super::ids::{FrameId, PointId};
use super::model::Model;
use super::vector::Vector;

impl Model {
    /// Kinetic energy in the Newtonian frame, `sum(m v.v / 2 + w.I.w / 2)`.
    pub fn kinetic_energy(&mut self) -> Result<ExprId> {
        let masses: Vec<_> = self.masses().collect();
        self.kinetic_energy_of(&masses)
    }

    /// Kinetic energy in the Newtonian frame of the masses `masses`.
    pub fn kinetic_energy_of(&mut self, masses: &[super::MassView]) -> Result<ExprId> {
        let n = self.newtonian;
        let mut terms = Vec::new();
        for view in masses {
            let m = view.mass()?;
            let v = self.velocity(view.point, n)?;
            let vv = self.dot(&v, &v)?;
            terms.push(self.ar.mul(&[m, vv])?);
            if let (Some(frame), Some(inertia)) = (view.frame, &view.inertia) {
                let w = self.angular_velocity(frame, n)?;
                let iw = self.dyadic_dot(inertia, &w)?;
                terms.push(self.dot(&w, &iw)?);
            }
        }
        let sum = self.ar.add(&terms)?;
        let half = self.ar.rational(1, 2)?;
        Ok(self.ar.mul(&[half, sum])?)
    }

    /// Potential energy of uniform gravity `g`, zero at `origin`: `-sum(m g . r)`.
    pub fn gravity_potential(&mut self, g: &Vector, origin: PointId) -> Result<ExprId> {
        let weighed = self.masses().map(|view| Ok((view.mass()?, view.point))).collect::<Result<Vec<_>>>()?;
        let mut terms = Vec::new();
        for (m, point) in weighed {
            let r = self.position(point, origin)?;
            let gr = self.dot(g, &r)?;
            terms.push(self.ar.mul(&[m, gr])?);
        }
        let sum = self.ar.add(&terms)?;
        Ok(self.ar.neg(sum)?)
    }

    /// Angular momentum about `about` in `frame`: `sum(r x m v + I . w)`.
    pub fn angular_momentum(&mut self, about: PointId, frame: FrameId) -> Result<Vector> {
        let masses: Vec<_> = self.masses().collect();
        self.angular_momentum_of(&masses, about, frame)
    }

    /// The angular momentum about `about`, in `frame`, of the masses `masses`.
    pub fn angular_momentum_of(
        &mut self,
        masses: &[super::MassView],
        about: PointId,
        frame: FrameId,
    ) -> Result<Vector> {
        let mut h = Vector::zero();
        for view in masses {
            let m = view.mass()?;
            let r = self.position(view.point, about)?;
            let v = self.velocity(view.point, frame)?;
            let mv = self.scale(&v, m)?;
            let rmv = self.cross(&r, &mv)?;
            h = self.add_vectors(&h, &rmv)?;
            if let (Some(body_frame), Some(inertia)) = (view.frame, &view.inertia) {
                let w = self.angular_velocity(body_frame, frame)?;
                let iw = self.dyadic_dot(inertia, &w)?;
                h = self.add_vectors(&h, &iw)?;
            }
        }
        Ok(h)
    }
}
