//! A loaded model file as a spec: in comes a [`LoadedModel`]; out goes a [`ModelSpec`] with the
//! file's equations, INPUT defaults, UNITS, its OUTPUT scalars, the residuals of its
//! configuration and motion constraints (`CONFIG`, `CONSTRAINT`) and the kinetic energy.

use thiserror::Error;

use crate::mechanics::{FrameId, KaneEquations};
use crate::spec::{Drawing, ModelSpec, OrientationForm};

use super::{LoadedModel, Value};

/// Why a loaded model file has no spec.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SpecError {
    /// An OUTPUT name that is not a scalar or vector the model defines.
    #[error("OUTPUT `{0}` is not a state, nor a scalar or vector defined in the model")]
    UnknownOutput(String),
    /// An expression operation failed.
    #[error(transparent)]
    Expr(#[from] crate::expr::ExprError),
    /// A mechanics operation failed.
    #[error(transparent)]
    Mechanics(#[from] crate::mechanics::MechanicsError),
}

impl LoadedModel {
    /// The spec of this model file, named `name` (the model moves into it).
    pub fn into_spec(self, name: &str) -> Result<ModelSpec, SpecError> {
        Ok(self.spec_with(name, false)?.0)
    }

    /// The spec of this model file with the outputs of its default drawing, and that drawing.
    pub fn into_spec_drawn(self, name: &str) -> Result<(ModelSpec, Drawing), SpecError> {
        let (spec, drawing) = self.spec_with(name, true)?;
        Ok((spec, drawing.expect("asked for")))
    }

    /// The spec, with the default drawing's outputs when `drawn`.
    fn spec_with(mut self, name: &str, drawn: bool) -> Result<(ModelSpec, Option<Drawing>), SpecError> {
        let mut formulas = super::interp::specified_formulas(&mut self.model, &self.formulas)?;
        // A file without dynamics: its code computes OUTPUT and ENCODE quantities from inputs
        // (coordinates, speeds and their rates among them), as Autolev's CODE ALGEBRAIC() does.
        // One whose CODE DYNAMICS() integrates the variables whose rates it assigns has those
        // rates as its equations.
        let integrates = self.code.iter().any(|c| matches!(c.kind.as_str(), "DYNAMICS" | "ODE"));
        let algebraic = self.equations.is_none() && !self.forces_formed && !integrates;
        let formed = self.equations.is_some() || self.forces_formed;
        let mut eqs = match self.equations.clone() {
            Some(eqs) => eqs,
            // FR() + FRSTAR() formed without KANE() or SOLVE (a file that writes its residuals
            // for CODE ALGEBRAIC): the equations of motion are KANE()'s.
            None if self.forces_formed => {
                let mut eqs = self.model.kane()?;
                eqs.substitute(&mut self.model.ar, &formulas)?;
                eqs
            }
            None if !algebraic => KaneEquations::none(),
            None => {
                for name in std::mem::take(&mut self.encoded) {
                    if !self.outputs.iter().any(|(o, _)| o.eq_ignore_ascii_case(&name)) {
                        self.outputs.push((name, None));
                    }
                }
                KaneEquations::none()
            }
        };
        if !algebraic {
            self.extra_coordinates(&mut eqs, &formulas)?;
        }
        // Auxiliary speeds are zero in every motion the outputs are computed along.
        let auxiliary = self.model.auxiliary_zero_map()?;
        // A coordinate whose rate is an auxiliary speed (`Q1' = U1`, AUXILIARY[1] = U1) is still.
        eqs.kinematics = self.model.ar.subs_many(&eqs.kinematics, &auxiliary)?;
        formulas.extend(auxiliary);
        let outputs = self.output_values(&eqs)?;
        let inputs = self.open_quantities(&formulas);
        let mut spec = ModelSpec::new(name, self.model, eqs);
        for input in &self.inputs {
            spec.set_default(&input.name, input.value);
        }
        for s in inputs {
            spec.add_input(s);
        }
        for (name, unit) in &self.units {
            spec.set_unit(name, unit);
        }
        let n = spec.model.newtonian();
        for (oname, value) in outputs {
            let unit = spec.unit(&oname).to_string();
            let oname = oname.as_str();
            match value {
                Output::Value(Value::Vector(v)) => spec.add_vector(oname, &v, n, &unit)?,
                Output::Value(Value::Scalar(e)) => spec.add_scalar(oname, e, &unit),
                // A matrix: one scalar per entry, `M_1_2` (a column's: `M_2`).
                Output::Value(Value::Matrix { rows, cols, data }) => {
                    for (k, e) in data.into_iter().enumerate() {
                        spec.add_scalar(&matrix_entry_name(oname, rows, cols, k), e, &unit);
                    }
                }
                Output::Orientation(f) => spec.add_orientation(oname, f, OrientationForm::Dcm)?,
                Output::Value(_) => return Err(SpecError::UnknownOutput(oname.to_string())),
            }
        }
        spec.add_configuration_residuals("CONFIG", "")?;
        spec.add_motion_residuals("CONSTRAINT", "");
        spec.add_constraint_matrix("CONSTRAINT_MATRIX");
        if formed && !spec.outputs.iter().any(|o| o.name.eq_ignore_ascii_case("KE")) {
            let unit = spec.unit("KE").to_string();
            spec.add_kinetic_energy("KE", &unit)?;
            if let Some(g) = self.gravity.as_ref().filter(|_| gravity_is_the_only_load(&spec.model)) {
                add_gravity_potential(&mut spec, g);
            }
        }
        let drawing = if drawn { Some(spec.add_drawing(self.gravity.as_ref())?) } else { None };
        finish_outputs(&mut spec, &formulas, formed, algebraic)?;
        Ok((spec, drawing))
    }
}

/// Whether the model's loads are gravity on every mass and nothing else (then the potential of
/// gravity is that of every load).
fn gravity_is_the_only_load(model: &crate::mechanics::Model) -> bool {
    let loads = model.loads();
    loads.len() == model.masses().count()
        && loads.iter().all(|l| matches!(l, crate::mechanics::Load::Force { .. }))
}

/// The potential energy of gravity `g` as the output `PE`, zero at the point every mass is
/// located from when that point is at rest in N; nothing when there is no such point (the
/// potential is then not known).
fn add_gravity_potential(spec: &mut ModelSpec, g: &crate::mechanics::Vector) {
    if spec.outputs.iter().any(|o| o.name.eq_ignore_ascii_case("PE")) {
        return;
    }
    let Some(first) = spec.model.masses().next() else { return };
    let Some(&root) = spec.model.point_chain(first.point).last() else { return };
    let n = spec.model.newtonian();
    let at_rest = spec
        .model
        .velocity(root, n)
        .and_then(|v| spec.model.express(&v, n))
        .is_ok_and(|v| v.iter().all(|c| spec.model.ar.is_zero(*c)));
    if at_rest {
        let unit = spec.unit("KE").to_string();
        // A mass located from another root has no position from this one: no potential.
        let _ = spec.add_potential_energy("PE", g, root, &unit);
    }
}

/// The outputs with the formulas put in; for a file that assigns its rates, those rates read
/// through one another; for a file without dynamics, every variable they read an input.
fn finish_outputs(
    spec: &mut ModelSpec,
    formulas: &rustc_hash::FxHashMap<crate::expr::ExprId, crate::expr::ExprId>,
    formed: bool,
    algebraic: bool,
) -> Result<(), SpecError> {
    for o in &mut spec.outputs {
        o.components = spec.model.ar.subs_many(&o.components, formulas)?;
    }
    if !formed && !algebraic {
        // Rates the file assigned (and their rates, `Q''`), read by their equations.
        let mut second = rustc_hash::FxHashMap::default();
        for k in 0..spec.equations.coordinates.len() {
            let name = format!("{}''", spec.symbol_name(spec.equations.coordinates[k]));
            if let Some(d2) = spec.model.ar.lookup(&name) {
                let rate = spec.model.dt(spec.equations.kinematics[k])?;
                second.insert(spec.model.ar.symbol_expr(d2), rate);
            }
        }
        let mut outputs = std::mem::take(&mut spec.outputs);
        for o in &mut outputs {
            o.components = spec.model.ar.subs_many(&o.components, &second)?;
            for c in &mut o.components {
                *c = spec.in_states(*c)?;
            }
        }
        spec.outputs = outputs;
    }
    if algebraic {
        let computed: Vec<_> = spec.outputs.iter().flat_map(|o| o.components.iter().copied()).collect();
        for s in spec.model.ar.free_symbols(&computed) {
            if matches!(spec.model.ar.symbol_info(s).kind, crate::expr::SymbolKind::Variable { .. }) {
                spec.add_input(s);
            }
        }
    }
    Ok(())
}

impl LoadedModel {
    /// Variables whose rates the file gives after its equations of motion were formed
    /// (`POSA1' = DOT(V_DISKAO_N>, N1>)` after KANE()), added to `eqs`' coordinates: Autolev's
    /// code integrates every variable whose rate is assigned. The SPECIFIED quantities'
    /// `formulas` are put into their rates as into the equations.
    fn extra_coordinates(
        &mut self,
        eqs: &mut crate::mechanics::KaneEquations,
        formulas: &rustc_hash::FxHashMap<crate::expr::ExprId, crate::expr::ExprId>,
    ) -> Result<(), SpecError> {
        let states: Vec<crate::expr::SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
        let dependent: Vec<crate::expr::SymbolId> =
            eqs.constraints.iter().flat_map(|c| c.dependent.clone()).collect();
        let mut extra: Vec<crate::expr::SymbolId> = self
            .model
            .coordinates_with_kinematics()
            .into_iter()
            .filter(|q| !states.contains(q) && !dependent.contains(q))
            .collect();
        if extra.is_empty() {
            return Ok(());
        }
        extra.sort();
        let map = self.model.kinematics_map();
        for q in extra {
            let rhs = self.model.kinematics(q).expect("listed with its equation");
            let rhs = self.model.ar.subs(rhs, &map)?;
            eqs.kinematics.push(self.model.ar.subs(rhs, formulas)?);
            eqs.coordinates.push(q);
        }
        Ok(())
    }

    /// The quantities of time the file leaves to its user: SPECIFIED quantities (and rates)
    /// without a formula, and VARIABLES declared without a derivative that are not states (a
    /// file's parameters that may vary, as Autolev's code takes them).
    fn open_quantities(
        &self,
        formulas: &rustc_hash::FxHashMap<crate::expr::ExprId, crate::expr::ExprId>,
    ) -> Vec<crate::expr::SymbolId> {
        let ar = &self.model.ar;
        let given: Vec<crate::expr::SymbolId> = formulas.keys().filter_map(|e| ar.as_symbol(*e)).collect();
        let mut out: Vec<crate::expr::SymbolId> = ar
            .symbols()
            .filter(|(s, info)| {
                matches!(info.kind, crate::expr::SymbolKind::Specified { .. }) && !given.contains(s)
            })
            .map(|(s, _)| s)
            .collect();
        for v in self.unstated_variables() {
            out.push(v);
            let name = format!("{}'", ar.symbol_info(v).name);
            out.extend(ar.lookup(&name));
        }
        out
    }

    /// The OUTPUT names other than `T` and the states, each a scalar or a vector (`L>`, written
    /// in the Newtonian frame) of the model, or a direction-cosine matrix `N_B` (`N` the
    /// Newtonian frame, `B` a frame; entries `N_B_ij = n_i . b_j`); names without the `>`.
    fn output_values(
        &mut self,
        eqs: &crate::mechanics::KaneEquations,
    ) -> Result<Vec<(String, Output)>, SpecError> {
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
            // A speed's rate (independent or dependent): computed where the output is.
            let rates =
                eqs.speed_derivatives.iter().chain(eqs.constraints.iter().flat_map(|c| &c.dependent_rates));
            if let Some(r) =
                rates.copied().find(|s| self.model.ar.symbol_info(*s).name.eq_ignore_ascii_case(oname))
            {
                let e = self.model.ar.symbol_expr(r);
                out.push((bare.to_string(), Output::Value(Value::Scalar(e))));
                continue;
            }
            // A coordinate's rate: its kinematic equation.
            let rate_of = |q: &crate::expr::SymbolId| {
                let name = &self.model.ar.symbol_info(*q).name;
                oname.len() == name.len() + 1
                    && oname.ends_with('\'')
                    && oname[..name.len()].eq_ignore_ascii_case(name)
            };
            if let Some(k) = eqs.coordinates.iter().position(rate_of) {
                out.push((bare.to_string(), Output::Value(Value::Scalar(eqs.kinematics[k]))));
                continue;
            }
            let dependent = eqs.constraints.iter().flat_map(|c| &c.dependent);
            let loads = eqs.loads.iter().flat_map(|l| &l.loads);
            let solved = dependent.chain(loads);
            if solved.map(|s| &self.model.ar.symbol_info(*s).name).any(|n| n.eq_ignore_ascii_case(oname)) {
                // A dependent speed or a load KANE solves for: solved where the output is computed.
                if let Some(super::interp::Binding::Symbol(e, _)) =
                    self.bindings.get(&oname.to_ascii_uppercase())
                {
                    out.push((bare.to_string(), Output::Value(Value::Scalar(*e))));
                    continue;
                }
            }
            if let Some(super::interp::Binding::Symbol(e, _)) = self.bindings.get(&oname.to_ascii_uppercase())
            {
                // A quantity (a SPECIFIED one's formula is put in below).
                out.push((bare.to_string(), Output::Value(Value::Scalar(*e))));
                continue;
            }
            match self.value(oname).or_else(|| self.value(&format!("{bare}>"))) {
                Some(v @ (Value::Scalar(_) | Value::Vector(_) | Value::Matrix { .. })) => {
                    out.push((bare.to_string(), Output::Value(v)))
                }
                _ => match (self.newtonian_dcm_of(oname), self.model.ar.lookup(oname)) {
                    (Some(f), _) => out.push((bare.to_string(), Output::Orientation(f))),
                    // A quantity's rate the file names (`RH'` of a SPECIFIED RH).
                    (None, Some(s)) => out
                        .push((bare.to_string(), Output::Value(Value::Scalar(self.model.ar.symbol_expr(s))))),
                    (None, None) => return Err(SpecError::UnknownOutput(oname.clone())),
                },
            }
        }
        Ok(out)
    }
}

/// What one OUTPUT name computes.
enum Output {
    /// A scalar or a vector.
    Value(Value),
    /// The direction cosines of a frame in the Newtonian frame.
    Orientation(FrameId),
}

impl LoadedModel {
    /// The frame `B` when `name` is `N_B` with `N` the Newtonian frame (Autolev's name for the
    /// direction-cosine matrix).
    fn newtonian_dcm_of(&self, name: &str) -> Option<FrameId> {
        let n = self.model.newtonian();
        let (first, second) = name.split_once('_')?;
        let newtonian = self.model.frame_name(n).eq_ignore_ascii_case(first);
        let frame = self.model.frame(&second.to_ascii_uppercase()).or_else(|| self.model.frame(second))?;
        newtonian.then_some(frame)
    }
}

/// The name an OUTPUT matrix's entry `k` (row by row) takes: `M_1_2`, or `M_2` in a row or a
/// column.
pub(crate) fn matrix_entry_name(name: &str, rows: usize, cols: usize, k: usize) -> String {
    if cols == 1 || rows == 1 {
        format!("{name}_{}", k + 1)
    } else {
        format!("{name}_{}_{}", k / cols + 1, k % cols + 1)
    }
}
