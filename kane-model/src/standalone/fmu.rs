//! An FMI 2.0 Functional Mock-up Unit for Model Exchange and Co-Simulation, as text: in comes a
//! [`Plan`]; out go its `modelDescription.xml` and one C source (the C program's `constants`,
//! `rhs` and outputs, its integrator for Co-Simulation's steps, and the FMI functions). The
//! caller compiles and zips them. Values are in internal units (SI, angles in radians), each
//! with its SI unit and the file's UNITS as its display unit.

use super::c::{self, C};
use super::fmu_units::{escape, Units};
use super::plan::{Plan, Source};
use super::{Program, StandaloneError};

/// The two texts of an FMU.
pub struct FmuText {
    /// `modelDescription.xml`.
    pub model_description: String,
    /// `sources/IDENTIFIER.c`.
    pub source: String,
    /// The model identifier (the shared library's and the source's name).
    pub identifier: String,
}

/// One scalar variable of the model description.
struct Variable {
    name: String,
    causality: &'static str,
    variability: &'static str,
    initial: Option<&'static str>,
    start: Option<f64>,
    derivative_of: Option<usize>,
    description: String,
    unit: String,
}

/// The FMU of `plan`: parameters (open inputs as inputs), states, their derivatives and the
/// OUTPUT quantities that are not states, in that order of value references.
pub(super) fn fmu(plan: &Plan<'_>, about: &Program) -> Result<FmuText, StandaloneError> {
    let missing = plan.missing();
    if !missing.is_empty() {
        return Err(StandaloneError::NoValue(missing.join(", ")));
    }
    let outputs: Vec<_> =
        plan.columns.iter().filter(|c| matches!(c.source, Source::Output(..))).cloned().collect();
    let internal = outputs.iter().map(|c| super::WrittenColumn { scale: 1.0, ..c.clone() }).collect();
    let fmu_plan = Plan { columns: internal, ..plan.clone() };
    let variables = variables(&fmu_plan);
    let description = model_description(&fmu_plan, &variables, &about.identifier, "GUID");
    let guid = guid(&description);
    let model_description = description.replace("GUID", &guid);
    let source = source(&fmu_plan, &about.identifier, &guid);
    Ok(FmuText { model_description, source, identifier: about.identifier.clone() })
}

fn variables(plan: &Plan<'_>) -> Vec<Variable> {
    let info = plan.info;
    let start = plan.start_params();
    let mut out = Vec::new();
    for (i, name) in info.param_names.iter().enumerate() {
        let input = info.open_inputs.contains(&i) || info.inputs.contains(&i);
        out.push(Variable {
            name: name.to_string(),
            causality: if input { "input" } else { "parameter" },
            variability: if input { "continuous" } else { "fixed" },
            initial: None,
            start: Some(start[i]),
            derivative_of: None,
            description: if input { "a SPECIFIED input".into() } else { "a constant".into() },
            unit: info.param_units[i].to_string(),
        });
    }
    for (i, name) in info.state_names.iter().enumerate() {
        out.push(Variable {
            name: name.to_string(),
            causality: "local",
            variability: "continuous",
            initial: Some("exact"),
            start: Some(plan.initial[i]),
            derivative_of: None,
            description: if i < info.n_coordinates { "a coordinate" } else { "a speed" }.into(),
            unit: info.state_units[i].to_string(),
        });
    }
    for (i, name) in info.state_names.iter().enumerate() {
        out.push(Variable {
            name: format!("der({name})"),
            causality: "local",
            variability: "continuous",
            initial: Some("calculated"),
            start: None,
            derivative_of: Some(info.param_names.len() + i + 1),
            description: format!("the rate of {name}"),
            unit: String::new(),
        });
    }
    for column in &plan.columns {
        let Source::Output(k, j) = column.source else { continue };
        let o = &info.outputs[k];
        out.push(Variable {
            name: o.columns[j].to_string(),
            causality: "output",
            variability: "continuous",
            initial: Some("calculated"),
            start: None,
            derivative_of: None,
            description: format!("OUTPUT {}", o.name),
            unit: o.unit.to_string(),
        });
    }
    out
}

/// An importer's solver at the file's RELERR errs by far more than the file asks: its global
/// error grows two to three orders past a BDF method's relative tolerance (FMPy's CVode on the
/// gimbal: 2.6e-5 at 1e-7, 1.9e-7 at 1e-10). The default experiment asks for a thousandth of it.
const IMPORTER_TOLERANCE_FACTOR: f64 = 1e-3;

/// The default experiment's tolerance for a file whose RELERR is `rtol`.
fn importer_tolerance(rtol: f64) -> f64 {
    (rtol * IMPORTER_TOLERANCE_FACTOR).max(1e-13)
}

