//! Errors of a `--model` run told where the user wrote the value: in comes a message that names a
//! place in the scene generated for the run (`<command line>:L:C: ...`); out goes the same
//! message naming what the user gave instead (`--set Q1=abc`, `--t-final`, or the model file's
//! INPUT or OUTPUT line), never a scene the user never saw.

use std::path::Path;

use crate::scene::IntegratorOverrides;

/// The name a generated scene is parsed under.
pub const GENERATED: &str = "<command line>";

/// What a `--model` run was given.
pub struct Given<'a> {
    /// The model file.
    pub model: &'a Path,
    /// `--set NAME=VALUE` pairs.
    pub sets: &'a [(String, String)],
    /// `--t-final`, if given.
    pub t_final: Option<f64>,
    /// `--method`, `--rtol` and `--atol`, where given.
    pub integrator: &'a IntegratorOverrides,
}

/// `message` with a place in the generated scene `source` replaced by where the value came from.
pub fn point_at_arguments(message: &str, source: &str, given: &Given<'_>) -> String {
    let Some(rest) = message.strip_prefix(GENERATED) else { return message.to_string() };
    let file = given.model.display();
    let Some(place) = rest.strip_prefix(':') else { return message.to_string() };
    // `L:C: text` or ` text` (a run's failure, named by the scene's path alone).
    let mut parts = place.splitn(3, ':');
    let (line, column, text) = (parts.next(), parts.next(), parts.next());
    let line: Option<usize> = line.and_then(|l| l.trim().parse().ok());
    let (Some(line), Some(_), Some(text)) = (line, column, text) else {
        return format!("{file}:{place}");
    };
    let origin = source
        .lines()
        .nth(line.saturating_sub(1))
        .map_or_else(|| format!("{file} (the scene of the run, line {line})"), |l| origin_of(l, given));
    format!("{origin}:{text}")
}

/// Where the generated scene line `line` came from.
fn origin_of(line: &str, given: &Given<'_>) -> String {
    let file = given.model.display();
    let key = line.split('=').next().unwrap_or("").trim().trim_matches('"');
    if let Some((name, value)) = given.sets.iter().find(|(n, _)| n.eq_ignore_ascii_case(key)) {
        return format!("--set {name}={value}");
    }
    match key {
        "t_final" if given.t_final.is_some() => "--t-final".to_string(),
        "t_final" => format!("{file}: INPUT TFINAL"),
        "output_step" => format!("{file}: INPUT INTEGSTP"),
        "method" if given.integrator.method.is_some() => "--method".to_string(),
        "rtol" if given.integrator.rtol.is_some() => "--rtol".to_string(),
        "atol" if given.integrator.atol.is_some() => "--atol".to_string(),
        "rtol" => format!("{file}: INPUT RELERR"),
        "atol" => format!("{file}: INPUT ABSERR"),
        "outputs" => format!("{file}: OUTPUT"),
        _ => file.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "title = \"g (model file)\"\nmodel = \"g.al\"\nt_final = 5.0\noutput_step = 0.05\n\n[initial]\n\"Q1\" = \"abc\"\n";

    fn given(sets: &[(String, String)]) -> Given<'_> {
        const NONE: &IntegratorOverrides = &IntegratorOverrides { method: None, rtol: None, atol: None };
        Given { model: Path::new("g.al"), sets, t_final: None, integrator: NONE }
    }

    #[test]
    fn a_place_in_the_generated_scene_becomes_the_argument_or_the_file() {
        let sets = [("Q1".to_string(), "abc".to_string())];
        let e = point_at_arguments("<command line>:7:8: error: `abc` is not a number", SCENE, &given(&sets));
        assert_eq!(e, "--set Q1=abc: error: `abc` is not a number");
        let e = point_at_arguments("<command line>:2:9: error: MCC has no value", SCENE, &given(&sets));
        assert_eq!(e, "g.al: error: MCC has no value");
        let e = point_at_arguments("<command line>:3:11: error: t_final is negative", SCENE, &given(&sets));
        assert_eq!(e, "g.al: INPUT TFINAL: error: t_final is negative");
        let e = point_at_arguments("<command line>: integration failed: x", SCENE, &given(&sets));
        assert_eq!(e, "g.al: integration failed: x");
        assert_eq!(
            point_at_arguments("scene.toml:1:1: error", SCENE, &given(&sets)),
            "scene.toml:1:1: error"
        );
    }
}
