//! Printing vectors and the partial velocity table (the paper's Table 1).

use super::error::Result;
use super::ids::{FrameId, PointId};
use super::model::Model;
use super::vector::Vector;

impl Model {
    /// A vector as Autolev text, for example `-u1*B2> + L*u3*D3>`.
    pub fn vector_to_text(&self, v: &Vector) -> String {
        let mut parts: Vec<String> = Vec::new();
        for (f, m) in &v.terms {
            for (i, x) in m.iter().enumerate() {
                if self.ar.is_zero(*x) {
                    continue;
                }
                let unit = format!("{}{}>", self.frame_name(*f), i + 1);
                let coeff = self.ar.to_text(*x);
                parts.push(match coeff.as_str() {
                    "1" => unit,
                    "-1" => format!("-{unit}"),
                    c if c.contains([' ', '+']) => format!("({c})*{unit}"),
                    c => format!("{c}*{unit}"),
                });
            }
        }
        if parts.is_empty() {
            return "0>".to_string();
        }
        parts.join(" + ").replace("+ -", "- ")
    }

    /// The partial angular velocities of `frames` and partial velocities of `points` in the
    /// Newtonian frame, one line per entity and speed (the dependent speeds last, constraints
    /// aside): `W_B_A> / u1 = -B2>`.
    pub fn partial_velocity_table(&mut self, frames: &[FrameId], points: &[PointId]) -> Result<String> {
        let n = self.newtonian;
        let speeds = self.kane_speeds();
        let mut out = String::new();
        for &f in frames {
            let rows = self.partial_angular_velocities(f)?;
            for (u, v) in speeds.iter().zip(&rows) {
                out.push_str(&format!(
                    "W_{}_{}> / {} = {}\n",
                    self.frame_name(f),
                    self.frame_name(n),
                    self.ar.symbol_info(*u).name,
                    self.vector_to_text(v)
                ));
            }
        }
        for &p in points {
            let rows = self.partial_velocities(p)?;
            for (u, v) in speeds.iter().zip(&rows) {
                out.push_str(&format!(
                    "V_{}_{}> / {} = {}\n",
                    self.point_name(p),
                    self.frame_name(n),
                    self.ar.symbol_info(*u).name,
                    self.vector_to_text(v)
                ));
            }
        }
        Ok(out)
    }
}
