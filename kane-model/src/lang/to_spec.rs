//! A loaded model file as a spec: in comes a [`LoadedModel`]; out goes a [`ModelSpec`] with the
//! file's equations, INPUT defaults, UNITS, its OUTPUT scalars and the kinetic energy.

use crate::codegen::CodegenError;
use crate::expr::ExprId;
use crate::spec::ModelSpec;

use super::{LoadedModel, Value};

impl LoadedModel {
    /// The spec of this model file, named `name` (the model moves into it).
    pub fn into_spec(self, name: &str) -> Result<ModelSpec, CodegenError> {
        let eqs = self.equations.clone().ok_or(CodegenError::NoEquations)?;
        let scalars = self.output_scalars(&eqs)?;
        let mut spec = ModelSpec::new(name, self.model, eqs);
        for input in &self.inputs {
            spec.set_default(&input.name, input.value);
        }
        for (name, unit) in &self.units {
            spec.set_unit(name, unit);
        }
        for (oname, e) in scalars {
            let unit = spec.unit(&oname).to_string();
            spec.add_scalar(&oname, e, &unit);
        }
        if !spec.outputs.iter().any(|o| o.name.eq_ignore_ascii_case("KE")) {
            let unit = spec.unit("KE").to_string();
            spec.add_kinetic_energy("KE", &unit)?;
        }
        Ok(spec)
    }

    /// The OUTPUT names other than `T` and the states, each a scalar of the model.
    fn output_scalars(
        &self,
        eqs: &crate::mechanics::KaneEquations,
    ) -> Result<Vec<(String, ExprId)>, CodegenError> {
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
            match self.value(oname) {
                Some(Value::Scalar(e)) => out.push((oname.clone(), e)),
                _ => return Err(CodegenError::UnknownOutput(oname.clone())),
            }
        }
        Ok(out)
    }
}
