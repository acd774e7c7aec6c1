//! A model's default drawing: in comes a spec (its frames, points, bodies and gravity); out go
//! outputs placing each frame and point in the Newtonian frame (direction cosines `N_F`,
//! positions `P_O_P`), each body's mass and inertia (`MASS_B`, `I_B_BO_11`, ...) and a
//! [`Drawing`] naming their columns, for a view that draws the model without a hand-written
//! scene.

mod bodies;

use rustc_hash::FxHashSet;

use crate::expr::ExprId;
use crate::mechanics::{FrameId, PointId, Result, Vector};

use super::{ModelSpec, OrientationForm, OutputKind};

pub use bodies::DrawnBody;

/// The frames and points of a model a default view draws, each with the columns placing it.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawing {
    /// The Newtonian frame's name.
    pub newtonian: String,
    /// The point positions are measured from (drawn at the origin), when any point is placed.
    pub origin: Option<String>,
    /// The Newtonian axis drawn upward, against gravity: 1, 2, 3, or -1, -2, -3 (3 without
    /// gravity along one axis).
    pub up: i8,
    /// The frames other than the Newtonian one whose orientation in it is known.
    pub frames: Vec<DrawnFrame>,
    /// The points whose position from the origin is known.
    pub points: Vec<DrawnPoint>,
    /// The bodies with a mass and an inertia whose frame stands at their mass centre.
    pub bodies: Vec<DrawnBody>,
}

/// A frame drawn as axes.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawnFrame {
    /// Its name.
    pub name: String,
    /// The columns of its direction cosines `N_i . F_j`, row by row.
    pub dcm: [String; 9],
    /// The drawn point it stands at (its body's mass centre), or none: at the origin.
    pub at: Option<String>,
}

/// A point drawn as a marker.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawnPoint {
    /// Its name.
    pub name: String,
    /// The columns of its position from the origin, in Newtonian axes.
    pub position: [String; 3],
    /// The drawn point it was located from (a line joins them), if any.
    pub from: Option<String>,
}

/// The drawing's columns and components, gathered before they become one output, and every
/// name a column may not take (states', outputs' and gathered columns', upper-cased).
struct Gathered {
    columns: Vec<String>,
    components: Vec<ExprId>,
    taken: FxHashSet<String>,
}

impl ModelSpec {
    /// Adds one output placing every frame and point the model can place (columns an output
    /// of the same name and meaning has already are read from it) and giving the drawn bodies'
    /// masses and inertias; `gravity` decides the upward axis.
    pub fn add_drawing(&mut self, gravity: Option<&Vector>) -> Result<Drawing> {
        let n = self.model.newtonian();
        let newtonian = self.model.frame_name(n).to_string();
        let origin = self.drawing_origin();
        let states = self.states().into_iter().map(|s| self.symbol_name(s).to_ascii_uppercase());
        let columns = self.outputs.iter().flat_map(|o| o.columns()).map(|c| c.to_ascii_uppercase());
        let taken = states.chain(columns).collect();
        let mut gathered = Gathered { columns: Vec::new(), components: Vec::new(), taken };
        let mut points = Vec::new();
        if let Some(o) = origin {
            for index in 0..self.model.points.len() {
                let p = PointId(index as u32);
                let Ok(r) = self.model.position(p, o) else { continue };
                let name = format!("P_{}_{}", self.model.point_name(o), self.model.point_name(p));
                // A position through a frame not oriented in N is not drawn.
                if let Ok(columns) = self.drawing_position(&mut gathered, &name, &r) {
                    points.push((p, columns));
                }
            }
        }
        let drawn_name = |p: PointId| points.iter().any(|(q, _)| *q == p);
        let mut frames = Vec::new();
        for index in 0..self.model.frames.len() {
            let f = FrameId(index as u32);
            if f == n || self.model.dcm(n, f).is_err() {
                continue;
            }
            let body = self.model.bodies().iter().find(|b| b.frame == f).map(|b| b.mass_center);
            let at = body.filter(|p| drawn_name(*p)).map(|p| self.model.point_name(p).to_string());
            let dcm = self.drawing_orientation(&mut gathered, f)?;
            frames.push(DrawnFrame { name: self.model.frame_name(f).to_string(), dcm, at });
        }
        let bodies = self.drawing_bodies(&mut gathered, &frames);
        let points = points
            .iter()
            .map(|(p, position)| {
                let parent = self.model.points[p.index()].position.as_ref().map(|(q, _)| *q);
                DrawnPoint {
                    name: self.model.point_name(*p).to_string(),
                    position: position.clone(),
                    from: parent.filter(|q| drawn_name(*q)).map(|q| self.model.point_name(q).to_string()),
                }
            })
            .collect();
        let origin = origin.map(|o| self.model.point_name(o).to_string());
        let up = gravity.and_then(|g| self.upward_axis(g).ok()).unwrap_or(3);
        if !gathered.components.is_empty() {
            let name = self.unused_name("DRAWING");
            let Gathered { columns, components, .. } = gathered;
            self.push(&name, "", OutputKind::Drawing { columns }, components);
        }
        Ok(Drawing { newtonian, origin, up, frames, points, bodies })
    }

