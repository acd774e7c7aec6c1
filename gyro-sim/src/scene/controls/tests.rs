//! Unit tests of `[[controls]]`: in come small scenes; out go checks of the bound controls, of
//! the errors at their line and column, and of scenes and text with moved values.

use super::*;

const HEAD: &str = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n\
[parameters]\nD = 1.0\nRR = 1\n\
[axle]\ntilt = \"60 deg\"\nspin = \"10 rad/s\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\", \"W2\", \"W3\"]\n";

fn scene(controls: &str) -> Result<Scene, SceneError> {
    Scene::parse("top.toml", &format!("{HEAD}{controls}"))
}

#[test]
fn controls_bind_to_axle_entries_and_parameters_in_their_units() {
    let s = scene(
        "[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\nstep = 0.5\n\
         [[controls]]\nname = \"tilt\"\nmin = 0.0\nmax = 90.0\nunit = \"deg\"\n\
         [[controls]]\nname = \"d\"\nmin = 0.2\nmax = 2.0\n",
    )
    .unwrap();
    let c = &s.controls;
    assert_eq!(c.len(), 3);
    assert_eq!(
        (c[0].target, c[0].unit.as_deref(), c[0].value, c[0].step),
        (Target::Axle(AxleKey::Spin), Some("rad/s"), 10.0, 0.5)
    );
    assert_eq!(
        (c[1].target, c[1].unit.as_deref(), c[1].value),
        (Target::Axle(AxleKey::Tilt), Some("deg"), 60.0)
    );
    assert!((c[1].step - 0.9).abs() < 1e-12, "a hundredth of the range when not given");
    assert_eq!((c[2].target, c[2].unit.as_deref(), c[2].value), (Target::Parameter(0), None, 1.0));
    assert_eq!(s.control("SPIN"), Some(0));
}

#[test]
fn control_errors_name_the_line_and_column() {
    let at = |controls: &str| scene(controls).unwrap_err().to_string();
    let e = at("[[controls]]\nname = \"M\"\nmin = 0\nmax = 2\n");
    assert!(e.starts_with("top.toml:13:8: error: a control for `M`, which the scene does not give"), "{e}");
    let e = at("[[controls]]\nname = \"spin\"\nmin = 20\nmax = 40\n");
    assert!(
        e.starts_with(
            "top.toml:13:8: error: the scene gives spin = 10, outside this control's range 20 to 40"
        ),
        "{e}"
    );
    let e = at("[[controls]]\nname = \"spin\"\nmin = 0\nmax = 0\n");
    assert!(e.starts_with("top.toml:15:7: error: max = 0 is not above min = 0"), "{e}");
    let e = at("[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\nstep = -1\n");
    assert!(e.starts_with("top.toml:16:8: error: step = -1 is not in (0, max - min = 40]"), "{e}");
    let e = at("[[controls]]\nname = \"spin\"\nmin = 0\nmax = nan\n");
    assert!(e.starts_with("top.toml:15:7: error: max is NaN, not a finite number"), "{e}");
    let e = at("[[controls]]\nname = \"tilt\"\nmin = 0\nmax = 2\nunit = \"rad\"\n");
    assert!(e.starts_with("top.toml:16:8: error: the control's unit `rad` is not the unit of tilt at line 8, column 8 (`deg`)"), "{e}");
    let e = at("[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\n[[controls]]\nname = \"Spin\"\nmin = 0\nmax = 40\n");
    assert!(e.starts_with("top.toml:17:8: error: a control for `Spin` is declared twice"), "{e}");
    let e = at("[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\nsteps = 1\n");
    assert!(e.starts_with("top.toml:16:1: error: unknown field `steps`"), "{e}");
}

#[test]
fn moved_values_reach_the_scene_and_its_saved_text() {
    let s = scene(
        "[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\n[[controls]]\nname = \"RR\"\nmin = 0.5\nmax = 2\n",
    )
    .unwrap();
    let moved = s.with_controls(&[(0, 12.5), (1, 1.25)]);
    assert_eq!(
        moved.axle.as_ref().unwrap().spin.as_ref().unwrap().0,
        Value { number: 12.5, unit: Some("rad/s".into()) }
    );
    assert_eq!(moved.parameters[1].1, Value { number: 1.25, unit: None });
    assert_eq!(moved.controls[0].value, 12.5);
    let text = s.text_with_controls(&[(0, 12.5), (1, 1.25)]);
    assert!(text.contains("spin = \"12.5 rad/s\"\n") && text.contains("RR = 1.25\n"), "{text}");
    let again = Scene::parse("top.toml", &text).unwrap();
    let axle_values = |s: &Scene| {
        let a = s.axle.clone().unwrap();
        (a.tilt.map(|(v, _)| v), a.spin.map(|(v, _)| v))
    };
    assert_eq!(axle_values(&again), axle_values(&moved));
    assert_eq!(
        again.parameters.iter().map(|(n, v, _)| (n, v)).collect::<Vec<_>>(),
        moved.parameters.iter().map(|(n, v, _)| (n, v)).collect::<Vec<_>>()
    );
    assert_eq!(again.controls.iter().map(|c| c.value).collect::<Vec<_>>(), [12.5, 1.25]);
}
