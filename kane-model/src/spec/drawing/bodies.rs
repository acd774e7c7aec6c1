//! The bodies of a model's default drawing: in come the model's bodies with a mass and an
//! inertia whose frame and mass centre are drawn; out go the columns of each one's mass and
//! central inertia in its frame's axes (evaluated with the run's parameters, for a view to size
//! the body's ellipsoid of inertia by).

use crate::expr::ExprId;
use crate::mechanics::{Result, Vector};

use super::{DrawnFrame, Gathered, ModelSpec};

/// A body drawn as the uniform solid ellipsoid of its mass and central inertia.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawnBody {
    /// Its name.
    pub name: String,
    /// Its frame, a drawn frame standing at the body's mass centre.
    pub frame: String,
    /// The column of its mass.
    pub mass: String,
    /// The columns of its central inertia in its frame's axes: I11, I22, I33, I12, I23, I31.
    pub inertia: [String; 6],
}

/// The inertia entries gathered, as (row, column) of the matrix in the body's axes.
const ENTRIES: [(usize, usize); 6] = [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (2, 0)];

impl ModelSpec {
    /// The bodies whose frame is among `frames` at the body's mass centre, each with its mass and
    /// inertia gathered (`MASS_B`, `I_B_BO_11`, ...); a body without mass or moments, or whose
    /// inertia cannot be expressed in its frame, is left out.
    pub(super) fn drawing_bodies(
        &mut self,
        gathered: &mut Gathered,
        frames: &[DrawnFrame],
    ) -> Vec<DrawnBody> {
        let mut drawn = Vec::new();
        for index in 0..self.model.bodies().len() {
            let body = &self.model.bodies()[index];
            let (name, centre) = (body.name.clone(), self.model.point_name(body.mass_center).to_string());
            let frame = self.model.frame_name(body.frame).to_string();
            if !frames.iter().any(|f| f.name == frame && f.at.as_deref() == Some(centre.as_str())) {
                continue;
            }
            let Ok(Some(components)) = self.mass_and_inertia(index) else { continue };
            let names = std::iter::once(format!("MASS_{name}"))
                .chain(ENTRIES.map(|(i, j)| format!("I_{name}_{centre}_{}{}", i + 1, j + 1)));
            let columns = self.gather(gathered, names, &components);
            let (mass, inertia) = columns.split_first().expect("a mass and six entries");
            let inertia = inertia.to_vec().try_into().expect("six entries");
            drawn.push(DrawnBody { name, frame, mass: mass.clone(), inertia });
        }
        drawn
    }

    /// The mass and the six inertia entries (in [`ENTRIES`]' order, in the body's axes) of body
    /// `index`, in states; none when it has no mass or no inertia, or either is zero.
    fn mass_and_inertia(&mut self, index: usize) -> Result<Option<[ExprId; 7]>> {
        let body = &self.model.bodies()[index];
        let (frame, Some(mass), Some(inertia)) = (body.frame, body.mass, body.inertia.clone()) else {
            return Ok(None);
        };
        let (zero, one) = (self.model.ar.zero(), self.model.ar.one());
        // Column j of the matrix: I . b_j in the body's axes.
        let mut columns = [[zero; 3]; 3];
        for (j, column) in columns.iter_mut().enumerate() {
            let b_j = Vector::new(frame, std::array::from_fn(|k| if k == j { one } else { zero }));
            let image = self.model.dyadic_dot(&inertia, &b_j)?;
            *column = self.model.express(&image, frame)?;
        }
        let entries = ENTRIES.map(|(i, j)| columns[j][i]);
        let ar = &self.model.ar;
        if ar.is_zero(mass) || entries.iter().all(|e| ar.is_zero(*e)) {
            return Ok(None);
        }
        let mut components = [mass; 7];
        for (c, e) in components.iter_mut().zip(std::iter::once(mass).chain(entries)) {
            *c = self.in_states(e)?;
        }
        Ok(Some(components))
    }
}
