//! What to generate, built from mechanics: in come a [`Model`] and its [`KaneEquations`]; out
//! goes a [`ModelSpec`] (equations, parameter and state defaults with units, a typed output list)
//! that [`crate::codegen`] lowers and prints. The model language builds one from a model file
//! ([`crate::lang::LoadedModel::into_spec`]); a Rust-API model builds one by hand.

mod drawing;
mod inertia_ellipsoid;
mod outputs;

use rustc_hash::FxHashMap;

use crate::expr::{ExprId, SymbolId};
use crate::mechanics::{KaneEquations, Model};

pub use drawing::{Drawing, DrawnBody, DrawnFrame, DrawnPoint};
pub use inertia_ellipsoid::{inertia_ellipsoid, InertiaEllipsoid};
pub use outputs::{OrientationForm, OutputKind, OutputSpec};

/// Everything code generation needs: the equations, defaults, units and outputs of one model.
pub struct ModelSpec {
    /// The model's name (the generated module's `NAME`).
    pub name: String,
    /// The mechanics model that owns every expression.
    pub model: Model,
    /// `q' = kinematics`, `M u' = f`.
    pub equations: KaneEquations,
    /// Default values by upper-case name (parameters and initial states), in model units
    /// (radians for angles).
    pub defaults: FxHashMap<String, f64>,
    /// Units by upper-case name (`DEG`, `RAD/SEC`, `KG`, ...).
    pub units: FxHashMap<String, String>,
    /// The outputs, in order.
    pub outputs: Vec<OutputSpec>,
    /// Quantities of time the model leaves to its user (SPECIFIED without a formula): read as
    /// parameters of the generated code.
    pub inputs: Vec<SymbolId>,
    /// The inputs with no default value (zero in the generated code).
    pub open_inputs: Vec<SymbolId>,
}

impl ModelSpec {
    /// A spec with no defaults, units or outputs yet.
    pub fn new(name: &str, model: Model, equations: KaneEquations) -> ModelSpec {
        ModelSpec {
            name: name.to_string(),
            model,
            equations,
            defaults: FxHashMap::default(),
            units: FxHashMap::default(),
            outputs: Vec::new(),
            inputs: Vec::new(),
            open_inputs: Vec::new(),
        }
    }

    /// Sets the default value of a parameter or state (model units).
    pub fn set_default(&mut self, name: &str, value: f64) {
        self.defaults.insert(name.to_ascii_uppercase(), value);
    }

    /// Sets the unit of a parameter, state or output.
    pub fn set_unit(&mut self, name: &str, unit: &str) {
        self.units.insert(name.to_ascii_uppercase(), unit.to_string());
    }

    /// The unit of `name` (empty when none).
    pub fn unit(&self, name: &str) -> &str {
        self.units.get(&name.to_ascii_uppercase()).map_or("", String::as_str)
    }

    /// The default of `name`, if any.
    pub fn default_of(&self, name: &str) -> Option<f64> {
        self.defaults.get(&name.to_ascii_uppercase()).copied()
    }

    /// Makes `s` an input of the model: a parameter of the generated code, zero unless given
    /// a default.
    pub fn add_input(&mut self, s: SymbolId) {
        if self.inputs.contains(&s) {
            return;
        }
        self.inputs.push(s);
        let name = self.symbol_name(s).to_string();
        if self.default_of(&name).is_none() {
            self.open_inputs.push(s);
            self.set_default(&name, 0.0);
        }
    }

    /// The states: coordinates, then speeds.
    pub fn states(&self) -> Vec<SymbolId> {
        self.equations.coordinates.iter().chain(&self.equations.speeds).copied().collect()
    }

    /// The name of a symbol.
    pub fn symbol_name(&self, s: SymbolId) -> &str {
        &self.model.ar.symbol_info(s).name
    }

    /// `e` with `q'` replaced through the kinematic equations (dependent speeds stay: they are
    /// solved numerically where `e` is evaluated).
    pub fn in_states(&mut self, e: ExprId) -> crate::mechanics::Result<ExprId> {
        let eqs = &self.equations;
        let ar = &mut self.model.ar;
        let mut map = FxHashMap::default();
        for (q, rhs) in eqs.coordinates.iter().zip(&eqs.kinematics) {
            let name = format!("{}'", ar.symbol_info(*q).name);
            if let Some(d) = ar.lookup(&name) {
                map.insert(ar.symbol_expr(d), *rhs);
            }
        }
        Ok(ar.subs(e, &map)?)
    }
}
