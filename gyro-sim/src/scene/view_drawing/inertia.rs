//! A view's bodies sized by their inertia: in come a view whose bodies may be
//! [`Shape::Inertia`] (columns of a mass and an inertia) and one row of the run; out goes the
//! view with each such body the uniform solid ellipsoid of the row's mass and inertia along its
//! principal axes, or left out when it has no mass or no moments.

use kane_model::spec::inertia_ellipsoid;

use crate::scene::{BodyView, Length, Shape, ViewError, ViewSpec};

impl ViewSpec {
    /// This view with every body sized by its inertia an ellipsoid, `values[k]` being the value
    /// of column `names[k]` (a run's first row: the parameters' values, constant over the run).
    pub fn with_inertias(&self, names: &[&str], values: &[f64]) -> Result<ViewSpec, ViewError> {
        let value_of = |user: &str, column: &str| {
            let k = names.iter().position(|n| *n == column).ok_or_else(|| ViewError::MissingColumn {
                user: user.to_string(),
                column: column.to_string(),
                known: names.join(", "),
            })?;
            Ok::<f64, ViewError>(values[k])
        };
        let mut view = self.clone();
        view.bodies.clear();
        for body in &self.bodies {
            let Shape::Inertia { mass, inertia } = &body.shape else {
                view.bodies.push(body.clone());
                continue;
            };
            let user = format!("body {}", body.name);
            let mass = value_of(&user, mass)?;
            let mut moments = [0.0; 6];
            for (m, column) in moments.iter_mut().zip(inertia) {
                *m = value_of(&user, column)?;
            }
            let Some(ellipsoid) = inertia_ellipsoid(mass, moments) else { continue };
            let [a, b, c] = ellipsoid.semi_axes.map(Length::Number);
            let shape = Shape::Ellipsoid { a, b, c };
            view.bodies.push(BodyView { shape, turn: ellipsoid.axes, ..body.clone() });
        }
        Ok(view)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Orientation;

    /// A view of body `B` sized by `MASS_B` and `I_B_BO_ij`, and a rod `R`.
    fn view() -> ViewSpec {
        let inertia = ["11", "22", "33", "12", "23", "31"].map(|ij| format!("I_B_BO_{ij}"));
        let body = |name: &str, shape: Shape| BodyView {
            name: name.into(),
            shape,
            colour: "#1f77b4".into(),
            orientation: Orientation::Fixed,
            offset: [0.0.into(), 0.0.into(), 0.0.into()],
            opacity: 0.4,
            axis: 3,
            turn: None,
            position: None,
        };
        let bodies = vec![
            body("B", Shape::Inertia { mass: "MASS_B".into(), inertia }),
            body("R", Shape::Rod { length: 1.0.into() }),
        ];
        ViewSpec { bodies, ..ViewSpec::default() }
    }

    const NAMES: [&str; 7] =
        ["MASS_B", "I_B_BO_11", "I_B_BO_22", "I_B_BO_33", "I_B_BO_12", "I_B_BO_23", "I_B_BO_31"];

    #[test]
    fn a_body_sized_by_its_inertia_becomes_its_ellipsoid() {
        // The solid ellipsoid of mass 5 with semi-axes 1, 2, 3: I = m/5 (b^2 + c^2), ...
        let sized = view().with_inertias(&NAMES, &[5.0, 13.0, 10.0, 5.0, 0.0, 0.0, 0.0]).unwrap();
        let Shape::Ellipsoid { a, b, c } = &sized.bodies[0].shape else { panic!("{:?}", sized.bodies[0]) };
        let semi = [a, b, c].map(|l| l.number().unwrap());
        assert!(semi.iter().zip([1.0, 2.0, 3.0]).all(|(s, w)| (s - w).abs() < 1e-12), "{semi:?}");
        assert_eq!(sized.bodies[0].turn, None, "no products: the body's axes");
        assert_eq!(sized.bodies[1], view().bodies[1], "other bodies as they were");
        assert!(sized.columns().iter().all(|(_, c)| !c.starts_with("I_B") && !c.starts_with("MASS")));
        sized.check().unwrap();
        let turned = view().with_inertias(&NAMES, &[5.0, 13.0, 10.0, 5.0, 1.0, 0.0, 0.0]).unwrap();
        assert!(turned.bodies[0].turn.is_some(), "products: the principal axes");
        let json = serde_json::to_string(&turned.bodies[0]).unwrap();
        assert!(json.contains("\"kind\":\"ellipsoid\"") && json.contains("\"turn\":["), "{json}");
    }

    #[test]
    fn a_body_without_mass_or_moments_is_left_out_and_a_missing_column_named() {
        for values in [[0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]] {
            let sized = view().with_inertias(&NAMES, &values).unwrap();
            let names: Vec<&str> = sized.bodies.iter().map(|b| b.name.as_str()).collect();
            assert_eq!(names, ["R"], "{values:?}");
        }
        let nan = view().with_inertias(&NAMES, &[f64::NAN, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0]).unwrap();
        assert_eq!(nan.bodies.len(), 1);
        let e = view().with_inertias(&NAMES[..6], &[1.0; 6]).unwrap_err();
        assert!(
            matches!(&e, ViewError::MissingColumn { user, column, .. } if user == "body B" && column == "I_B_BO_31"),
            "{e}"
        );
    }
}
