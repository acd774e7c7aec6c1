//! A view with the model's default drawing: in come a [`ViewSpec`] asking for it
//! (`draw_model = true`) and the model's [`Drawing`]; out goes the view with a body of axes per
//! frame, a translucent ellipsoid of inertia per body with a mass and an inertia (sized once the
//! run is known, in `inertia`) and a marker per point, joined to the points it was located from.

mod inertia;

use kane_model::spec::Drawing;

use super::view_spec::{BodyView, Length, Orientation, PointView, Shape, ViewSpec};

/// Colours of the frames' labels, in turn.
const FRAME_COLOURS: [&str; 6] = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"];
/// The points' colour.
const POINT_COLOUR: &str = "#333333";
/// The opacity of a body's ellipsoid of inertia: its frame's axes and the arrows inside show.
const BODY_OPACITY: f64 = 0.4;

impl ViewSpec {
    /// This view with `drawing`'s frames, bodies (each the ellipsoid of its inertia, in its
    /// frame's colour, about its mass centre) and points added after its own bodies and points
    /// (and its up axis and frame name, unless the view gives them).
    pub fn with_drawing(&self, drawing: &Drawing) -> ViewSpec {
        let mut view = self.clone();
        view.draw_model = false;
        view.up.get_or_insert(drawing.up);
        view.frame.get_or_insert_with(|| drawing.newtonian.clone());
        let position_of =
            |name: &str| drawing.points.iter().find(|p| p.name == name).map(|p| p.position.clone());
        // A body turning with frame `i`, at its mass centre, in the frame's colour.
        let with_frame = |i: usize, name: String, shape: Shape, opacity: f64| BodyView {
            name,
            shape,
            colour: FRAME_COLOURS[i % FRAME_COLOURS.len()].to_string(),
            orientation: Orientation::Dcm(drawing.frames[i].dcm.clone()),
            offset: [Length::Number(0.0), Length::Number(0.0), Length::Number(0.0)],
            opacity,
            axis: 3,
            turn: None,
            position: drawing.frames[i].at.as_deref().and_then(position_of),
        };
        for (i, frame) in drawing.frames.iter().enumerate() {
            let name = unused(&frame.name, |n| view.bodies.iter().any(|b| b.name == n));
            view.bodies.push(with_frame(i, name, Shape::Axes { length: None }, 1.0));
        }
        for body in &drawing.bodies {
            let Some(i) = drawing.frames.iter().position(|f| f.name == body.frame) else { continue };
            let name =
                unused(&format!("{} (inertia)", body.name), |n| view.bodies.iter().any(|b| b.name == n));
            let shape = Shape::Inertia { mass: body.mass.clone(), inertia: body.inertia.clone() };
            view.bodies.push(with_frame(i, name, shape, BODY_OPACITY));
        }
        // The drawing's points under names the view's own points do not have.
        let own = self.points.clone();
        let named = |name: &str| unused(name, |n| own.iter().any(|p| p.name == n));
        for point in &drawing.points {
            view.points.push(PointView {
                name: named(&point.name),
                position: point.position.clone(),
                colour: POINT_COLOUR.to_string(),
                from: point.from.as_deref().map(named),
            });
        }
        view
    }
}

/// `name`, else `name (drawn)`, `name (drawn 2)`, ...: the first not `taken`.
fn unused(name: &str, taken: impl Fn(&str) -> bool) -> String {
    let suffixed =
        (1..).map(|k| if k == 1 { format!("{name} (drawn)") } else { format!("{name} (drawn {k})") });
    std::iter::once(name.to_string()).chain(suffixed).find(|n| !taken(n)).expect("a free name")
}

#[cfg(test)]
mod tests {
    use kane_model::spec::{DrawnBody, DrawnFrame, DrawnPoint};

    use super::*;

    fn columns<const N: usize>(name: &str, suffixes: [&str; N]) -> [String; N] {
        suffixes.map(|s| format!("{name}_{s}"))
    }

    fn drawing() -> Drawing {
        let dcm = ["11", "12", "13", "21", "22", "23", "31", "32", "33"];
        let xyz = ["N1", "N2", "N3"];
        Drawing {
            newtonian: "N".into(),
            origin: Some("O".into()),
            up: -1,
            frames: vec![
                DrawnFrame { name: "A".into(), dcm: columns("N_A", dcm), at: Some("AO".into()) },
                DrawnFrame { name: "C".into(), dcm: columns("N_C", dcm), at: None },
            ],
            points: vec![
                DrawnPoint { name: "O".into(), position: columns("P_O_O", xyz), from: None },
                DrawnPoint { name: "AO".into(), position: columns("P_O_AO", xyz), from: Some("O".into()) },
            ],
            bodies: Vec::new(),
        }
    }

