//! Initial conditions of a top, EJS style: in come a scene's `[axle]` values (tilt of the axle
//! from +z, spin about it, precession and nutation rates, with their units); out go the Euler
//! parameters (scalar first, body -> space) and body-axis angular velocity in model units
//! (radians, rad/s), in the convention of the EJS "Gyroscope" references
//! (`gyro-sim/tests/data/ejs/PROVENANCE.md`):
//!
//! ```text
//! q0 = (cos(theta0/2), sin(theta0/2), 0, 0)           a rotation by theta0 about space x
//! omega_body = (thetadot0, phidot0 sin(theta0), omega3)
//! ```
//!
//! so the axle (body 3) starts at `(0, -sin theta0, cos theta0)` in space, z up. Also here: the
//! unit-norm test of Euler parameters given directly, and two numbers the presets quote (the
//! steady-precession rates and the sleeping top's spin threshold).

use kane_model::lang::units::normalised;
use kane_model::lang::units::size::unit_size;

use crate::scene::{Axle, Scene, SceneError, Value};

/// How far from 1 the norm of Euler parameters given directly may be.
pub const UNIT_NORM_TOLERANCE: f64 = 1e-9;

/// A top's initial motion, EJS style, in radians and rad/s.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TopStart {
    /// theta0: the axle's angle from +z (0 = upright).
    pub tilt: f64,
    /// omega3: the body rate about the axle.
    pub spin: f64,
    /// phidot0: the rate of the axle's azimuth about +z.
    pub precession: f64,
    /// thetadot0: the rate of the tilt.
    pub nutation: f64,
}

impl TopStart {
    /// The Euler parameters, scalar first, body -> space: `(cos(theta0/2), sin(theta0/2), 0, 0)`.
    pub fn euler_parameters(&self) -> [f64; 4] {
        let (s, c) = (self.tilt / 2.0).sin_cos();
        [c, s, 0.0, 0.0]
    }

    /// The angular velocity in body axes: `(thetadot0, phidot0 sin(theta0), omega3)`.
    pub fn body_rates(&self) -> [f64; 3] {
        [self.nutation, self.precession * self.tilt.sin(), self.spin]
    }

    /// The motion an `[axle]` table of `scene` gives (absent values are 0), or an error at a value
    /// whose unit does not fit.
    pub fn from_scene(scene: &Scene, axle: &Axle) -> Result<TopStart, SceneError> {
        let get = |given: &Option<(Value, std::ops::Range<usize>)>, key: &str, kind: Kind| {
            given.as_ref().map_or(Ok(0.0), |(v, span)| {
                in_radians(v, kind).map_err(|wrong| {
                    scene.error_at(
                        span.clone(),
                        format!("`{key}` in [axle] is {}, {wrong}", kind.what()),
                        &format!("write a number with {}", kind.units()),
                    )
                })
            })
        };
        Ok(TopStart {
            tilt: get(&axle.tilt, "tilt", Kind::Angle)?,
            spin: get(&axle.spin, "spin", Kind::Rate)?,
            precession: get(&axle.precession, "precession", Kind::Rate)?,
            nutation: get(&axle.nutation, "nutation", Kind::Rate)?,
        })
    }
}

/// What an `[axle]` value measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// An angle: `deg` or `rad` (a plain number is radians).
    Angle,
    /// An angular rate: `rad/s`, `deg/s` or `rpm` (a plain number is rad/s).
    Rate,
}

impl Kind {
    fn what(self) -> &'static str {
        match self {
            Kind::Angle => "an angle",
            Kind::Rate => "an angular rate",
        }
    }

    fn units(self) -> &'static str {
        match self {
            Kind::Angle => "deg or rad, e.g. \"60 deg\" (a plain number is radians)",
            Kind::Rate => "rad/s, deg/s or rpm, e.g. \"10 rad/s\" (a plain number is rad/s)",
        }
    }
}

/// A unit that does not fit what an `[axle]` value measures: the unit written, upper case.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("not in {unit}")]
pub struct WrongUnit {
    /// The unit written, upper case, spaces removed.
    pub unit: String,
}

/// `v` in radians (an angle) or rad/s (a rate), its unit read as INPUT lines read units (a plain
/// number is already in them); the unit written when it does not fit `kind`.
pub fn in_radians(v: &Value, kind: Kind) -> Result<f64, WrongUnit> {
    let Some(unit) = v.unit.as_deref().filter(|u| !u.trim().is_empty()) else { return Ok(v.number) };
    let unit = normalised(unit);
    let wanted = unit_size(match kind {
        Kind::Angle => "RAD",
        Kind::Rate => "RAD/S",
    });
    match (unit_size(&unit), wanted) {
        (Ok(size), Ok(wanted)) if size.dim == wanted.dim => Ok(v.number * size.si),
        _ => Err(WrongUnit { unit }),
    }
}

/// How far the norm of `q` is from 1.
pub fn norm_error(q: &[f64; 4]) -> f64 {
    (q.iter().map(|x| x * x).sum::<f64>().sqrt() - 1.0).abs()
}

/// The two rates of steady precession at tilt `theta` with spin `omega3` about the axle, slow
/// then fast: the roots of `I1 cos(theta) phidot^2 - I3 omega3 phidot + M g d = 0` (the torque
/// `M g d sin(theta)` equals the rate of change of the angular momentum); `None` when the spin
/// is too slow for steady precession at that tilt. `mgd` is `M g d`; `i1` is the transverse
/// moment about the support, `i3` the axial one.
pub fn steady_precession(i1: f64, i3: f64, mgd: f64, theta: f64, omega3: f64) -> Option<(f64, f64)> {
    let a = i1 * theta.cos();
    let b = i3 * omega3;
    if a == 0.0 {
        return Some((mgd / b, f64::INFINITY));
    }
    let disc = b * b - 4.0 * a * mgd;
    if disc < 0.0 {
        return None;
    }
    // The slow root as c / q (no cancellation), the fast one as q / a.
    let q = (b + b.signum() * disc.sqrt()) / 2.0;
    Some((mgd / q, q / a))
}

