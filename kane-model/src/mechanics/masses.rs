//! One view over every mass of a model, bodies and particles alike, and what sums over masses:
//! total mass (Autolev's MASS()), centre of mass (CM()), linear momentum (MOMENTUM(LINEAR)) and
//! uniform gravity applied once to each mass (GRAVITY).
//!
//! In: the model's bodies and particles, or a chosen few of them as [`MassView`]s. Out: mass
//! views, and the scalars, vectors and loads built from them.

use crate::expr::ExprId;

use super::error::{MechanicsError, Result};
use super::ids::{BodyId, FrameId, ParticleId, PointId};
use super::model::Model;
use super::vector::{Dyadic, Vector};

/// Which body or particle a [`MassView`] shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MassId {
    /// A rigid body.
    Body(BodyId),
    /// A particle.
    Particle(ParticleId),
}

/// One mass of a model: a rigid body or a particle, seen the same way.
#[derive(Clone, Debug, PartialEq)]
pub struct MassView {
    /// The body or particle.
    pub id: MassId,
    /// Its name.
    pub name: String,
    /// Its mass, once given.
    pub mass: Option<ExprId>,
    /// The mass centre (a particle's own point).
    pub point: PointId,
    /// The frame fixed in a body; `None` for a particle.
    pub frame: Option<FrameId>,
    /// A body's inertia dyadic about its mass centre, once given; `None` for a particle.
    pub inertia: Option<Dyadic>,
}

impl MassView {
    /// The mass, or [`MechanicsError::MissingMass`] naming the body or particle.
    pub fn mass(&self) -> Result<ExprId> {
        self.mass.ok_or_else(|| MechanicsError::MissingMass(self.name.clone()))
    }
}