    /// The root of the largest tree of position relations (the first such point on a tie).
    fn drawing_origin(&self) -> Option<PointId> {
        let count = self.model.points.len();
        let mut members = vec![0usize; count];
        for i in 0..count {
            let chain = self.model.point_chain(PointId(i as u32));
            members[chain.last().expect("a chain holds its point").index()] += 1;
        }
        let most = *members.iter().max()?;
        (0..count).find(|&i| members[i] == most && most > 0).map(|i| PointId(i as u32))
    }

    /// The columns of the position `r` named `name` (`P_O_P`) in Newtonian axes: an output's
    /// of that name already measured there, else gathered (nothing gathered on an error).
    fn drawing_position(&mut self, gathered: &mut Gathered, name: &str, r: &Vector) -> Result<[String; 3]> {
        let n = self.model.newtonian();
        let frame_name = self.model.frame_name(n).to_string();
        let same = |kind: &OutputKind| matches!(kind, OutputKind::Vector { frame } if *frame == frame_name);
        if let Some(k) = self.output_named(name).filter(|k| same(&self.outputs[*k].kind)) {
            return Ok(three(self.outputs[k].columns()));
        }
        let m = self.model.express(r, n)?;
        let m = [self.in_states(m[0])?, self.in_states(m[1])?, self.in_states(m[2])?];
        let names = (1..=3).map(|i| format!("{name}_{frame_name}{i}"));
        Ok(three(self.gather(gathered, names, &m)))
    }

    /// The columns of the direction cosines of `frame` (`N_F`): an output's of that name and
    /// meaning, else gathered.
    fn drawing_orientation(&mut self, gathered: &mut Gathered, frame: FrameId) -> Result<[String; 9]> {
        let n = self.model.newtonian();
        let frame_name = self.model.frame_name(frame).to_string();
        let name = format!("{}_{frame_name}", self.model.frame_name(n));
        let same = |kind: &OutputKind| matches!(kind, OutputKind::Orientation { frame, form: OrientationForm::Dcm } if *frame == frame_name);
        if let Some(k) = self.output_named(&name).filter(|k| same(&self.outputs[*k].kind)) {
            return Ok(nine(self.outputs[k].columns()));
        }
        let dcm = self.model.dcm(n, frame)?;
        let names = (1..=3).flat_map(|i| (1..=3).map(move |j| (i, j))).map(|(i, j)| format!("{name}_{i}{j}"));
        let entries: Vec<ExprId> = dcm.iter().flatten().copied().collect();
        Ok(nine(self.gather(gathered, names, &entries)))
    }

    /// Gathers `components` under `names` (each, when taken, suffixed `_VIEW`, `_VIEW2`, ...),
    /// giving the columns' names.
    fn gather(
        &self,
        gathered: &mut Gathered,
        names: impl Iterator<Item = String>,
        components: &[ExprId],
    ) -> Vec<String> {
        let mut columns = Vec::with_capacity(components.len());
        for name in names {
            let column = first_free(&name, |c| gathered.taken.contains(&c.to_ascii_uppercase()));
            gathered.taken.insert(column.to_ascii_uppercase());
            gathered.columns.push(column.clone());
            columns.push(column);
        }
        gathered.components.extend_from_slice(components);
        columns
    }

    /// The index of the output named `name` (case-insensitive).
    fn output_named(&self, name: &str) -> Option<usize> {
        self.outputs.iter().position(|o| o.name.eq_ignore_ascii_case(name))
    }

    /// `name`, else `name_VIEW`, ...: the first that no output has.
    fn unused_name(&self, name: &str) -> String {
        first_free(name, |candidate| self.output_named(candidate).is_some())
    }

