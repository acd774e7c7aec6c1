//! Plausibility of a run's values: in come a scene and the problem resolved from it (which
//! carries the model's entry); out goes an error naming the first negative mass, inertia that no rigid body has,
//! or Euler parameters off unit norm, at the scene's line that gives the value (at its `model`
//! key when the value is the model's own). Models without known mechanics are not checked.

use crate::problem::Problem;
use crate::scene::{Scene, SceneError};

/// An error at `scene` when `problem`'s values are implausible for its model's mechanics.
pub(crate) fn check(scene: &Scene, problem: &Problem) -> Result<(), SceneError> {
    let Some(model) = problem.model.mechanics() else { return Ok(()) };
    let info = problem.model.info();
    let value = |name: &str| {
        let param = info.param(name).map(|i| problem.params[i]);
        param.or_else(|| info.state(name).map(|i| problem.initial[i]))
    };
    let Some(issue) = kane_model::plausibility::plausibility(&model, value).into_iter().next() else {
        return Ok(());
    };
    let given = |name: &str| {
        let tables = scene
            .parameters
            .iter()
            .map(|(n, _, s)| (n, s))
            .chain(scene.initial.iter().map(|(n, _, s)| (n, s)));
        tables.filter(|(n, _)| n.eq_ignore_ascii_case(name)).map(|(_, s)| s.clone()).next_back()
    };
    let span = std::iter::once(&issue.parameter)
        .chain(&issue.involved)
        .find_map(|n| given(n))
        .unwrap_or_else(|| scene.model_span.clone());
    Err(scene.error_at(
        span,
        format!("implausible value of {}: {}", issue.parameter, issue.message),
        &format!("change {} (under [parameters] or [initial], or with --set)", issue.parameter),
    ))
}
