//! Output quantities: kinetic and potential energy, angular momentum.

use crate::expr::ExprId;

use super::error::{MechanicsError, Result};
use super::model::{FrameId, Model, PointId};
use super::vector::Vector;

impl Model {
    /// Kinetic energy in the Newtonian frame, `sum(m v.v / 2 + w.I.w / 2)`.
    pub fn kinetic_energy(&mut self) -> Result<ExprId> {
        let n = self.newtonian;
        let mut terms = Vec::new();
        for b in self.bodies.clone() {
            let m = b.mass.ok_or_else(|| MechanicsError::MissingMass(b.name.clone()))?;
            let v = self.velocity(b.mass_center, n)?;
            let vv = self.dot(&v, &v)?;
            terms.push(self.ar.mul(&[m, vv])?);
            if let Some(inertia) = &b.inertia {
                let w = self.angular_velocity(b.frame, n)?;
                let iw = self.dyadic_dot(inertia, &w)?;
                terms.push(self.dot(&w, &iw)?);
            }
        }
        for p in self.particles.clone() {
            let m = p.mass.ok_or_else(|| MechanicsError::MissingMass(p.name.clone()))?;
            let v = self.velocity(p.point, n)?;
            let vv = self.dot(&v, &v)?;
            terms.push(self.ar.mul(&[m, vv])?);
        }
        let sum = self.ar.add(&terms)?;
        let half = self.ar.rational(1, 2)?;
        Ok(self.ar.mul(&[half, sum])?)
    }

    /// Potential energy of uniform gravity `g`, zero at `origin`: `-sum(m g . r)`.
    pub fn gravity_potential(&mut self, g: &Vector, origin: PointId) -> Result<ExprId> {
        let mut terms = Vec::new();
        for (m, point) in self.masses()? {
            let r = self.position(point, origin)?;
            let gr = self.dot(g, &r)?;
            terms.push(self.ar.mul(&[m, gr])?);
        }
        let sum = self.ar.add(&terms)?;
        Ok(self.ar.neg(sum)?)
    }

    /// Angular momentum about `about` in `frame`: `sum(r x m v + I . w)`.
    pub fn angular_momentum(&mut self, about: PointId, frame: FrameId) -> Result<Vector> {
        let mut h = Vector::zero();
        for b in self.bodies.clone() {
            let m = b.mass.ok_or_else(|| MechanicsError::MissingMass(b.name.clone()))?;
            let r = self.position(b.mass_center, about)?;
            let v = self.velocity(b.mass_center, frame)?;
            let mv = self.scale(&v, m)?;
            let rmv = self.cross(&r, &mv)?;
            h = self.add_vectors(&h, &rmv)?;
            if let Some(inertia) = &b.inertia {
                let w = self.angular_velocity(b.frame, frame)?;
                let iw = self.dyadic_dot(inertia, &w)?;
                h = self.add_vectors(&h, &iw)?;
            }
        }
        for p in self.particles.clone() {
            let m = p.mass.ok_or_else(|| MechanicsError::MissingMass(p.name.clone()))?;
            let r = self.position(p.point, about)?;
            let v = self.velocity(p.point, frame)?;
            let mv = self.scale(&v, m)?;
            let rmv = self.cross(&r, &mv)?;
            h = self.add_vectors(&h, &rmv)?;
        }
        Ok(h)
    }
}
