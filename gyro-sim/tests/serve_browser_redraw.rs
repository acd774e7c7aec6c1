//! What `gyro-sim serve`'s page redraws after a slider moves, in headless Chromium: in come
//! scenes of model files (docs/examples/pendulum.al with a slider for its length, a gimbal
//! variant with one for its rotor speed) and the EJS cusp preset; out go checks that the camera
//! frames a drawing grown out of its view (keeping the user's turn, and still for a small
//! change), that the title shows the values run, that angles of very different sizes get y
//! axes of their own with no tick label cut (a top's two elevations sharing one), and that the
//! torque arrow is not named like the space axes N1, N2, N3.

mod serve_support;

use std::path::{Path, PathBuf};

use serve_support::cdp::Browser;
use serve_support::*;

/// A model file of the repository, by its path from the workspace's root.
fn model_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(path).canonicalize().unwrap()
}

/// A scene of the pendulum model file with a slider for its length L, written into `dir`.
fn pendulum_scene(dir: &Path) -> PathBuf {
    let model = model_file("docs/examples/pendulum.al");
    let text = format!(
        "title = \"pendulum (model file)\"\nmodel = {:?}\nt_final = 10.0\noutput_step = 0.1\n\
         outputs = [\"Q\", \"U\"]\n[parameters]\nL = 1.0\nM = 1.0\nG = 9.81\n\
         [initial]\nQ = 0.5235987755982988\nU = 0.0\n[view]\ndraw_model = true\n\
         [[controls]]\nname = \"L\"\nmin = 0.2\nmax = 5.0\nstep = 0.05\n",
        model.display().to_string()
    );
    let path = dir.join("pendulum.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// A scene of the gimbal variant model file with a slider for its rotor speed U3 (10 rad/s at
/// first), written into `dir`.
fn gimbal_scene(dir: &Path) -> PathBuf {
    let model = model_file("gyro-sim/tests/data/variant_gimbal.al");
    let text = format!(
        "title = \"variant_gimbal (model file)\"\nmodel = {:?}\nt_final = 5.0\noutput_step = 0.05\n\
         outputs = [\"Q1\", \"Q2\", \"Q3\", \"U1\", \"U2\", \"U3\", \"AP\", \"A_B\", \"A_C\", \"A_D\"]\n\
         [initial]\nU3 = \"10 rad/s\"\n[view]\ndraw_model = true\n\
         [[controls]]\nname = \"U3\"\nmin = 0.0\nmax = 200.0\nstep = 1.0\n",
        model.display().to_string()
    );
    let path = dir.join("gimbal.toml");
    std::fs::write(&path, text).unwrap();
    path
}

/// The page of `scene`, served, open in a browser and paused; the server is kept with it.
fn open(scene: &Path, dir: &Path) -> (Server, Browser) {
    let server = serve(scene);
    let mut browser = Browser::open(&format!("http://{}/", server.address), &dir.join("profile"));
    browser.wait_for("window.gyroState?.ready === true");
    browser.eval("gyroView.pause()");
    (server, browser)
}

/// Moves the slider of control `name` to `value` as a user would and waits for the redraw.
fn slide(browser: &mut Browser, name: &str, value: f64) {
    let answer = move_slider_once(browser, name, value);
    assert_eq!(answer["redrew"], true, "{name} = {value}: {answer}");
}

/// The camera's framing as the page gives it.
fn framing(browser: &mut Browser) -> serde_json::Value {
    browser.eval("gyroView.framing()")
}

/// The page's two titles (the tab's and the one on the page), both `title`.
fn both(title: &str) -> serde_json::Value {
    serde_json::json!([title, title])
}

/// A number of a JSON value.
fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Where the pendulum's bob falls on the screen (-1 to 1 when in view) at 21 times of the run.
fn bob_on_screen(browser: &mut Browser) -> Vec<(f64, f64)> {
    let places = browser.eval(
        "(() => { const ts = gyroView.data().t; const out = [];
           for (let k = 0; k <= 20; k++) {
             gyroView.seek(ts[Math.round((k * (ts.length - 1)) / 20)]);
             out.push(gyroView.onScreen(gyroView.pointsDrawn().AO.drawn));
           }
           return out; })()",
    );
    places.as_array().unwrap().iter().map(|p| (num(&p[0]), num(&p[1]))).collect()
}

#[test]
fn the_camera_frames_a_pendulum_made_longer_and_keeps_the_users_turn() {
    let dir = folder("browser_redraw_framing");
    let (_server, mut browser) = open(&pendulum_scene(&dir), &dir);
    // The user turns the view: a drag across the picture.
    browser.eval(
        "(() => { const c = document.querySelector('#scene canvas');
           const at = (type, x, y) => c.dispatchEvent(new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, bubbles: true }));
           at('pointerdown', 600, 400); at('pointermove', 650, 380); at('pointerup', 650, 380); })()",
    );
    let turned = framing(&mut browser);
    assert_eq!((num(&turned["azimuth"]), num(&turned["elevation"])), (20.0, 12.0), "{turned}");

    // A small change stays in the view: the camera does not move.
    slide(&mut browser, "L", 1.05);
    let small = framing(&mut browser);
    assert_eq!(
        (&small["refits"], &small["distance"]),
        (&serde_json::json!(0), &turned["distance"]),
        "{small}"
    );

    // Three times as long: framed again, from the same direction, and the bob stays in view.
    slide(&mut browser, "L", 3.0);
    let grown = framing(&mut browser);
    assert_eq!(grown["refits"], 1, "{grown}");
    assert_eq!((&grown["azimuth"], &grown["elevation"]), (&turned["azimuth"], &turned["elevation"]));
    let ratio = num(&grown["distance"]) / num(&turned["distance"]);
    assert!((2.5..3.5).contains(&ratio), "the camera backs off with the size: {ratio}");
    for (x, y) in bob_on_screen(&mut browser) {
        assert!(x.abs() <= 1.0 && y.abs() <= 1.0, "the bob left the view: ({x}, {y})");
    }

    // Much shorter: framed again, closer.
    slide(&mut browser, "L", 0.3);
    let shrunk = framing(&mut browser);
    assert_eq!(shrunk["refits"], 2, "{shrunk}");
    assert!(num(&shrunk["distance"]) < 0.2 * num(&grown["distance"]), "{shrunk}");
    assert_eq!(shrunk["azimuth"], turned["azimuth"]);

    // The title says the length run, in the tab and on the page.
    let titles = browser.eval("[document.title, document.getElementById('title').textContent]");
    assert_eq!(titles, both("pendulum (model file) — now L = 0.3"));
}