fn model_description(plan: &Plan<'_>, variables: &[Variable], id: &str, guid: &str) -> String {
    let s = plan.settings;
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.push_str(&format!(
        "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"{id}\" guid=\"{guid}\" generationTool=\"kane\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n"
    ));
    x.push_str(&format!("  <ModelExchange modelIdentifier=\"{id}\">\n    <SourceFiles><File name=\"{id}.c\"/></SourceFiles>\n  </ModelExchange>\n"));
    x.push_str(&format!("  <CoSimulation modelIdentifier=\"{id}\" canHandleVariableCommunicationStepSize=\"true\">\n    <SourceFiles><File name=\"{id}.c\"/></SourceFiles>\n  </CoSimulation>\n"));
    let mut units = Units::default();
    let attributes: Vec<String> = variables.iter().map(|v| units.attributes(&v.unit)).collect();
    x.push_str(&units.definitions());
    x.push_str(&format!(
        "  <DefaultExperiment startTime=\"0\" stopTime=\"{:?}\" tolerance=\"{:?}\" stepSize=\"{:?}\"/>\n",
        s.t_final,
        importer_tolerance(s.rtol),
        s.output_step
    ));
    x.push_str("  <ModelVariables>\n");
    for (i, v) in variables.iter().enumerate() {
        x.push_str(&format!(
            "    <!-- index {} -->\n    <ScalarVariable name=\"{}\" valueReference=\"{i}\" description=\"{}\" causality=\"{}\" variability=\"{}\"{}>\n      <Real{}{}{}/>\n    </ScalarVariable>\n",
            i + 1,
            escape(&v.name),
            escape(&v.description),
            v.causality,
            v.variability,
            v.initial.map_or(String::new(), |i| format!(" initial=\"{i}\"")),
            v.start.map_or(String::new(), |s| format!(" start=\"{s:?}\"")),
            v.derivative_of.map_or(String::new(), |d| format!(" derivative=\"{d}\"")),
            attributes[i],
        ));
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n");
    let indices = |f: &dyn Fn(&Variable) -> bool| -> Vec<usize> {
        variables.iter().enumerate().filter(|(_, v)| f(v)).map(|(i, _)| i + 1).collect()
    };
    let unknowns = |x: &mut String, tag: &str, list: &[usize]| {
        if !list.is_empty() {
            x.push_str(&format!("    <{tag}>\n"));
            list.iter().for_each(|i| x.push_str(&format!("      <Unknown index=\"{i}\"/>\n")));
            x.push_str(&format!("    </{tag}>\n"));
        }
    };
    let outputs = indices(&|v| v.causality == "output");
    let derivatives = indices(&|v| v.derivative_of.is_some());
    unknowns(&mut x, "Outputs", &outputs);
    unknowns(&mut x, "Derivatives", &derivatives);
    unknowns(&mut x, "InitialUnknowns", &indices(&|v| v.initial == Some("calculated")));
    x.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

/// A GUID from the model description's text (the same text, the same GUID).
fn guid(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut g: u64 = 0x8422_2325_cbf2_9ce4;
    for b in text.bytes() {
        h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        g = (g ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3).rotate_left(5);
    }
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        h >> 32,
        (h >> 16) & 0xffff,
        h & 0xffff,
        g >> 48,
        g & 0xffff_ffff_ffff
    )
}

/// The C source: the model's functions (static), the integrator and the FMI functions.
fn source(plan: &Plan<'_>, id: &str, guid: &str) -> String {
    let c = C { n_coordinates: plan.info.n_coordinates };
    let (ny, np) = (plan.info.state_names.len(), plan.params.len());
    let nk = plan.program.param_constants.results.len().max(1);
    let mut out = format!(
        "/* The FMI 2.0 model {id}: generated by kane, do not edit by hand. */\n#include <math.h>\n#include <stdarg.h>\n#include <stddef.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\nenum {{ NY = {ny}, NP = {np}, NK = {nk}, NCOL = {} }};\n\n",
        plan.columns.len()
    );
    out.push_str(&c::functions(plan, &c, id).replace("\nvoid ", "\nstatic void "));
    let p0: Vec<String> = plan.start_params().iter().map(|v| format!("{v:?}")).collect();
    let y0: Vec<String> = plan.initial.iter().map(|v| format!("{v:?}")).collect();
    let s = plan.settings;
    out.push_str(&format!(
        "static const double P0[NP > 0 ? NP : 1] = {{ {} }};\nstatic const double Y0[NY] = {{ {} }};\nstatic const double RTOL = {:?}, ATOL = {:?};\n\n",
        if p0.is_empty() { "0.0".into() } else { p0.join(", ") },
        y0.join(", "),
        s.rtol,
        s.atol
    ));
    out.push_str(&c::INTEGRATOR.replace("MODEL", id));
    out.push_str(&super::fmi::FMI2.replace("MODEL", id).replace("GUID_TEXT", guid));
    out
}
