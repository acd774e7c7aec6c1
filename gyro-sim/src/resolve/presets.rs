//! The built-in events, as expressions: in comes a [`Preset`] with the scene and the model; out
//! goes the text of its `when`, lowered like any other.
//!
//! - `axle_below_horizontal`: the space z component of the body z axis (the `[axle]`
//!   quaternion's `e0^2 - e1^2 - e2^2 + e3^2`, scalar first, body -> space) crossing zero,
//!   downward by default.
//! - `nutation_turning_points`: the time derivative of that component: its zeros are the axle
//!   elevation's extrema (elevation = asin of it), both ways by default (up: the lowest points,
//!   down: the highest).
//! - `gimbal_lock`: `|sin(angle - lock)| - sin(margin)`, downward by default: the angle comes
//!   within `margin` of `lock` or `lock + 180 deg`. For the paper's gimbal model the sequence
//!   is body-fixed 2-1-2 (`SIMPROT(A, B, -2, Q1)`, `(B, C, -1, Q2)`, `(C, D, -2, Q3)`): the
//!   rotor's spin axis C2 = cos(Q2) B2 + sin(Q2) B3 (up to sign) lines up with the outer axis
//!   A2 = B2 when sin(Q2) = 0, so the three rates no longer span the angular velocity at
//!   Q2 = 0 and 180 deg; `lock` defaults to 0 deg (90 deg for a Tait-Bryan sequence such as
//!   3-2-1).

use kane_model::runtime::ModelInfo;

use crate::scene::{EventDecl, Preset, Scene, SceneError};

/// The expression of preset `p` of event `decl` in `scene` for the model `info`.
pub fn when_text(
    decl: &EventDecl,
    p: &Preset,
    scene: &Scene,
    info: &ModelInfo,
) -> Result<String, SceneError> {
    match p {
        Preset::AxleBelowHorizontal => Ok(axle_z(decl, scene)?),
        Preset::NutationTurningPoints => Ok(format!("({})'", axle_z(decl, scene)?)),
        Preset::GimbalLock { angle, margin, lock } => {
            let (name, span) = angle;
            let Some(i) = info.state(name) else {
                return Err(scene.error_at(
                    span.clone(),
                    format!("{}: `{name}` is not a state of {}", decl.label(), info.name),
                    &format!("angle names the gimbal angle, one of: {}", info.state_names.join(", ")),
                ));
            };
            let unit = info.state_units[i].to_ascii_uppercase();
            let state = info.state_names[i];
            let margin = margin.sin();
            Ok(match unit.as_str() {
                "DEG" => format!("abs(sin(({state} - {:?}) * pi / 180)) - {margin:?}", lock.to_degrees()),
                "RAD" | "" => format!("abs(sin({state} - {lock:?})) - {margin:?}"),
                _ => {
                    return Err(scene.error_at(
                        span.clone(),
                        format!("{}: `{name}` is in {unit}, not an angle", decl.label()),
                        "angle names a state in DEG or RAD (the gimbal angle)",
                    ))
                }
            })
        }
    }
}

/// `e0^2 - e1^2 - e2^2 + e3^2` of the `[axle]` quaternion: the body z axis's space z component.
fn axle_z(decl: &EventDecl, scene: &Scene) -> Result<String, SceneError> {
    let Some(axle) = scene.axle.as_ref().filter(|a| a.quaternion.len() == 4) else {
        return Err(scene.error_at(
            decl.span.clone(),
            format!("{}: this preset needs the scene's [axle] table", decl.label()),
            "add [axle] with quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"] (the model's Euler parameters, scalar first, body -> space)",
        ));
    };
    let q: Vec<&str> = axle.quaternion.iter().map(|(n, _)| n.as_str()).collect();
    Ok(format!("{}^2 - {}^2 - {}^2 + {}^2", q[0], q[1], q[2], q[3]))
}
