//! A thin disk rolling without slip on a horizontal plane (SymPy's rolling-disc example).
//!
//! Yaw `q1` about `n3` (frame Y), lean `q2` about `y1` (frame L), spin `q3` about `l2` (the disk
//! R); speeds are the disk's angular velocity in L: `w_R = u1 l1 + u2 l2 + u3 l3`, so
//! `q1' = u3 / cos q2`, `q2' = u1`, `q3' = u2 - u3 tan q2`. The centre is `r l3` above the
//! contact point; gravity `-g y3`; central inertia `m r^2 (1/4, 1/2, 1/4)` in L.
//!
//! Two formulations: [`RollingDisk::contact_fixed`] takes the contact point as momentarily fixed
//! (three speeds, no constraint); [`RollingDisk::nonholonomic`] tracks the contact point's
//! position `(x, y)` with speeds `u4 = x'`, `u5 = y'` and eliminates them with the two no-slip
//! constraints. Both must give the same equations for `u1..u3`.

use crate::expr::ExprId;
use crate::mechanics::{Model, Orientation, Result, Vector};

/// The rolling disk with handles on its symbols.
pub struct RollingDisk {
    /// The model.
    pub model: Model,
    /// Yaw, lean, spin (and x, y in the nonholonomic form).
    pub q: Vec<ExprId>,
    /// Speeds u1..u3 (and u4, u5 in the nonholonomic form).
    pub u: Vec<ExprId>,
}

impl RollingDisk {
    /// Three speeds; the contact point has zero velocity.
    pub fn contact_fixed() -> Result<RollingDisk> {
        build(false)
    }

    /// Five speeds, two of them eliminated by the no-slip constraints.
    pub fn nonholonomic() -> Result<RollingDisk> {
        build(true)
    }
}

fn build(track_contact: bool) -> Result<RollingDisk> {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let r = m.ar.constant("r")?;
    let mass = m.ar.constant("m")?;
    let g = m.ar.constant("g")?;
    let mut q: Vec<ExprId> =
        ["q1", "q2", "q3"].iter().map(|s| m.ar.variable(s)).collect::<std::result::Result<_, _>>()?;
    let mut u: Vec<ExprId> =
        ["u1", "u2", "u3"].iter().map(|s| m.ar.variable(s)).collect::<std::result::Result<_, _>>()?;
    let y = m.add_frame("Y")?;
    let l = m.add_frame("L")?;
    let disk = m.add_body("R")?;
    let rf = m.body(disk).frame;
    m.orient(y, n, Orientation::Axis { axis: 3, angle: q[0] })?;
    m.orient(l, y, Orientation::Axis { axis: 1, angle: q[1] })?;
    m.orient(rf, l, Orientation::Axis { axis: 2, angle: q[2] })?;
    // w_R_N = u1 l1 + u2 l2 + u3 l3, and w_R_L = w_R_N - w_L_N with w_L_N = q1' y3 + q2' l1.
    let w_l = m.angular_velocity(l, n)?;
    let w_r = Vector::new(l, [u[0], u[1], u[2]]);
    let rel = m.sub_vectors(&w_r, &w_l)?;
    let rel = m.express_vector(&rel, l)?;
    m.set_angular_velocity(rf, rel);

    let o = m.add_point("O")?;
    m.fix_point(o, n);
    let contact = m.add_point("C")?;
    if track_contact {
        let x = m.ar.variable("x")?;
        let yy = m.ar.variable("y")?;
        let z = m.ar.zero();
        m.set_position(contact, o, Vector::new(n, [x, yy, z]))?;
        q.extend([x, yy]);
        u.extend([m.ar.variable("u4")?, m.ar.variable("u5")?]);
    } else {
        m.fix_point(contact, n);
    }
    m.set_coordinates(&q)?;
    m.set_speeds(&u)?;
    let (s2, c2) = (m.ar.sin(q[1])?, m.ar.cos(q[1])?);
    let q1d = m.ar.div(u[2], c2)?;
    let tan = m.ar.div(s2, c2)?;
    let u3t = m.ar.mul(&[u[2], tan])?;
    let q3d = m.ar.sub(u[1], u3t)?;
    m.set_kinematics(q[0], q1d)?;
    m.set_kinematics(q[1], u[0])?;
    m.set_kinematics(q[2], q3d)?;
    if track_contact {
        m.set_kinematics(q[3], u[3])?;
        m.set_kinematics(q[4], u[4])?;
    }

    let centre = m.body(disk).mass_center;
    let up = m.scale(&m.unit(l, 3), r)?;
    m.set_position(centre, contact, up)?;
    if !track_contact {
        // The contact point is the disk's material point at rest; the centre is fixed in R.
        m.v2pts(n, rf, contact, centre)?;
    }
    let quarter = m.ar.rational(1, 4)?;
    let half = m.ar.rational(1, 2)?;
    let r2 = m.ar.powi(r, 2)?;
    let it = m.ar.mul(&[quarter, mass, r2])?;
    let ia = m.ar.mul(&[half, mass, r2])?;
    let inertia = m.diagonal_inertia(l, [it, ia, it]);
    m.set_mass(disk, mass);
    m.set_inertia(disk, inertia);
    let mg = m.ar.mul(&[m.ar.minus_one(), mass, g])?;
    let weight = m.scale(&m.unit(y, 3), mg)?;
    m.add_force(centre, weight);

    if track_contact {
        // No slip: the disk's material point at the contact has zero velocity in N.
        let v_centre = m.velocity(centre, n)?;
        let w = m.angular_velocity(rf, n)?;
        let mr = m.ar.neg(r)?;
        let down = m.scale(&m.unit(l, 3), mr)?;
        let spin = m.cross(&w, &down)?;
        let v_material = m.add_vectors(&v_centre, &spin)?;
        let c1 = m.dot(&v_material, &m.unit(n, 1))?;
        let c2 = m.dot(&v_material, &m.unit(n, 2))?;
        m.set_motion_constraints(&[c1, c2], &[u[3], u[4]])?;
    }
    Ok(RollingDisk { model: m, q, u })
}
