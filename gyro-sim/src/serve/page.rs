//! The served page: in come the scene and its first run's data; out goes the view page (the one
//! runs write, see [`crate::output`]) with the serving panels, uPlot and their script added.

use crate::scene::Scene;

/// uPlot 1.6.32, `dist/uPlot.iife.min.js` (see `gyro-sim/assets/uplot/README.md`).
const UPLOT_JS: &str = include_str!("../../assets/uplot/uPlot.iife.min.js");
/// uPlot's style sheet, `dist/uPlot.min.css`.
const UPLOT_CSS: &str = include_str!("../../assets/uplot/uPlot.min.css");
/// The panels: controls, the plot window, the error line.
const PANELS_HTML: &str = include_str!("panels.html");
/// The panels' script.
const SERVE_JS: &str = include_str!("serve.js");

/// The whole page for `scene`, drawing `data` (from [`super::run_data`]) first.
pub(super) fn page(scene: &Scene, data: &serde_json::Value) -> String {
    let controls: Vec<serde_json::Value> = scene
        .controls
        .iter()
        .map(|c| {
            serde_json::json!({ "name": c.name, "min": c.min, "max": c.max, "step": c.step, "unit": c.unit, "value": c.value })
        })
        .collect();
    let file = scene.path.file_name().map_or("scene.toml".into(), |n| n.to_string_lossy().into_owned());
    let serve = serde_json::json!({ "controls": controls, "file": file });
    let extra = format!(
        "<style>{UPLOT_CSS}</style>\n{PANELS_HTML}\n<script>{UPLOT_JS}</script>\n\
         <script id=\"serve-data\" type=\"application/json\">{}</script>\n<script type=\"module\">\n{SERVE_JS}\n</script>",
        crate::output::script_json(&serve)
    );
    crate::output::page_html(&scene.title, data, &extra)
}