/// The spin above which an upright top sleeps (stays up): `omega3^2 > 4 M g d I1 / I3^2`.
pub fn sleeping_threshold(i1: f64, i3: f64, mgd: f64) -> f64 {
    (4.0 * mgd * i1).sqrt() / i3
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(number: f64, unit: &str) -> Value {
        Value { number, unit: (!unit.is_empty()).then(|| unit.to_string()) }
    }

    #[test]
    fn the_references_initial_states() {
        // top_loops_conserved.json: theta0 = 60 deg, phidot0 = -1, omega3 = 10.
        let top = TopStart { tilt: 60f64.to_radians(), spin: 10.0, precession: -1.0, nutation: 0.0 };
        let q = top.euler_parameters();
        let want_q = [0.8660254037844386, 0.5, 0.0, 0.0];
        let w = top.body_rates();
        let want_w = [0.0, -0.8660254037844386, 10.0];
        for k in 0..4 {
            assert!((q[k] - want_q[k]).abs() < 2e-16, "{q:?}");
        }
        for k in 0..3 {
            assert!((w[k] - want_w[k]).abs() < 2e-16, "{w:?}");
        }
        // top_nospin: 1 deg, at rest.
        let q = TopStart { tilt: 1f64.to_radians(), ..TopStart::default() }.euler_parameters();
        assert!((q[0] - 0.9999619230641713).abs() < 2e-16);
        assert!((q[1] - 0.008726535498373935).abs() < 2e-18);
    }

    #[test]
    fn the_axle_is_tilted_about_space_x() {
        // v_space = q (0, v_body) q*: body 3 goes to (0, -sin theta, cos theta).
        let theta: f64 = 0.7;
        let [w, x, y, z] = TopStart { tilt: theta, ..TopStart::default() }.euler_parameters();
        let axle = [2.0 * (x * z + w * y), 2.0 * (y * z - w * x), w * w - x * x - y * y + z * z];
        assert!(axle[0] == 0.0 && (axle[1] + theta.sin()).abs() < 4e-16);
        assert!((axle[2] - theta.cos()).abs() < 4e-16);
        assert!(norm_error(&[w, x, y, z]) < 4e-16);
    }

    #[test]
    fn units() {
        let deg = std::f64::consts::PI / 180.0;
        let near = |got: Result<f64, WrongUnit>, want: f64| (got.unwrap() - want).abs() <= 4e-16 * want;
        assert_eq!(in_radians(&value(60.0, "deg"), Kind::Angle), Ok(60.0 * deg));
        assert_eq!(in_radians(&value(1.5, "rad"), Kind::Angle), Ok(1.5));
        // Every angle spelling the unit table lists, as INPUT lines and [parameters] read it.
        assert!(near(in_radians(&value(30.0, "degrees"), Kind::Angle), 30.0 * deg));
        assert!(near(in_radians(&value(2.0, "deg/sec"), Kind::Rate), 2.0 * deg));
        assert_eq!(in_radians(&value(1.5, ""), Kind::Angle), Ok(1.5));
        assert_eq!(in_radians(&value(10.0, "rad/s"), Kind::Rate), Ok(10.0));
        assert_eq!(in_radians(&value(10.0, "rad/sec"), Kind::Rate), Ok(10.0));
        assert_eq!(in_radians(&value(90.0, "deg/s"), Kind::Rate), Ok(90.0 * deg));
        assert!(near(in_radians(&value(60.0, "rpm"), Kind::Rate), std::f64::consts::TAU));
        assert_eq!(
            in_radians(&value(10.0, "rad/s"), Kind::Angle),
            Err(WrongUnit { unit: "RAD/S".to_string() })
        );
        assert_eq!(in_radians(&value(10.0, "deg"), Kind::Rate), Err(WrongUnit { unit: "DEG".to_string() }));
    }

    #[test]
    fn steady_precession_roots_and_the_sleeping_threshold() {
        // top_steady_conserved.json: I1 = 151/125, I3 = 2/5, M g d = 1, 60 deg, omega3 = 10.
        let (slow, fast) = steady_precession(151.0 / 125.0, 0.4, 1.0, 60f64.to_radians(), 10.0).unwrap();
        assert!((slow - 0.2602252980690218).abs() < 1e-15, "{slow}");
        // Both are roots; their product is M g d / (I1 cos theta).
        assert!((slow * fast - 1.0 / (151.0 / 125.0 * 0.5)).abs() < 1e-13);
        // Too slow a spin has no steady precession at 60 deg: 4 I1 cos(theta) M g d > (I3 omega3)^2.
        assert!(steady_precession(151.0 / 125.0, 0.4, 1.0, 60f64.to_radians(), 3.0).is_none());
        // 4 M g d I1 / I3^2 = 30.2 for the EJS top.
        let w = sleeping_threshold(151.0 / 125.0, 0.4, 1.0);
        assert!((w * w - 30.2).abs() < 1e-12, "{w}");
    }

    #[test]
    fn norm() {
        assert!(norm_error(&[1.0, 0.0, 0.0, 0.0]) == 0.0);
        assert!((norm_error(&[1.0, 0.5, 0.0, 0.0]) - (1.25f64.sqrt() - 1.0)).abs() < 1e-16);
    }
}
