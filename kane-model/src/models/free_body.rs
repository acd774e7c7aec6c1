//! Torque-free rigid bodies: an asymmetric body, and Feynman's wobbling plate.
//!
//! Euler-parameter orientation (scalar first, body to space), body-frame angular velocity
//! components as speeds, `e' = 1/2 e (0, w)`, no loads. The mass centre is fixed.

use crate::expr::ExprId;
use crate::mechanics::{BodyId, Model, Orientation, Result, Shape, Vector};

/// A torque-free body with handles on its symbols.
pub struct FreeBody {
    /// The model.
    pub model: Model,
    /// Euler parameters e0..e3.
    pub e: [ExprId; 4],
    /// Body angular velocity components w1..w3.
    pub w: [ExprId; 3],
    /// The body.
    pub body: BodyId,
}

impl FreeBody {
    /// An asymmetric body with principal moments `I1, I2, I3` (constants of those names).
    pub fn asymmetric() -> Result<FreeBody> {
        build(|m, _| {
            let i = [m.ar.constant("I1")?, m.ar.constant("I2")?, m.ar.constant("I3")?];
            Ok(i)
        })
    }

    /// Feynman's wobbling plate: a thin disk of mass `m` and radius `r` (normal along axis 3).
    pub fn feynman_plate() -> Result<FreeBody> {
        build(|m, _| {
            let mass = m.ar.constant("m")?;
            let r = m.ar.constant("r")?;
            m.shape_moments(Shape::ThinDisk { r }, mass)
        })
    }
}

fn build(moments: impl Fn(&mut Model, BodyId) -> Result<[ExprId; 3]>) -> Result<FreeBody> {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let e = [m.ar.variable("e0")?, m.ar.variable("e1")?, m.ar.variable("e2")?, m.ar.variable("e3")?];
    let w = [m.ar.variable("w1")?, m.ar.variable("w2")?, m.ar.variable("w3")?];
    let body = m.add_body("B")?;
    let f = m.body(body).frame;
    m.orient(f, n, Orientation::EulerParameters(e))?;
    m.set_angular_velocity(f, Vector::new(f, w));
    m.set_coordinates(&e)?;
    m.set_speeds(&w)?;
    quaternion_kinematics(&mut m, e, w)?;
    let i = moments(&mut m, body)?;
    let one = m.ar.one();
    m.set_mass(body, one);
    let inertia = m.diagonal_inertia(f, i);
    m.set_inertia(body, inertia);
    let o = m.add_point("O")?;
    m.fix_point(o, n);
    let cm = m.body(body).mass_center;
    m.set_position(cm, o, Vector::zero())?;
    Ok(FreeBody { model: m, e, w, body })
}

/// `e' = 1/2 e (0, w)`: `e0' = -(e.w)/2`, `ev' = (e0 w + ev x w)/2`.
pub(crate) fn quaternion_kinematics(m: &mut Model, e: [ExprId; 4], w: [ExprId; 3]) -> Result<()> {
    let half = m.ar.rational(1, 2)?;
    let terms: [[(usize, usize, i128); 3]; 4] = [
        [(1, 0, -1), (2, 1, -1), (3, 2, -1)],
        [(0, 0, 1), (2, 2, 1), (3, 1, -1)],
        [(0, 1, 1), (3, 0, 1), (1, 2, -1)],
        [(0, 2, 1), (1, 1, 1), (2, 0, -1)],
    ];
    for (k, row) in terms.iter().enumerate() {
        let mut parts = Vec::new();
        for &(ei, wi, sign) in row {
            let s = m.ar.integer(sign);
            parts.push(m.ar.mul(&[s, half, e[ei], w[wi]])?);
        }
        let rhs = m.ar.add(&parts)?;
        m.set_kinematics(e[k], rhs)?;
    }
    Ok(())
}