#[test]
fn the_title_shows_the_values_run() {
    let dir = folder("browser_redraw_title");
    let (_server, mut browser) = open(&scene_path("ejs/cusp.toml"), &dir);
    let title = |browser: &mut Browser| {
        browser.eval("[document.title, document.getElementById('title').textContent]")
    };
    let first = "EJS top: cusp (60 deg, spin 10 rad/s, at rest)";
    assert_eq!(title(&mut browser), both(first));
    slide(&mut browser, "spin", 20.5);
    slide(&mut browser, "tilt", 45.0);
    assert_eq!(title(&mut browser), both("EJS top: cusp (45 deg, spin 20.5 rad/s, at rest)"));
    slide(&mut browser, "precession", 0.5);
    let now = "EJS top: cusp (45 deg, spin 20.5 rad/s, at rest) — now precession = 0.5 rad/s";
    assert_eq!(title(&mut browser), both(now));
    for (name, value) in [("spin", 10.0), ("tilt", 60.0), ("precession", 0.0)] {
        slide(&mut browser, name, value);
    }
    assert_eq!(title(&mut browser), both(first), "the scene's own values, its own title");
}

/// The second window's y axes: each series' scale, and for each axis the room its tick labels
/// have and the widest of them (CSS pixels).
fn plot_axes(browser: &mut Browser) -> serde_json::Value {
    browser.eval(
        "(() => { const u = gyroState.plot();
           const ctx = document.createElement('canvas').getContext('2d');
           const axes = u.axes.slice(1).map((a) => {
             ctx.font = a.font[0];
             const widest = Math.max(0, ...a._values.map((v) => ctx.measureText(v).width / devicePixelRatio));
             return { scale: a.scale, room: a._size - a.ticks.size - a.gap, widest, values: a._values };
           });
           const series = Object.fromEntries(u.series.slice(1).map((s) => [s.label, s.scale]));
           return { axes, series, title: document.querySelector('#plot .title').textContent }; })()",
    )
}

/// No y axis's tick label is wider than the room the axis gives it.
fn assert_no_label_cut(axes: &serde_json::Value) {
    for a in axes["axes"].as_array().unwrap() {
        assert!(num(&a["widest"]) <= num(&a["room"]), "a tick label is cut: {a}");
    }
}

#[test]
fn a_spin_angle_gets_a_y_axis_of_its_own_and_no_tick_label_is_cut() {
    let dir = folder("browser_redraw_axes");
    let (_server, mut browser) = open(&gimbal_scene(&dir), &dir);
    let slow = plot_axes(&mut browser);
    assert_eq!(slow["title"], "Q1, Q2, Q3 against time");
    assert_no_label_cut(&slow);
    // At 100 rad/s the rotor turns some 28,000 degrees, the gimbals some tens or hundreds.
    slide(&mut browser, "U3", 100.0);
    let fast = plot_axes(&mut browser);
    assert_no_label_cut(&fast);
    let scale = |name: &str| fast["series"][format!("{name} (deg)")].as_str().unwrap().to_string();
    assert_ne!(scale("Q3"), scale("Q1"), "{fast}");
    assert_ne!(scale("Q3"), scale("Q2"), "{fast}");
    let q3 = fast["axes"].as_array().unwrap().iter().find(|a| a["scale"] == scale("Q3").as_str()).unwrap();
    assert!(q3["values"].as_array().unwrap().iter().any(|v| v.as_str().unwrap().contains(',')), "{q3}");
}

#[test]
fn the_torque_arrow_is_not_named_like_the_axes() {
    let dir = folder("browser_redraw_torque");
    let (_server, mut browser) = open(&scene_path("ejs/cusp.toml"), &dir);
    let shown = browser.eval("[...document.querySelectorAll('#arrows label')].map((l) => l.textContent)");
    assert_eq!(shown, serde_json::json!(["L", "omega", "torque"]));
    assert_eq!(
        browser.eval("gyroView.arrowTags()"),
        serde_json::json!({ "L": "L", "omega": "omega", "N": "torque" })
    );
    assert_eq!(browser.eval("gyroView.arrowsShown().N"), true, "the scene's label still names it");
}

#[test]
fn the_tops_two_elevations_share_one_axis() {
    let dir = folder("browser_redraw_elevations");
    let (_server, mut browser) = open(&scene_path("ejs/cusp.toml"), &dir);
    let axes = plot_axes(&mut browser);
    assert_eq!(axes["series"], serde_json::json!({ "ELEVATION (deg)": "y", "L_ELEVATION (deg)": "y" }));
    assert_no_label_cut(&axes);
}