impl Model {
    /// Every mass: the bodies in the order they were added, then the particles.
    pub fn masses(&self) -> impl Iterator<Item = MassView> + '_ {
        let bodies = (0..self.bodies.len()).map(|i| MassId::Body(BodyId(i as u32)));
        let particles = (0..self.particles.len()).map(|i| MassId::Particle(ParticleId(i as u32)));
        bodies.chain(particles).map(|id| self.mass_view(id))
    }

    /// The view of one body or particle.
    pub fn mass_view(&self, id: MassId) -> MassView {
        match id {
            MassId::Body(b) => {
                let body = &self.bodies[b.index()];
                MassView {
                    id,
                    name: body.name.clone(),
                    mass: body.mass,
                    point: body.mass_center,
                    frame: Some(body.frame),
                    inertia: body.inertia.clone(),
                }
            }
            MassId::Particle(p) => {
                let part = &self.particles[p.index()];
                MassView {
                    id,
                    name: part.name.clone(),
                    mass: part.mass,
                    point: part.point,
                    frame: None,
                    inertia: None,
                }
            }
        }
    }

    /// The sum of the masses of `masses` (Autolev's MASS()).
    pub fn total_mass(&mut self, masses: &[MassView]) -> Result<ExprId> {
        let ms = masses.iter().map(MassView::mass).collect::<Result<Vec<_>>>()?;
        Ok(self.ar.add(&ms)?)
    }

    /// The position of the centre of mass of `masses` from `origin`, `sum(m r) / sum(m)` (CM()).
    pub fn center_of_mass(&mut self, origin: PointId, masses: &[MassView]) -> Result<Vector> {
        let mut moment = Vector::zero();
        let mut total = Vec::with_capacity(masses.len());
        for view in masses {
            let m = view.mass()?;
            let r = self.position(view.point, origin)?;
            let mr = self.scale(&r, m)?;
            moment = self.add_vectors(&moment, &mr)?;
            total.push(m);
        }
        let tm = self.ar.add(&total)?;
        let one = self.ar.one();
        let inv = self.ar.div(one, tm)?;
        self.scale(&moment, inv)
    }

    /// The linear momentum of `masses` in `frame`, `sum(m v)` (MOMENTUM(LINEAR)).
    pub fn linear_momentum(&mut self, masses: &[MassView], frame: FrameId) -> Result<Vector> {
        let mut p = Vector::zero();
        for view in masses {
            let m = view.mass()?;
            let v = self.velocity(view.point, frame)?;
            let mv = self.scale(&v, m)?;
            p = self.add_vectors(&p, &mv)?;
        }
        Ok(p)
    }

    /// Uniform gravity: the force `mass * g` at every mass centre and particle (each needs a mass).
    pub fn add_gravity(&mut self, g: &Vector) -> Result<()> {
        self.gravity_on_masses(g, true)
    }

    /// Uniform gravity on every body and particle given a mass so far; the others are skipped
    /// (Autolev's GRAVITY command).
    pub fn add_gravity_to_given_masses(&mut self, g: &Vector) -> Result<()> {
        self.gravity_on_masses(g, false)
    }

    /// Uniform gravity on the bodies and particles `only` (Autolev's `GRAVITY(G>, B, C)`); each
    /// must have its mass given.
    pub fn add_gravity_to(&mut self, g: &Vector, only: &[MassId]) -> Result<()> {
        for id in only {
            let view = self.mass_view(*id);
            let f = self.scale(g, view.mass()?)?;
            self.add_force(view.point, f);
        }
        Ok(())
    }

    /// The force `mass * g` at each mass centre, once per mass; a mass not given is an error
    /// (before any force is applied) when `every` is set, and skipped otherwise.
    fn gravity_on_masses(&mut self, g: &Vector, every: bool) -> Result<()> {
        let weighed: Vec<(ExprId, PointId)> = self
            .masses()
            .filter(|view| every || view.mass.is_some())
            .map(|view| Ok((view.mass()?, view.point)))
            .collect::<Result<_>>()?;
        for (m, point) in weighed {
            let f = self.scale(g, m)?;
            self.add_force(point, f);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::mechanics::{Load, MassId, MechanicsError, Model, Orientation, Vector};

    #[test]
    fn centre_of_mass_of_two_particles() {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let o = m.add_point("O").unwrap();
        let p1 = m.add_particle("P1").unwrap();
        let p2 = m.add_particle("P2").unwrap();
        let (m1, m2, l) =
            (m.ar.constant("m1").unwrap(), m.ar.constant("m2").unwrap(), m.ar.constant("L").unwrap());
        m.set_particle_mass(p1, m1);
        m.set_particle_mass(p2, m2);
        // P1 at the origin, P2 at L N1 from it.
        let (a1, a2) = (m.particle(p1).point, m.particle(p2).point);
        m.set_position(a1, o, Vector::zero()).unwrap();
        let x = m.unit(n, 1);
        let lx = m.scale(&x, l).unwrap();
        m.set_position(a2, o, lx).unwrap();
        let all: Vec<_> = m.masses().collect();
        assert_eq!(
            all.iter().map(|v| v.id).collect::<Vec<_>>(),
            [MassId::Particle(p1), MassId::Particle(p2)]
        );
        let c = m.center_of_mass(o, &all).unwrap();
        let cx = m.express(&c, n).unwrap()[0];
        let want = m.ar.eval_named(cx, &[("m1", 1.0), ("m2", 3.0), ("L", 2.0)]).unwrap();
        assert!((want - 1.5).abs() < 1e-12, "{want}");
        let total = m.total_mass(&all).unwrap();
        let sum = m.ar.add(&[m1, m2]).unwrap();
        assert_eq!(total, sum);
    }

    #[test]
    fn linear_momentum_of_a_body() {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let o = m.add_point("O").unwrap();
        let b = m.add_body("B").unwrap();
        let q = m.ar.variable("q").unwrap();
        let u = m.ar.variable("u").unwrap();
        let (mass, l) = (m.ar.constant("M").unwrap(), m.ar.constant("L").unwrap());
        let frame = m.body(b).frame;
        m.orient(frame, n, Orientation::Axis { axis: 3, angle: q }).unwrap();
        m.set_kinematics(q, u).unwrap();
        m.set_mass(b, mass);
        m.set_velocity(o, n, Vector::zero());
        let b1 = m.unit(frame, 1);
        let r = m.scale(&b1, l).unwrap();
        let cm = m.body(b).mass_center;
        m.set_position(cm, o, r).unwrap();
        let all: Vec<_> = m.masses().collect();
        assert_eq!(all[0].frame, Some(frame));
        let p = m.linear_momentum(&all, n).unwrap();
        // p = M L u B2.
        let want = m.ar.mul(&[mass, l, u]).unwrap();
        let got = m.express(&p, frame).unwrap();
        let value = [("M", 2.0), ("L", 0.5), ("u", 3.0), ("q", 0.4)];
        let (g, w) = (m.ar.eval_named(got[1], &value).unwrap(), m.ar.eval_named(want, &value).unwrap());
        assert!((g - w).abs() < 1e-12 && m.ar.eval_named(got[0], &value).unwrap().abs() < 1e-12);
    }

    #[test]
    fn gravity_once_per_mass_and_missing_masses() {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let b = m.add_body("B").unwrap();
        let p = m.add_particle("P").unwrap();
        let g = m.unit(n, 2);
        let mass = m.ar.constant("M").unwrap();
        m.set_mass(b, mass);
        assert_eq!(m.add_gravity(&g), Err(MechanicsError::MissingMass("P".into())));
        assert!(m.loads().is_empty(), "no force applied when a mass is missing");
        m.add_gravity_to_given_masses(&g).unwrap();
        let cm = m.body(b).mass_center;
        assert!(matches!(m.loads(), [Load::Force { point, .. }] if *point == cm));
        m.clear_loads();
        m.set_particle_mass(p, mass);
        m.add_gravity(&g).unwrap();
        assert_eq!(m.loads().len(), 2);
        let all: Vec<_> = m.masses().collect();
        assert!(m.total_mass(&all).is_ok());
    }
}
