//! Unit tests of the server's answers: in comes a small top scene with controls; out go checks
//! that only the page and the API are served, that runs follow the values sent and that bad
//! requests and failed runs are answered with their reason.

use super::*;

const SCENE: &str = "title = \"top\"\nmodel = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n\
outputs = [\"E4\", \"E1\", \"E2\", \"E3\", \"W1\", \"W2\", \"W3\", \"ELEVATION\", \"L_ELEVATION\"]\n\
[integrator]\nmethod = \"dop853\"\nrtol = 1e-9\natol = 1e-9\n\
[axle]\ntilt = \"60 deg\"\nspin = \"10 rad/s\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\", \"W2\", \"W3\"]\n\
[[controls]]\nname = \"spin\"\nmin = 0\nmax = 40\n";

fn app_of(text: &str) -> App {
    app(Scene::parse("top.toml", text).unwrap(), Registry::builtin()).unwrap()
}

fn json(reply: &Reply) -> serde_json::Value {
    serde_json::from_slice(&reply.body).unwrap()
}

#[test]
fn only_the_page_and_the_api_are_served() {
    let app = app_of(SCENE);
    let page = answer(&app, "GET", "/", b"");
    assert_eq!((page.status, page.content_type), (200, "text/html; charset=utf-8"));
    let html = String::from_utf8(page.body).unwrap();
    assert!(html.contains("id=\"serve-data\"") && html.contains("uPlot") && html.contains("gyroView"));
    for path in ["/../Cargo.toml", "/etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/assets/three.js", "//"] {
        assert_eq!(answer(&app, "GET", path, b"").status, 404, "{path}");
    }
    assert_eq!(answer(&app, "GET", "/api/run", b"").status, 405);
    assert_eq!(answer(&app, "POST", "/", b"").status, 405);
}

#[test]
fn a_run_follows_the_values_sent() {
    let app = app_of(SCENE);
    let reply = answer(&app, "POST", "/api/run", br#"{"values": {"spin": 20}}"#);
    assert_eq!(reply.status, 200, "{}", String::from_utf8_lossy(&reply.body));
    let data = json(&reply);
    assert_eq!(data["values"]["spin"], 20.0);
    assert_eq!(data["plot"], serde_json::json!(["ELEVATION", "L_ELEVATION"]));
    assert_eq!(data["t"].as_array().unwrap().len(), 11);
    let direct = run_data(&app.scene.with_controls(&[(0, 20.0)]), &app.registry).unwrap();
    for name in ["ELEVATION", "L_ELEVATION"] {
        let (a, b) = (data["columns"][name].as_array().unwrap(), direct["columns"][name].as_array().unwrap());
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!((x - y).abs() <= 1e-12, "{name}: {x} against {y}");
        }
    }
    let first = json(&answer(&app, "POST", "/api/run", br#"{"values": {}}"#));
    assert_ne!(first["columns"]["ELEVATION"], data["columns"]["ELEVATION"], "the spin changes the motion");
}

#[test]
fn bad_requests_are_refused_and_failed_runs_explained() {
    let app = app_of(SCENE);
    let error = |body: &[u8]| {
        let r = answer(&app, "POST", "/api/run", body);
        (r.status, json(&r)["error"].as_str().unwrap().to_string())
    };
    assert_eq!(
        error(br#"{"values": {"spin": 99}}"#),
        (400, "spin = 99 is outside its range, 0 to 40 rad/s".into())
    );
    assert_eq!(error(b"not json").0, 400);
    assert_eq!(error(&vec![b'{'; request::MAX_BODY + 1]).0, 413);
    // A scene whose run passes the step limit (an app built around it without its first run).
    let few_steps = SCENE.replace("atol = 1e-9\n", "atol = 1e-9\nmax_steps = 5\n");
    let app = App {
        scene: Scene::parse("top.toml", &few_steps).unwrap(),
        registry: Registry::builtin(),
        page: String::new(),
        runs: gate::Gate::new(1),
    };
    let r = answer(&app, "POST", "/api/run", br#"{"values": {"spin": 12}}"#);
    let message = json(&r)["error"].as_str().unwrap().to_string();
    assert_eq!(r.status, 422, "{message}");
    assert!(message.contains("max_steps"), "{message}");
}

#[test]
fn the_saved_scene_has_the_values_sent() {
    let app = app_of(SCENE);
    let reply = answer(&app, "POST", "/api/scene", br#"{"values": {"spin": 12.5}}"#);
    assert_eq!((reply.status, reply.download.as_deref()), (200, Some("top.toml")));
    let text = String::from_utf8(reply.body).unwrap();
    assert!(text.contains("spin = \"12.5 rad/s\"\n"), "{text}");
    assert_eq!(Scene::parse("top.toml", &text).unwrap().controls[0].value, 12.5);
}