    /// The Newtonian axis against `g` when `g` lies along one axis (its sign from the defaults
    /// when they give it, else taken as pointing down the axis), else 3.
    fn upward_axis(&mut self, g: &Vector) -> Result<i8> {
        let n = self.model.newtonian();
        let m = self.model.express(g, n)?;
        let zero = self.model.ar.zero();
        let along: Vec<(usize, ExprId)> = m.iter().copied().enumerate().filter(|(_, e)| *e != zero).collect();
        let [(axis, component)] = along[..] else { return Ok(3) };
        let ar = &self.model.ar;
        let value_of = |s| self.defaults.get(&ar.symbol_info(s).name.to_ascii_uppercase()).copied();
        let downward_positive = ar.eval::<f64>(&[component], value_of).is_ok_and(|x| x[0] > 0.0);
        let axis = axis as i8 + 1;
        Ok(if downward_positive { -axis } else { axis })
    }
}

/// `name`, else `name_VIEW`, `name_VIEW2`, ...: the first that is not `taken`.
fn first_free(name: &str, taken: impl Fn(&str) -> bool) -> String {
    let suffixed = (1..).map(|k| if k == 1 { format!("{name}_VIEW") } else { format!("{name}_VIEW{k}") });
    std::iter::once(name.to_string())
        .chain(suffixed)
        .find(|candidate| !taken(candidate))
        .expect("an unbounded sequence of names has a free one")
}

fn three(columns: Vec<String>) -> [String; 3] {
    columns.try_into().expect("a position has three columns")
}