    /// [`drawing`] with body A (mass `MASS_A`, inertia `I_A_AO_ij`).
    fn drawing_with_a_body() -> Drawing {
        let inertia = columns("I_A_AO", ["11", "22", "33", "12", "23", "31"]);
        let a = DrawnBody { name: "A".into(), frame: "A".into(), mass: "MASS_A".into(), inertia };
        Drawing { bodies: vec![a], ..drawing() }
    }

    #[test]
    fn a_body_is_an_ellipsoid_of_inertia_turning_with_its_frame_at_its_mass_centre() {
        let own = ViewSpec { draw_model: true, ..ViewSpec::default() };
        let view = own.with_drawing(&drawing_with_a_body());
        let names: Vec<&str> = view.bodies.iter().map(|b| b.name.as_str()).collect();
        assert_eq!(names, ["A", "C", "A (inertia)"]);
        let (axes, body) = (&view.bodies[0], &view.bodies[2]);
        assert_eq!(
            (&body.orientation, &body.position, &body.colour),
            (&axes.orientation, &axes.position, &axes.colour)
        );
        assert!(
            matches!(&body.shape, Shape::Inertia { mass, inertia } if mass == "MASS_A" && inertia[3] == "I_A_AO_12")
        );
        assert!(body.opacity > 0.3 && body.opacity < 0.6, "the axes inside show: {}", body.opacity);
        view.check().unwrap();
        let read: Vec<&str> = view.columns().into_iter().map(|(_, c)| c).collect();
        assert_eq!(read.len(), 9 + 3 + 9 + (9 + 3 + 7) + 3 + 3, "the mass and inertia are read");
    }

    #[test]
    fn frames_become_axes_at_their_mass_centres_and_points_markers_joined_up() {
        let view = ViewSpec { draw_model: true, ..ViewSpec::default() }.with_drawing(&drawing());
        assert!(!view.draw_model);
        assert_eq!((view.up, view.frame.as_deref()), (Some(-1), Some("N")));
        assert_eq!(view.bodies[0].position.as_ref().map(|p| p[0].as_str()), Some("P_O_AO_N1"));
        assert_eq!(view.bodies[1].position, None, "a frame without a body stands at the origin");
        assert_eq!(view.bodies[1].orientation.columns()[4], "N_C_22");
        assert_eq!(view.points[1].from.as_deref(), Some("O"));
        view.check().unwrap();
        let read: Vec<&str> = view.columns().into_iter().map(|(_, c)| c).collect();
        assert_eq!(read.len(), 9 + 3 + 9 + 3 + 3);
    }

    #[test]
    fn the_scene_keeps_its_own_bodies_points_up_axis_and_frame_name() {
        let body = BodyView {
            name: "A".into(),
            shape: Shape::Rod { length: Length::Number(1.0) },
            colour: "#000000".into(),
            orientation: Orientation::Fixed,
            offset: [Length::Number(0.0), Length::Number(0.0), Length::Number(0.0)],
            opacity: 1.0,
            axis: 3,
            turn: None,
            position: None,
        };
        let point = PointView {
            name: "O".into(),
            position: ["X", "Y", "Z"].map(String::from),
            colour: "#000000".into(),
            from: None,
        };
        let own = ViewSpec {
            up: Some(2),
            frame: Some("A".into()),
            bodies: vec![body],
            points: vec![point],
            ..ViewSpec::default()
        };
        let view = own.with_drawing(&drawing());
        assert_eq!((view.up, view.frame.as_deref()), (Some(2), Some("A")));
        let bodies: Vec<&str> = view.bodies.iter().map(|b| b.name.as_str()).collect();
        assert_eq!(bodies, ["A", "A (drawn)", "C"]);
        let points: Vec<(&str, Option<&str>)> =
            view.points.iter().map(|p| (p.name.as_str(), p.from.as_deref())).collect();
        assert_eq!(points, [("O", None), ("O (drawn)", None), ("AO", Some("O (drawn)"))]);
        view.check().unwrap();
    }
}
