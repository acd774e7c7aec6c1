//! The heavy symmetric top of the EJS "Gyroscope" model.
//!
//! A rotor, a uniform solid ellipsoid with semi-axes `R, R, R/5` (body axis 3 the axle), has its
//! centre at distance `d` along the axle from a fixed support point O; gravity `-g n3`. The
//! orientation is a unit quaternion (Euler parameters `e0..e3`, scalar first, body to space), the
//! speeds are the body-frame angular velocity components `w1, w2, w3`, and the kinematics are
//! `e' = 1/2 e (0, w)`.
//!
//! The EJS text gives the axial moment as `4MR^2/5`; the ellipsoid formula gives `2MR^2/5` for
//! these semi-axes (the transverse `26MR^2/125` agrees with both). The inertia here is computed
//! from the shape, so it is `2MR^2/5`.

use crate::expr::ExprId;
use crate::mechanics::{BodyId, Model, Orientation, PointId, Result, Shape, Vector};
use crate::spec::{ModelSpec, OrientationForm};

/// The heavy top with handles on its symbols.
pub struct HeavyTop {
    /// The model.
    pub model: Model,
    /// Euler parameters e0..e3.
    pub e: [ExprId; 4],
    /// Body angular velocity components w1..w3.
    pub w: [ExprId; 3],
    /// The rotor.
    pub rotor: BodyId,
    /// The support point.
    pub support: PointId,
    /// Constants M, g, R, d.
    pub constants: [ExprId; 4],
}

impl HeavyTop {
    /// Builds the model.
    pub fn new() -> Result<HeavyTop> {
        let mut m = Model::new("N");
        let n = m.newtonian();
        let [mass, g, r, d] = ["M", "g", "R", "d"].map(|s| m.ar.constant(s));
        let (mass, g, r, d) = (mass?, g?, r?, d?);
        let e = [m.ar.variable("e0")?, m.ar.variable("e1")?, m.ar.variable("e2")?, m.ar.variable("e3")?];
        let w = [m.ar.variable("w1")?, m.ar.variable("w2")?, m.ar.variable("w3")?];
        let rotor = m.add_body("R")?;
        let fr = m.body(rotor).frame;
        m.orient(fr, n, Orientation::EulerParameters(e))?;
        m.set_angular_velocity(fr, Vector::new(fr, w));
        m.set_coordinates(&e)?;
        m.set_speeds(&w)?;
        super::free_body::quaternion_kinematics(&mut m, e, w)?;
        let fifth = m.ar.rational(1, 5)?;
        let c = m.ar.mul(&[fifth, r])?;
        let inertia = m.shape_inertia(Shape::SolidEllipsoid { a: r, b: r, c }, mass, fr)?;
        m.set_mass(rotor, mass);
        m.set_inertia(rotor, inertia);
        let o = m.add_point("O")?;
        m.fix_point(o, n);
        let cm = m.body(rotor).mass_center;
        let arm = m.scale(&m.unit(fr, 3), d)?;
        m.set_position(cm, o, arm)?;
        let mg = m.ar.neg(g)?;
        let gravity = m.scale(&m.unit(n, 3), mg)?;
        m.add_gravity(&gravity)?;
        Ok(HeavyTop { model: m, e, w, rotor, support: o, constants: [mass, g, r, d] })
    }
}

impl HeavyTop {
    /// The name of the spec the Rust-API top generates (the model file's is `heavy_top`).
    pub const SPEC_NAME: &'static str = "heavy_top_rust";

    /// The spec of the top: the EJS defaults (M = g = R = d = 1, tilted 60 degrees from the
    /// vertical, spin 10 rad/s), and outputs: kinetic and potential energy, the angular
    /// momentum about the support in space axes, the rotor's orientation as a quaternion.
    pub fn spec(self) -> Result<ModelSpec> {
        let HeavyTop { mut model, support, rotor, constants, .. } = self;
        let eqs = model.kane()?;
        let n = model.newtonian();
        let frame = model.body(rotor).frame;
        let g = model.ar.neg(constants[1])?;
        let gravity = model.scale(&model.unit(n, 3), g)?;
        let mut spec = ModelSpec::new(Self::SPEC_NAME, model, eqs);
        let half_tilt = 30f64.to_radians();
        for (name, v) in [("M", 1.0), ("g", 1.0), ("R", 1.0), ("d", 1.0)] {
            spec.set_default(name, v);
        }
        let initial = [half_tilt.cos(), half_tilt.sin(), 0.0, 0.0, 0.0, 0.0, 10.0];
        for (name, v) in ["e0", "e1", "e2", "e3", "w1", "w2", "w3"].iter().zip(initial) {
            spec.set_default(name, v);
        }
        for w in ["w1", "w2", "w3"] {
            spec.set_unit(w, "RAD/SEC");
        }
        spec.add_kinetic_energy("KE", "")?;
        spec.add_potential_energy("PE", &gravity, support, "")?;
        spec.add_angular_momentum("L", support, n, "")?;
        spec.add_orientation("Q", frame, OrientationForm::Quaternion)?;
        Ok(spec)
    }
}
