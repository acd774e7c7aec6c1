//! The inputs a run leaves at zero: a model file's SPECIFIED quantities without a formula that
//! neither the scene (`[parameters]`, `[specified]`) nor `--set` gives. In: the scene and the
//! model's metadata. Out: the warning naming them, when there are any.

use kane_model::runtime::ModelInfo;

use crate::scene::Scene;

/// `warning: ...` naming the model's open inputs `scene` gives no value, or None.
pub(crate) fn open_inputs_warning(scene: &Scene, info: &ModelInfo) -> Option<String> {
    let given = |name: &str| {
        scene.parameters.iter().any(|(n, _, _)| n.eq_ignore_ascii_case(name))
            || scene.specified.iter().any(|(n, _, _)| n.eq_ignore_ascii_case(name))
    };
    let left: Vec<&str> =
        info.open_inputs.iter().map(|i| info.param_names[*i]).filter(|n| !given(n)).collect();
    if left.is_empty() {
        return None;
    }
    let first = left[0];
    Some(format!(
        "warning: {} {} the model leaves open (SPECIFIED without a formula, or a variable without an equation): 0 in this run; give {} with --set {first}=VALUE, [parameters] {first} = VALUE, or [specified] {first} = \"a formula of time T\" (or a table)",
        left.join(", "),
        if left.len() == 1 { "is an input" } else { "are inputs" },
        if left.len() == 1 { "it" } else { "them" },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    const INFO: ModelInfo = ModelInfo {
        name: "rod",
        state_names: &["Q", "U"],
        state_units: &["", ""],
        n_coordinates: 1,
        param_names: &["T1", "T2", "L"],
        param_units: &["", "", ""],
        inputs: &[0, 1],
        open_inputs: &[0, 1],
        outputs: &[],
        cyclic: &[],
        dependent_coordinates: &[],
        op_counts: kane_model::runtime::OpCounts { rhs: 0, outputs: 0 },
        taylor_straight_line: &[],
    };

    #[test]
    fn inputs_the_scene_gives_are_not_named() {
        let src = "model = \"rod.al\"\nt_final = 1\noutput_step = 0.1\n[parameters]\nT1 = 2\n";
        let scene = Scene::parse("s.toml", src).unwrap();
        let warning = open_inputs_warning(&scene, &INFO).unwrap();
        assert!(warning.starts_with("warning: T2 is an input the model leaves open"), "{warning}");
        let only_t1 = ModelInfo { open_inputs: &[0], ..INFO };
        assert_eq!(open_inputs_warning(&scene, &only_t1), None);
    }
}
