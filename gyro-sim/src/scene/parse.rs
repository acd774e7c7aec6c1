//! Reading a scene: in comes a TOML file's text; out goes a validated [`Scene`], or a
//! [`SceneError`] at the file's line and column. Everything that needs no model is checked here
//! (times, the integrator and its method, units, the `[axle]`, `[[events]]` and `[[controls]]`
//! tables); names are checked against the model when the scene is resolved.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use super::controls::ControlFile;
use super::event_decls::{self, EventFile};
use super::grid::too_many_rows;
use super::specified_table::Table;
use super::text::{is_simple_name, keep, SceneError, Span, Text};
use super::{Axle, Integrator, IntegratorOverrides, Scene, SceneDefaults, Value, ViewSpec};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    title: Option<String>,
    model: Option<Spanned<String>>,
    t_final: Option<Spanned<f64>>,
    output_step: Option<Spanned<f64>>,
    plot_points: Option<Spanned<u32>>,
    outputs: Option<Vec<Spanned<String>>>,
    integrator: Option<IntegratorFile>,
    parameters: Option<BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
    initial: Option<BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
    specified: Option<BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
    axle: Option<Spanned<AxleFile>>,
    view: Option<ViewSpec>,
    events: Option<Vec<EventFile>>,
    controls: Option<Vec<ControlFile>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AxleFile {
    tilt: Option<Spanned<toml::Value>>,
    spin: Option<Spanned<toml::Value>>,
    precession: Option<Spanned<toml::Value>>,
    nutation: Option<Spanned<toml::Value>>,
    quaternion: Option<Spanned<Vec<Spanned<String>>>>,
    rates: Option<Spanned<Vec<Spanned<String>>>>,
}

#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct IntegratorFile {
    method: Option<Spanned<String>>,
    rtol: Option<Spanned<f64>>,
    atol: Option<Spanned<f64>>,
    step: Option<Spanned<f64>>,
    accuracy: Option<Spanned<f64>>,
    max_steps: Option<Spanned<i64>>,
}