fn nine(columns: Vec<String>) -> [String; 9] {
    columns.try_into().expect("direction cosines have nine columns")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A double pendulum hinged at O: rod A from O to P, rod B from P on.
    const DOUBLE: &str = "NEWTONIAN N\nBODIES A, B\nPOINTS O, P\nCONSTANTS L, G, M\nVARIABLES Q{2}', U{2}'\n\
        SIMPROT(N, A, 3, Q1)\nSIMPROT(A, B, 3, Q2)\nQ1' = U1\nQ2' = U2\nP_O_AO> = L/2*A1>\nP_O_P> = L*A1>\n\
        P_P_BO> = L/2*B1>\nV_O_N> = 0>\nV2PTS(N, A, O, AO)\nV2PTS(N, A, O, P)\nV2PTS(N, B, P, BO)\n\
        MASS A = M, B = M\nINERTIA A, 0, 0, M*L^2/12\nINERTIA B, 0, 0, M*L^2/12\nGRAVITY(DOWN)\n\
        ZERO = FR() + FRSTAR()\nKANE()\nINPUT L = 1, G = 9.81, M = 1\n";

    fn drawn(gravity: &str, extra: &str) -> (ModelSpec, Drawing) {
        let text = DOUBLE.replace("DOWN", gravity) + extra;
        crate::lang::load("double.al", &text).unwrap().into_spec_drawn("double").unwrap()
    }

    /// The values of the columns `NAME` and `NAME_suffix` at `q1`, `q2` and L = M = 1.
    fn values(spec: &ModelSpec, name: &str, q1: f64, q2: f64) -> Vec<f64> {
        let output = spec.outputs.iter().find(|o| o.name == "DRAWING").unwrap();
        let picked: Vec<ExprId> = output
            .columns()
            .iter()
            .zip(&output.components)
            .filter(|(c, _)| *c == name || c.starts_with(&format!("{name}_")))
            .map(|(_, e)| *e)
            .collect();
        let ar = &spec.model.ar;
        let value_of = |s| match ar.symbol_info(s).name.as_str() {
            "Q1" => Some(q1),
            "Q2" => Some(q2),
            "L" | "M" => Some(1.0),
            _ => None,
        };
        ar.eval::<f64>(&picked, value_of).unwrap()
    }

    #[test]
    fn frames_stand_at_their_mass_centres_and_points_join_the_points_they_were_located_from() {
        let (_, d) = drawn("-G*N2>", "");
        assert_eq!((d.newtonian.as_str(), d.origin.as_deref(), d.up), ("N", Some("O"), 2));
        let frames: Vec<(&str, Option<&str>, &str)> =
            d.frames.iter().map(|f| (f.name.as_str(), f.at.as_deref(), f.dcm[0].as_str())).collect();
        assert_eq!(frames, [("A", Some("AO"), "N_A_11"), ("B", Some("BO"), "N_B_11")]);
        let points: Vec<(&str, Option<&str>, &str)> =
            d.points.iter().map(|p| (p.name.as_str(), p.from.as_deref(), p.position[2].as_str())).collect();
        assert_eq!(
            points,
            [
                ("AO", Some("O"), "P_O_AO_N3"),
                ("BO", Some("P"), "P_O_BO_N3"),
                ("O", None, "P_O_O_N3"),
                ("P", Some("O"), "P_O_P_N3")
            ]
        );
    }

    #[test]
    fn positions_and_direction_cosines_are_the_hand_derived_ones() {
        let (spec, _) = drawn("-G*N2>", "");
        let (q1, q2) = (0.3, 0.5);
        let bo = values(&spec, "P_O_BO", q1, q2);
        let hand = [q1.cos() + 0.5 * (q1 + q2).cos(), q1.sin() + 0.5 * (q1 + q2).sin(), 0.0];
        for (got, want) in bo.iter().zip(hand) {
            assert!((got - want).abs() < 1e-14, "{bo:?} against {hand:?}");
        }
        let (c, s) = ((q1 + q2).cos(), (q1 + q2).sin());
        let dcm = values(&spec, "N_B", q1, q2);
        let hand = [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0];
        for (got, want) in dcm.iter().zip(hand) {
            assert!((got - want).abs() < 1e-14, "{dcm:?} against {hand:?}");
        }
    }

    #[test]
    fn a_point_placed_through_a_frame_not_oriented_in_n_is_left_out() {
        let (_, d) = drawn("-G*N2>", "FRAMES C\nPOINTS Q\nP_O_Q> = L*C1>\n");
        assert!(!d.points.iter().any(|p| p.name == "Q") && d.points.len() == 4, "{:?}", d.points);
        assert!(!d.frames.iter().any(|f| f.name == "C"));
    }

    #[test]
    fn up_is_against_gravity_with_its_sign_from_the_defaults() {
        assert_eq!(drawn("G*N1>", "").1.up, -1, "G = 9.81 pulls along +N1");
        assert_eq!(drawn("-G*N3>", "").1.up, 3);
        assert_eq!(drawn("-G*N1> - G*N2>", "").1.up, 3, "not along one axis");
    }

    #[test]
    fn each_body_gives_its_mass_and_inertia_in_its_own_axes() {
        let (spec, d) = drawn("-G*N2>", "");
        let a = &d.bodies[0];
        assert_eq!((d.bodies.len(), a.name.as_str(), a.frame.as_str()), (2, "A", "A"));
        assert_eq!(
            (a.mass.as_str(), a.inertia[0].as_str(), a.inertia[5].as_str()),
            ("MASS_A", "I_A_AO_11", "I_A_AO_31")
        );
        let mass_and_inertia =
            values(&spec, "MASS_B", 0.3, 0.5).into_iter().chain(values(&spec, "I_B_BO", 0.3, 0.5));
        let hand = [1.0, 0.0, 0.0, 1.0 / 12.0, 0.0, 0.0, 0.0];
        for (got, want) in mass_and_inertia.zip(hand) {
            assert!((got - want).abs() < 1e-14, "{got} against {want}");
        }
    }

    #[test]
    fn a_body_with_products_of_inertia_gives_them_and_one_without_mass_or_moments_is_left_out() {
        let with_products = DOUBLE
            .replace("DOWN", "-G*N2>")
            .replace("INERTIA B, 0, 0, M*L^2/12", "INERTIA B, 1, 2, 3, 4, 5, 6");
        let (spec, d) = crate::lang::load("double.al", &with_products).unwrap().into_spec_drawn("d").unwrap();
        assert_eq!(values(&spec, "I_B_BO", 0.3, 0.5), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(d.bodies.len(), 2);
        let massless = DOUBLE.replace("DOWN", "-G*N2>").replace("MASS A = M, B = M", "MASS A = 0, B = M");
        let (_, d) = crate::lang::load("double.al", &massless).unwrap().into_spec_drawn("d").unwrap();
        let names: Vec<&str> = d.bodies.iter().map(|b| b.name.as_str()).collect();
        assert_eq!(names, ["B"]);
    }

    #[test]
    fn an_output_of_the_same_name_and_meaning_is_reused_and_one_of_another_is_not() {
        let (spec, d) = drawn("-G*N2>", "P_O_AO_N1 = L\nOUTPUT N_A, P_O_AO_N1\n");
        assert_eq!(d.frames[0].dcm[8], "N_A_33", "the file's own N_A");
        assert_eq!(d.points[0].position[0], "P_O_AO_N1_VIEW", "not the file's scalar");
        let drawing = spec.outputs.iter().find(|o| o.name == "DRAWING").unwrap();
        assert!(!drawing.columns().iter().any(|c| c.starts_with("N_A_")));
        assert_eq!(drawing.columns().len(), drawing.components.len());
    }
}
