//! A loaded model file as a spec: in comes a [`LoadedModel`]; out goes a [`ModelSpec`] with the
//! file's equations, INPUT defaults, UNITS, its OUTPUT scalars and the kinetic energy.

use crate::codegen::CodegenError;
use crate::spec::ModelSpec;

use super::{LoadedModel, Value};

impl LoadedModel {
    /// The spec of this model file, named `name` (the model moves into it).
    pub fn into_spec(self, name: &str) -> Result<ModelSpec, CodegenError> {
        let eqs = self.equations.clone().ok_or(CodegenError::NoEquations)?;
        let outputs = self.output_values(&eqs)?;
        let mut spec = ModelSpec::new(name, self.model, eqs);
        for input in &self.inputs {
            spec.set_default(&input.name, input.value);
        }
        for (name, unit) in &self.units {
            spec.set_unit(name, unit);
        }
        let n = spec.model.newtonian();
        for (oname, value) in outputs {
            let unit = spec.unit(&oname).to_string();
            let oname = oname.as_str();
            match value {
                Value::Vector(v) => spec.add_vector(oname, &v, n, &unit)?,
                Value::Scalar(e) => spec.add_scalar(oname, e, &unit),
                _ => return Err(CodegenError::UnknownOutput(oname.to_string())),
            }
        }
        if !spec.outputs.iter().any(|o| o.name.eq_ignore_ascii_case("KE")) {
            let unit = spec.unit("KE").to_string();
            spec.add_kinetic_energy("KE", &unit)?;
        }
        Ok(spec)
    }

    /// The OUTPUT names other than `T` and the states, each a scalar or a vector (`L>`, written
    /// in the Newtonian frame) of the model; names without the `>`.
    fn output_values(
        &self,
        eqs: &crate::mechanics::KaneEquations,
    ) -> Result<Vec<(String, Value)>, CodegenError> {
        let mut out = Vec::new();
        for (oname, _) in &self.outputs {
            let is_state = eqs
                .coordinates
                .iter()
                .chain(&eqs.speeds)
                .any(|s| self.model.ar.symbol_info(*s).name.eq_ignore_ascii_case(oname));
            if oname.eq_ignore_ascii_case("T") || is_state {
                continue;
            }
            let bare = oname.trim_end_matches('>');
            match self.value(oname).or_else(|| self.value(&format!("{bare}>"))) {
                Some(v @ (Value::Scalar(_) | Value::Vector(_))) => out.push((bare.to_string(), v)),
                _ => return Err(CodegenError::UnknownOutput(oname.clone())),
            }
        }
        Ok(out)
    }
}