impl Text<'_> {
    /// `v` if positive and finite, `default` when absent.
    fn positive(&self, v: &Option<Spanned<f64>>, default: f64, what: &str) -> Result<f64, SceneError> {
        match v {
            Some(s) if !(*s.get_ref() > 0.0 && s.get_ref().is_finite()) => Err(self.err(
                s.span(),
                format!("{what} must be positive, not {}", s.get_ref()),
                &format!("give a positive {what}"),
            )),
            Some(s) => Ok(*s.get_ref()),
            None => Ok(default),
        }
    }

    /// The integrator table (with `overrides` in place of its entries): a known method,
    /// positive tolerances, accuracy only if adaptive.
    fn integrator(
        &self,
        integ: Option<IntegratorFile>,
        overrides: &IntegratorOverrides,
        (t_final, output_step): (f64, f64),
    ) -> Result<Integrator, SceneError> {
        let integ = integ.unwrap_or_default();
        let named = overrides
            .method
            .clone()
            .or_else(|| integ.method.as_ref().map(|m| m.get_ref().clone()))
            .map_or(crate::ode::AUTO.to_string(), |m| m.to_ascii_lowercase());
        let asked = match &integ.accuracy {
            Some(_) => Some(self.positive(&integ.accuracy, 0.0, "accuracy")?),
            None => None,
        };
        // Without tolerances, an accuracy asked is where the refinement starts.
        let default_tol = asked.unwrap_or(1e-9);
        let rtol = overrides.rtol.map_or_else(|| self.positive(&integ.rtol, default_tol, "rtol"), Ok)?;
        let atol = overrides.atol.map_or_else(|| self.positive(&integ.atol, default_tol, "atol"), Ok)?;
        // A scene's method is found here once (the command line's name was checked by the same
        // lookup); the scene carries the method found.
        let found = if named == crate::ode::AUTO {
            Some(crate::ode::for_tolerances(crate::ode::Tolerances { rtol, atol }))
        } else {
            crate::ode::by_name(&named)
        };
        let Some(method) = found else {
            let span =
                integ.method.as_ref().filter(|_| overrides.method.is_none()).map_or(0..0, |m| m.span());
            return Err(self.err(span, format!("unknown integrator `{named}`"), &crate::ode::methods_help()));
        };
        if let (Some(a), false) = (&integ.accuracy, method.adaptive) {
            return Err(self.err(
                a.span(),
                format!("accuracy needs an adaptive method: {} has a fixed step", method.name()),
                "use an adaptive method (method = \"dop853\" or \"vern9\", or --method), or remove accuracy",
            ));
        }
        let step = self.positive(&integ.step, output_step / 10.0, "step")?;
        let max_steps = self.max_steps(&integ.max_steps)?;
        if !method.adaptive {
            self.fixed_steps_fit(&integ, step, t_final, max_steps)?;
        }
        Ok(Integrator { method, rtol, atol, step, accuracy: asked, max_steps })
    }

    /// `max_steps`: a positive whole number, [`crate::ode::DEFAULT_MAX_STEPS`] when absent.
    fn max_steps(&self, v: &Option<Spanned<i64>>) -> Result<usize, SceneError> {
        match v {
            Some(n) if *n.get_ref() < 1 => Err(self.err(
                n.span(),
                format!("max_steps must be at least 1, not {}", n.get_ref()),
                &format!(
                    "give the most steps one integration may take (default {})",
                    crate::ode::DEFAULT_MAX_STEPS
                ),
            )),
            Some(n) => Ok(usize::try_from(*n.get_ref()).unwrap_or(usize::MAX)),
            None => Ok(crate::ode::DEFAULT_MAX_STEPS),
        }
    }

    /// An error at `step` (or the method) when a fixed-step method would need more than
    /// `max_steps` steps to reach `t_final`.
    fn fixed_steps_fit(
        &self,
        integ: &IntegratorFile,
        step: f64,
        t_final: f64,
        max_steps: usize,
    ) -> Result<(), SceneError> {
        let needed = (t_final / step).ceil();
        if needed <= max_steps as f64 {
            return Ok(());
        }
        let span = match (&integ.step, &integ.max_steps, &integ.method) {
            (Some(s), _, _) => s.span(),
            (None, Some(m), _) => m.span(),
            (None, None, Some(m)) => m.span(),
            (None, None, None) => 0..0,
        };
        Err(self.err(
            span,
            format!("step = {step:e} needs {needed:.3e} steps to reach t_final = {t_final}, more than max_steps = {max_steps}"),
            &format!("raise step to at least {:.3e}, raise max_steps under [integrator], or shorten t_final", t_final / max_steps as f64),
        ))
    }

    /// A table of numbers with optional units (`"30 deg"`).
    fn values(
        &self,
        table: Option<BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
    ) -> Result<Vec<(String, Value, Span)>, SceneError> {
        let mut out = Vec::new();
        for (k, v) in table.unwrap_or_default() {
            out.push((k.get_ref().clone(), self.value(k.get_ref(), &v)?, v.span()));
        }
        Ok(out)
    }

    /// `[specified]`: each name (a SPECIFIED quantity of the model file) with its formula, or
    /// a table of its values in time (a spline through them, covering the run).
    fn formulas(
        &self,
        table: Option<BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
        t_final: f64,
    ) -> Result<Vec<(String, String, Span)>, SceneError> {
        let mut out = Vec::new();
        for (k, v) in table.unwrap_or_default() {
            let name = k.get_ref();
            let simple = is_simple_name(name);
            let help = "write NAME = \"formula of t, states and parameters\" (T = \"-K*Q1 - C*U1\"), or a table: NAME = { table = \"file.csv\" } (columns t and NAME) or NAME = { t = [...], values = [...] }";
            let formula = match v.get_ref() {
                toml::Value::String(f)
                    if simple && !f.contains(['\n', '\r', '%', ';']) && !f.trim().is_empty() =>
                {
                    f.clone()
                }
                toml::Value::Table(t) if simple => {
                    let folder = Path::new(self.file).parent().unwrap_or(Path::new("."));
                    let table = Table::from_toml(name, t, folder)
                        .and_then(|table| table.covers(t_final).map(|()| table))
                        .map_err(|e| self.err(v.span(), format!("[specified] {name}: {e}"), help))?;
                    table.spline_formula()
                }
                _ => {
                    return Err(self.err(
                        v.span(),
                        format!("[specified] {name}: a name and a one-line formula or a table are needed"),
                        help,
                    ))
                }
            };
            out.push((name.clone(), formula, v.span()));
        }
        Ok(out)
    }

    /// The finite number `key` is given, with an optional unit (`"30 deg"`).
    fn value(&self, key: &str, v: &Spanned<toml::Value>) -> Result<Value, SceneError> {
        let span = v.span();
        let value = match v.get_ref() {
            toml::Value::Float(x) => Value { number: *x, unit: None },
            toml::Value::Integer(i) => Value { number: *i as f64, unit: None },
            toml::Value::String(s) => self.with_unit(s, span.clone())?,
            other => {
                return Err(self.err(
                    span,
                    format!("`{other}` is not a number"),
                    "write a number, or a string like \"30 deg\"",
                ))
            }
        };
        if !value.number.is_finite() {
            return Err(self.err(
                span,
                format!("`{key}` is {}, not a finite number", value.number),
                &format!("give {key} a finite value (NaN and infinity are not values)"),
            ));
        }
        Ok(value)
    }

    /// The `[axle]` table: `quaternion` names four states, `rates` three; spin, precession and
    /// nutation set rates, so they need `tilt` (the derived orientation) and `rates`.
    fn axle(&self, axle: Option<Spanned<AxleFile>>) -> Result<Option<Axle>, SceneError> {
        let Some(axle) = axle else { return Ok(None) };
        let table_span = axle.span();
        let a = axle.into_inner();
        let names = |list: Option<Spanned<Vec<Spanned<String>>>>, want: usize, what: &str, example: &str| {
            let Some(list) = list else { return Ok((Vec::new(), table_span.clone())) };
            if list.get_ref().len() != want {
                return Err(self.err(
                    list.span(),
                    format!("`{what}` names {} states, not {want}", list.get_ref().len()),
                    &format!("write {what} = {example}, the model's state names"),
                ));
            }
            let span = list.span();
            Ok((list.into_inner().into_iter().map(|n| (n.get_ref().clone(), n.span())).collect(), span))
        };
        let (quaternion, quaternion_span) = names(
            a.quaternion,
            4,
            "quaternion",
            "[\"E4\", \"E1\", \"E2\", \"E3\"] (scalar first, body -> space)",
        )?;
        let (rates, _) = names(a.rates, 3, "rates", "[\"W1\", \"W2\", \"W3\"] (body-axis angular velocity)")?;
        if quaternion.is_empty() {
            return Err(self.err(
                table_span,
                "[axle] does not say which states are the Euler parameters".into(),
                "add quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"] (the model's Euler-parameter states, scalar first, body -> space)",
            ));
        }
        let value = |key: &str, v: Option<Spanned<toml::Value>>| {
            v.map(|v| self.value(key, &v).map(|x| (x, v.span()))).transpose()
        };
        let out = Axle {
            tilt: value("tilt", a.tilt)?,
            spin: value("spin", a.spin)?,
            precession: value("precession", a.precession)?,
            nutation: value("nutation", a.nutation)?,
            quaternion,
            rates,
            quaternion_span,
        };
        for (key, given) in
            [("spin", &out.spin), ("precession", &out.precession), ("nutation", &out.nutation)]
        {
            let Some((_, span)) = given else { continue };
            if !out.derives() {
                return Err(self.err(
                    span.clone(),
                    format!("`{key}` needs `tilt` in [axle]"),
                    "add tilt = \"0 deg\" (upright) or the axle's angle from +z; without tilt, [axle] only names the Euler-parameter states and [initial] gives them",
                ));
            }
            if out.rates.is_empty() {
                return Err(self.err(
                    span.clone(),
                    format!("`{key}` sets the body rates, but [axle] does not name them"),
                    "add rates = [\"W1\", \"W2\", \"W3\"] (the model's body-axis angular velocity states)",
                ));
            }
        }
        Ok(Some(out))
    }

    fn with_unit(&self, s: &str, span: Span) -> Result<Value, SceneError> {
        let mut parts = s.split_whitespace();
        let number: f64 = parts.next().and_then(|n| n.parse().ok()).ok_or_else(|| {
            self.err(
                span,
                format!("`{s}` is not a number with a unit"),
                "write a number, or a string like \"30 deg\" or \"10 rad/s\"",
            )
        })?;
        let unit: String = parts.collect::<Vec<_>>().join(" ");
        Ok(Value { number, unit: (!unit.is_empty()).then_some(unit) })
    }

    /// `t_final` and `output_step`: positive, the step no longer than the span.
    /// `plot_points`: 1 (the output rows alone) to 1000 points per output interval.
    fn plot_points(&self, v: Option<Spanned<u32>>) -> Result<Option<usize>, SceneError> {
        match v {
            Some(n) if !(1..=1000).contains(n.get_ref()) => Err(self.err(
                n.span(),
                format!("plot_points must be 1 to 1000, not {}", n.get_ref()),
                "give the points per output interval the figures are drawn from (1: the rows alone)",
            )),
            Some(n) => Ok(Some(*n.get_ref() as usize)),
            None => Ok(None),
        }
    }

    fn times(
        &self,
        t_final: Option<Spanned<f64>>,
        output_step: Option<Spanned<f64>>,
    ) -> Result<(f64, f64), SceneError> {
        let missing =
            |key: &str, add: &str| self.err(0..0, format!("missing `{key}`"), &format!("add {add}"));
        let (t_final, output_step) = match (t_final, output_step) {
            (Some(t), Some(s)) => (t, s),
            (t, s) => {
                let t_err = t.is_none().then(|| missing("t_final", "t_final = 5.0 (seconds)"));
                let s_err = s.is_none().then(|| missing("output_step", "output_step = 0.05"));
                return Err(SceneError::all(t_err.into_iter().chain(s_err).collect()));
            }
        };
        if !(*t_final.get_ref() > 0.0 && t_final.get_ref().is_finite()) {
            return Err(self.err(
                t_final.span(),
                format!("t_final must be positive, not {}", t_final.get_ref()),
                "the simulation starts at t = 0; give a positive end time",
            ));
        }
        let step = output_step;
        if !(*step.get_ref() > 0.0 && *step.get_ref() <= *t_final.get_ref()) {
            return Err(self.err(
                step.span(),
                format!("output_step must be in (0, t_final], not {}", step.get_ref()),
                "give a positive step no longer than t_final",
            ));
        }
        if let Some((what, help)) = too_many_rows(*t_final.get_ref(), *step.get_ref()) {
            return Err(self.err(step.span(), what, &help));
        }
        Ok((t_final.into_inner(), step.into_inner()))
    }
}

