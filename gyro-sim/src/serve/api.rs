//! What the server answers: in come a method, a path and a body; out goes a [`Reply`]: the page,
//! a run of the scene with the values asked for (the data the page draws), the scene's text
//! with those values (to save), or a client error. Nothing but these is served.

use crate::models::Registry;
use crate::problem::Trajectory;
use crate::scene::Scene;
use kane_model::lang::units::size::shown_per_internal;

use super::request::{self, Refused};

/// The scene served and what answers need of it.
pub struct App {
    /// The scene as loaded (its controls at the file's values).
    pub scene: Scene,
    /// The models, the scene's among them.
    pub registry: Registry,
    /// The page (built once, with the scene's own run).
    pub page: String,
    /// Runs at once: one per core, the others waiting.
    pub runs: super::gate::Gate,
}

/// An answer: status, content type, body and, for a download, its file name.
#[derive(Clone, Debug, PartialEq)]
pub struct Reply {
    /// HTTP status.
    pub status: u16,
    /// The reply's `Content-Type`.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
    /// A file name to save the body as (`Content-Disposition: attachment`).
    pub download: Option<String>,
}

impl Reply {
    /// A JSON answer.
    fn json(status: u16, value: &serde_json::Value) -> Reply {
        Reply {
            status,
            content_type: "application/json",
            body: value.to_string().into_bytes(),
            download: None,
        }
    }

    /// `{"error": message}` with `status`.
    pub fn error(status: u16, message: &str) -> Reply {
        Reply::json(status, &serde_json::json!({ "error": message }))
    }
}

impl From<Refused> for Reply {
    fn from(r: Refused) -> Reply {
        Reply::error(r.status, &r.message)
    }
}

/// The answer to one request (`body` already cut at [`request::MAX_BODY`] + 1 bytes).
pub fn answer(app: &App, method: &str, path: &str, body: &[u8]) -> Reply {
    let path = path.split(['?', '#']).next().unwrap_or("");
    let post = |handle: fn(&App, &[(usize, f64)]) -> Reply| {
        if method != "POST" {
            return Reply::error(405, &format!("{path} takes POST"));
        }
        match request::values(body, &app.scene.controls) {
            Ok(values) => handle(app, &values),
            Err(refused) => refused.into(),
        }
    };
    match path {
        "/" | "/index.html" if method == "GET" || method == "HEAD" => Reply {
            status: 200,
            content_type: "text/html; charset=utf-8",
            body: app.page.clone().into_bytes(),
            download: None,
        },
        "/" | "/index.html" => Reply::error(405, &format!("{path} takes GET")),
        "/api/run" => post(run),
        "/api/scene" => post(saved_scene),
        _ => Reply::error(404, "not found: this server serves its page (/), /api/run and /api/scene only"),
    }
}

/// The scene run with `values`: the data the page draws (titled with the values), or the run's
/// error (422).
fn run(app: &App, values: &[(usize, f64)]) -> Reply {
    let _pass = app.runs.enter();
    let moved = app.scene.with_controls(values);
    match run_data(&moved, &app.registry) {
        Ok(mut data) => {
            let title = data["title"].as_str().unwrap_or(&app.scene.title).to_string();
            data["title"] = super::title::moved_title(&title, &app.scene.controls, &moved.controls).into();
            Reply::json(200, &data)
        }
        Err(e) => Reply::error(422, &e.to_string()),
    }
}

/// The scene's text with `values`, as a file to save.
fn saved_scene(app: &App, values: &[(usize, f64)]) -> Reply {
    let name = app.scene.path.file_name().map_or("scene.toml".into(), |n| n.to_string_lossy().into_owned());
    Reply {
        status: 200,
        content_type: "application/toml; charset=utf-8",
        body: app.scene.text_with_controls(values).into_bytes(),
        download: Some(name),
    }
}

/// Why a scene's run gave no data for the page.
#[derive(Debug, thiserror::Error)]
pub enum RunDataError {
    /// The scene's `[view]` tables are wrong.
    #[error(transparent)]
    View(#[from] crate::scene::ViewError),
    /// The scene does not fit its model.
    #[error(transparent)]
    Scene(Box<crate::scene::SceneError>),
    /// The integration stopped.
    #[error(transparent)]
    Solve(#[from] crate::problem::SolveError),
}

impl From<crate::scene::SceneError> for RunDataError {
    fn from(e: crate::scene::SceneError) -> Self {
        RunDataError::Scene(Box::new(e))
    }
}

/// Runs `scene` (resolve, then solve: the `gyro-sim run` pipeline without files) and gives the
/// page's data: the view's columns and the plotted ones (with the groups sharing a y axis), their
/// units, the controls' values.
pub fn run_data(scene: &Scene, registry: &Registry) -> Result<serde_json::Value, RunDataError> {
    let problem = crate::resolve::resolve(scene, registry)?;
    let view = problem.view.clone().unwrap_or_default();
    let trajectory = crate::solve::solve(&problem, None)?;
    let plot = plot_columns(&trajectory);
    let mut data = crate::output::view_data(&trajectory, &view, &plot)?;
    let units: serde_json::Map<String, serde_json::Value> =
        trajectory.columns.iter().map(|c| (c.name.clone(), c.unit.clone().into())).collect();
    // Plotted values per model value: angles in degrees, other quantities in their declared unit.
    let scale = |c: &crate::problem::Column| {
        if c.is_angle() {
            180.0 / std::f64::consts::PI
        } else {
            shown_per_internal(&c.unit)
        }
    };
    let scales: serde_json::Map<String, serde_json::Value> =
        trajectory.columns.iter().map(|c| (c.name.clone(), scale(c).into())).collect();
    let values: serde_json::Map<String, serde_json::Value> =
        scene.controls.iter().map(|c| (c.name.clone(), c.value.into())).collect();
    data["plot_groups"] = super::plot_groups::plot_groups(&trajectory, &plot).into();
    data["plot"] = plot.into();
    data["units"] = units.into();
    data["scales"] = scales.into();
    data["values"] = values.into();
    data["wall_ms"] = (trajectory.wall.as_secs_f64() * 1e3).into();
    Ok(data)
}

/// The columns of the second window: the axle's and L's elevations when the run has them (the
/// EJS top), else its first three angles, else its first three written columns.
fn plot_columns(trajectory: &Trajectory) -> Vec<String> {
    let written = || trajectory.columns.iter().filter(|c| !c.hidden);
    let elevations: Vec<String> = written()
        .filter(|c| c.name == "ELEVATION" || c.name == "L_ELEVATION")
        .map(|c| c.name.clone())
        .collect();
    if !elevations.is_empty() {
        return elevations;
    }
    let angles: Vec<String> = written().filter(|c| c.is_angle()).take(3).map(|c| c.name.clone()).collect();
    if !angles.is_empty() {
        return angles;
    }
    written().take(3).map(|c| c.name.clone()).collect()
}