/// Where the first `[view]` or `[[view.` table header is (empty when none): a dotted table
/// array has no span of its own in the TOML reader.
fn view_span(source: &str) -> Span {
    let mut at = 0;
    for line in source.split_inclusive('\n') {
        let head = line.trim_start();
        if head.starts_with("[view") || head.starts_with("[[view") {
            let start = at + line.len() - head.len();
            return start..start + head.trim_end().len();
        }
        at += line.len();
    }
    0..0
}

impl Scene {
    /// Reads and validates a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        Scene::load_with(path, &IntegratorOverrides::default(), &|_| SceneDefaults::default())
    }

    /// Reads and validates a scene file, with `overrides` in place of its integrator settings
    /// and `defaults(model)` (given the scene's `model`) where it gives no times or tolerances.
    pub fn load_with(
        path: &Path,
        overrides: &IntegratorOverrides,
        defaults: &dyn Fn(&str) -> SceneDefaults,
    ) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let source = std::fs::read_to_string(path).map_err(|e| SceneError {
            file: file.clone(),
            line: 1,
            column: 1,
            message: format!("cannot read the scene: {e}"),
            help: "give the path of a scene .toml file, e.g. gyro-sim/scenes/paper/trial3.toml".into(),
            more: Vec::new(),
        })?;
        Scene::parse_with(&file, &source, overrides, defaults)
    }

    /// Parses and validates a scene from its text (the model is looked up when it is resolved).
    pub fn parse(file: &str, source: &str) -> Result<Scene, SceneError> {
        Scene::parse_with(file, source, &IntegratorOverrides::default(), &|_| SceneDefaults::default())
    }

    /// [`Scene::parse`] with `overrides` in place of the text's integrator settings and
    /// `defaults(model)` where it gives no times or tolerances.
    pub fn parse_with(
        file: &str,
        source: &str,
        overrides: &IntegratorOverrides,
        defaults: &dyn Fn(&str) -> SceneDefaults,
    ) -> Result<Scene, SceneError> {
        let text = Text { file, source };
        let typed = super::typed::read_typed::<SceneFile>(&text)?;
        let mut raw = typed.tables;
        let defaults = match &raw.model {
            Some(m) if raw.lacks_settings() => defaults(m.get_ref()),
            _ => SceneDefaults::default(),
        };
        raw.fill(&defaults);
        // Each check on its own, so one reading reports every mistake.
        let mut found = typed.unknown;
        let model = keep(
            &mut found,
            raw.model.ok_or_else(|| {
                text.err(
                    0..0,
                    "missing `model`".into(),
                    "add model = \"gimbal_gyroscope\" (or another compiled model)",
                )
            }),
        );
        let times = keep(&mut found, text.times(raw.t_final, raw.output_step));
        let integrator = times.and_then(|t| keep(&mut found, text.integrator(raw.integrator, overrides, t)));
        let parameters = keep(&mut found, text.values(raw.parameters));
        let initial = keep(&mut found, text.values(raw.initial));
        let specified =
            times.and_then(|(t_final, _)| keep(&mut found, text.formulas(raw.specified, t_final)));
        let axle = keep(&mut found, text.axle(raw.axle));
        let plot_points = keep(&mut found, text.plot_points(raw.plot_points));
        let events = keep(
            &mut found,
            event_decls::decls(raw.events.unwrap_or_default(), source, &|span, message, help| {
                text.err(span, message, help)
            }),
        );
        let (
            Some(model),
            Some((t_final, output_step)),
            Some(integrator),
            Some(parameters),
            Some(initial),
            Some(specified),
            Some(axle),
            Some(plot_points),
            Some(events),
        ) = (model, times, integrator, parameters, initial, specified, axle, plot_points, events)
        else {
            // `missing output_step` after `output_stp` (did you mean `output_step`?) says it again.
            let said = |e: &SceneError| typed.suggested.iter().any(|k| e.message == format!("missing `{k}`"));
            found.retain(|e| !said(e));
            return Err(SceneError::all(found));
        };
        if !found.is_empty() {
            return Err(SceneError::all(found));
        }
        let outputs =
            raw.outputs.unwrap_or_default().into_iter().map(|o| (o.get_ref().clone(), o.span())).collect();
        let mut scene = Scene {
            path: PathBuf::from(file),
            source: source.to_string(),
            title: raw.title.unwrap_or_else(|| model.get_ref().clone()),
            model_span: model.span(),
            model: model.into_inner(),
            parameters,
            initial,
            specified,
            axle,
            view_span: view_span(source),
            view: raw.view,
            t_final,
            output_step,
            plot_points,
            outputs,
            integrator,
            events,
            controls: Vec::new(),
        };
        scene.controls = text.controls(raw.controls.unwrap_or_default(), &scene)?;
        Ok(scene)
    }
}

impl SceneFile {
    /// Whether it leaves out a time or a tolerance.
    fn lacks_settings(&self) -> bool {
        let integ = self.integrator.as_ref();
        self.t_final.is_none()
            || self.output_step.is_none()
            || integ.is_none_or(|i| i.rtol.is_none() || i.atol.is_none())
    }

    /// The scene with `defaults` where it gives no times or tolerances (located at its start).
    fn fill(&mut self, defaults: &SceneDefaults) {
        let at_start = |v: Option<f64>| v.map(|v| Spanned::new(0..0, v));
        self.t_final = self.t_final.take().or_else(|| at_start(defaults.t_final));
        self.output_step = self.output_step.take().or_else(|| at_start(defaults.output_step));
        if defaults.rtol.is_none() && defaults.atol.is_none() {
            return;
        }
        let integ = self.integrator.get_or_insert_with(IntegratorFile::default);
        integ.rtol = integ.rtol.take().or_else(|| at_start(defaults.rtol));
        integ.atol = integ.atol.take().or_else(|| at_start(defaults.atol));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &str = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n[axle]\n";

    fn error(text: &str) -> String {
        Scene::parse("top.toml", &format!("{HEAD}{text}")).unwrap_err().to_string()
    }

    #[test]
    fn an_axle_table_is_read_with_its_units_and_spans() {
        let text = "tilt = \"60 deg\"\nspin = 10\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\", \"W2\", \"W3\"]\n";
        let s = Scene::parse("top.toml", &format!("{HEAD}{text}")).unwrap();
        let axle = s.axle.unwrap();
        assert!(axle.derives());
        assert_eq!(axle.tilt.unwrap().0, Value { number: 60.0, unit: Some("deg".into()) });
        assert_eq!(axle.spin.unwrap().0, Value { number: 10.0, unit: None });
        assert!(axle.precession.is_none() && axle.nutation.is_none());
        assert_eq!(
            axle.quaternion.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(),
            ["E4", "E1", "E2", "E3"]
        );
        assert_eq!(&s.source[axle.rates[1].1.clone()], "\"W2\"");
    }

    #[test]
    fn an_axle_table_needs_its_quaternion_and_the_right_counts() {
        let e = error("tilt = \"60 deg\"\n");
        assert!(e.contains("error: [axle] does not say which states are the Euler parameters"), "{e}");
        assert!(e.contains("help: add quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]"), "{e}");
        let e = error("quaternion = [\"E4\", \"E1\", \"E2\"]\n");
        assert!(e.starts_with("top.toml:5:14: error: `quaternion` names 3 states, not 4"), "{e}");
        let e = error("quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\"]\n");
        assert!(e.starts_with("top.toml:6:9: error: `rates` names 1 states, not 3"), "{e}");
        let e = error("quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\ntilts = \"60 deg\"\n");
        assert!(e.starts_with("top.toml:6:1: error: unknown field `tilts`"), "{e}");
        assert!(e.contains("help: did you mean `tilt`?"), "{e}");
    }

    #[test]
    fn every_mistake_is_reported_at_once_with_the_key_meant() {
        let src = "model = \"heavy_top\"\nt_final = 1.0\noutput_stp = 0.1\nplot_points = 5000\n\
                   [integrator]\nmethd = [\n  \"dop853\",\n]\n[view]\ncamra = 1\n";
        let e = Scene::parse("s.toml", src).unwrap_err();
        let each: Vec<String> = e.each().map(|m| format!("{}:{} {}", m.line, m.column, m.message)).collect();
        assert_eq!(each.len(), 4, "{e}");
        assert!(
            each[0].starts_with("3:1 unknown field `output_stp`") && e.help == "did you mean `output_step`?",
            "{e}"
        );
        assert!(each[1].starts_with("4:15 plot_points must be 1 to 1000"), "{e}");
        assert!(
            each[2].starts_with("6:1 unknown field `methd`") && e.more[1].help == "did you mean `method`?",
            "{e}"
        );
        assert!(each[3].starts_with("10:1 unknown field `camra`"), "{e}");
        // `missing output_step` would only say again what the did-you-mean says.
        assert!(!e.to_string().contains("missing `output_step`"), "{e}");
    }

    #[test]
    fn rates_of_the_axle_need_tilt_and_rates() {
        let q = "quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\n";
        let e = error(&format!("spin = \"10 rad/s\"\n{q}"));
        assert!(e.starts_with("top.toml:5:8: error: `spin` needs `tilt` in [axle]"), "{e}");
        let e = error(&format!("tilt = \"60 deg\"\nprecession = \"1 rad/s\"\n{q}"));
        assert!(e.starts_with("top.toml:6:14: error: `precession` sets the body rates"), "{e}");
        assert!(e.contains("help: add rates = [\"W1\", \"W2\", \"W3\"]"), "{e}");
    }

    #[test]
    fn an_unnamed_or_auto_method_is_picked_by_the_tolerances() {
        let head = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n";
        let method = |integ: &str| {
            Scene::parse("top.toml", &format!("{head}{integ}")).unwrap().integrator.method.name()
        };
        assert_eq!(method(""), "vern9", "the default tolerances are 1e-9");
        assert_eq!(method("[integrator]\nrtol = 1e-6\natol = 1e-6\n"), "dop853");
        assert_eq!(method("[integrator]\nmethod = \"AUTO\"\nrtol = 1e-6\natol = 1e-10\n"), "dop853");
        assert_eq!(method("[integrator]\nmethod = \"auto\"\nrtol = 1e-8\natol = 1e-8\n"), "vern9");
        assert_eq!(method("[integrator]\nmethod = \"dopri5\"\nrtol = 1e-8\n"), "dopri5");
    }
}
