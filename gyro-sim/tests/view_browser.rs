//! The 3-D view in a real browser: in comes a synthetic run (a ball on an arm turning about z at
//! half a turn per second, its quaternion as columns, a constant arrow); out go screenshots by
//! headless Chromium, checked pixel by pixel against where the run puts the ball and whether
//! the arrow is shown; and a model file's default drawing (`gyro-sim run --model`), its frames
//! and points read from the page's state. Needs `chromium` (Debian: `apt-get install chromium`;
//! `tests/run` installs it); without it these tests fail.

mod serve_support;

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use gyro_sim::Stats;
use gyro_sim::{write_view, ArrowView, BodyView, Orientation, Shape, TraceView, ViewSpec};
use gyro_sim::{Column, Trajectory};

/// Turn rate of the arm about z, rad/s: half a turn per second.
const RATE: f64 = PI;
/// Where the ball's centre is along the arm (body x).
const ARM: f64 = 0.8;
/// The camera the tests ask for: azimuth and elevation (degrees), distance, field of view.
const CAM: (f64, f64, f64, f64) = (30.0, 25.0, 4.0, 45.0);
const WIDTH: u32 = 800;
const HEIGHT: u32 = 600;

fn trajectory() -> Trajectory {
    let names = ["Q_E0", "Q_E1", "Q_E2", "Q_E3", "L_N1", "L_N2", "L_N3", "W_N1", "W_N2", "W_N3"];
    let columns = names
        .iter()
        .map(|n| Column { name: n.to_string(), unit: String::new(), output: true, hidden: false })
        .collect();
    let rows = (0..=400)
        .map(|i| {
            let t = i as f64 * 0.01;
            let half = RATE * t / 2.0;
            vec![t, half.cos(), 0.0, 0.0, half.sin(), -0.6, 0.0, 1.0, 1.5, 0.0, 0.0]
        })
        .collect();
    Trajectory {
        title: "Arm turning about z".to_string(),
        columns,
        rows,
        plot_rows: Vec::new(),
        stats: Stats::default(),
        wall: Duration::ZERO,
        integrated: vec![],
        kinetic_energy: None,
        potential_energy: None,
        accuracy: None,
        norm_drift: None,
        constraints: None,
        events: Default::default(),
    }
}

fn view() -> ViewSpec {
    let q = ["Q_E0", "Q_E1", "Q_E2", "Q_E3"].map(String::from);
    ViewSpec {
        bodies: vec![
            BodyView {
                name: "ball".to_string(),
                shape: Shape::Ellipsoid { a: 0.22.into(), b: 0.22.into(), c: 0.22.into() },
                colour: "#ff00ff".to_string(),
                orientation: Orientation::Quaternion(q.clone()),
                offset: [ARM.into(), 0.0.into(), 0.0.into()],
                opacity: 1.0,
                axis: 3,
                turn: None,
                position: None,
            },
            BodyView {
                name: "arm".to_string(),
                shape: Shape::Box { x: ARM.into(), y: 0.04.into(), z: 0.04.into() },
                colour: "#808080".to_string(),
                orientation: Orientation::Quaternion(q),
                offset: [(ARM / 2.0).into(), 0.0.into(), 0.0.into()],
                opacity: 1.0,
                axis: 3,
                turn: None,
                position: None,
            },
        ],
        arrows: vec![ArrowView {
            label: "L".to_string(),
            colour: "#ffff00".to_string(),
            columns: ["L_N1", "L_N2", "L_N3"].map(String::from),
            scale: 1.0,
        }],
        traces: vec![TraceView {
            body: "ball".to_string(),
            point: [ARM.into(), 0.0.into(), 0.0.into()],
            colour: "#202020".to_string(),
        }],
        up: Some(3),
        frame: Some("N".to_string()),
        ..ViewSpec::default()
    }
}

/// A fresh folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("view_browser").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The page written for the synthetic run.
fn page(dir: &Path) -> PathBuf {
    page_of(dir, &view())
}

/// The page of the synthetic run drawn as `view` says.
fn page_of(dir: &Path, view: &ViewSpec) -> PathBuf {
    let path = dir.join("view.html");
    write_view(&trajectory(), view, &path).expect("view written");
    path
}

/// The Chromium binary, or a failure saying how to install it.
fn chromium() -> &'static str {
    let found =
        Command::new("chromium").arg("--version").stdout(Stdio::null()).stderr(Stdio::null()).status();
    assert!(
        found.is_ok_and(|s| s.success()),
        "the view's browser tests need Chromium: apt-get install chromium (tests/run installs it)"
    );
    "chromium"
}

/// An RGB screenshot of `page` with the URL fragment `fragment`, and its size.
fn screenshot(page: &Path, fragment: &str, name: &str) -> (Vec<u8>, u32, u32) {
    let dir = page.parent().unwrap();
    let png = dir.join(format!("{name}.png"));
    let profile = dir.join(format!("profile-{name}"));
    let url = format!("file://{}#{fragment}", page.display());
    let mut child = Command::new(chromium())
        .args(["--headless", "--disable-gpu", "--no-sandbox", "--hide-scrollbars", "--no-first-run"])
        .args(["--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--virtual-time-budget=5000"])
        // No network: the page must draw from the file alone.
        .arg("--host-resolver-rules=MAP * ~NOTFOUND")
        .arg(format!("--window-size={WIDTH},{HEIGHT}"))
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", png.display()))
        .arg(&url)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("chromium starts");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("chromium took over 120 s on {url}");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let output = child.wait_with_output().unwrap();
    assert!(png.exists(), "no screenshot of {url}: {}", String::from_utf8_lossy(&output.stderr));
    let _ = std::fs::remove_dir_all(&profile);
    decode(&png)
}

/// The pixels of a PNG as RGB bytes, with its width and height.
fn decode(path: &Path) -> (Vec<u8>, u32, u32) {
    let decoder = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    let channels = info.color_type.samples();
    assert!(channels >= 3 && info.bit_depth == png::BitDepth::Eight, "8-bit RGB(A) screenshot");
    let rgb = buf[..info.buffer_size()].chunks(channels).flat_map(|p| [p[0], p[1], p[2]]).collect();
    (rgb, info.width, info.height)
}

/// Shaded magenta (the ball): red and blue alike and well above green.
fn is_magenta(p: &[u8]) -> bool {
    let (r, g, b) = (p[0] as i32, p[1] as i32, p[2] as i32);
    r > 90 && b > 90 && (r - b).abs() < 40 && g < r / 2
}

/// The arrow's yellow (unlit): red and green high, blue low.
fn is_yellow(p: &[u8]) -> bool {
    p[0] > 180 && p[1] > 180 && p[2] < 90
}

/// The pixels where `test` holds, as (x, y).
fn where_(image: &(Vec<u8>, u32, u32), test: fn(&[u8]) -> bool) -> Vec<(f64, f64)> {
    let (rgb, w, _) = image;
    rgb.chunks(3)
        .enumerate()
        .filter(|(_, p)| test(p))
        .map(|(i, _)| ((i as u32 % w) as f64 + 0.5, (i as u32 / w) as f64 + 0.5))
        .collect()
}

/// Where a point in space lands on the screenshot, for the camera the fragment asks for
/// (three.js's perspective camera looking at the origin from `CAM`, z up).
fn project(p: [f64; 3], width: u32, height: u32) -> (f64, f64) {
    let (az, el, dist, fov) = CAM;
    let (az, el) = (az.to_radians(), el.to_radians());
    let eye = [dist * el.cos() * az.cos(), dist * el.cos() * az.sin(), dist * el.sin()];
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    };
    let unit = |a: [f64; 3]| {
        let n = dot(a, a).sqrt();
        [a[0] / n, a[1] / n, a[2] / n]
    };
    let forward = unit(sub([0.0; 3], eye));
    let right = unit(cross(forward, [0.0, 0.0, 1.0]));
    let up = cross(right, forward);
    let d = sub(p, eye);
    let (x, y, depth) = (dot(d, right), dot(d, up), dot(d, forward));
    let half = (fov.to_radians() / 2.0).tan();
    let aspect = width as f64 / height as f64;
    let (nx, ny) = (x / (depth * half * aspect), y / (depth * half));
    ((nx + 1.0) / 2.0 * width as f64, (1.0 - ny) / 2.0 * height as f64)
}

/// The fragment showing time `t` with the test camera, no panels, and the arrows `arrows`.
fn fragment(t: f64, arrows: &str) -> String {
    let (az, el, dist, fov) = CAM;
    format!("t={t}&arrows={arrows}&cam={az},{el},{dist}&target=0,0,0&fov={fov}&ui=0")
}

/// The ball's centre in space at time `t`.
fn ball_at(t: f64) -> [f64; 3] {
    [ARM * (RATE * t).cos(), ARM * (RATE * t).sin(), 0.0]
}

fn mean(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n)
}

#[test]
fn the_ball_is_where_the_run_puts_it() {
    let dir = folder("ball");
    let page = page(&dir);
    for (t, name) in [(0.5, "t0_5"), (1.5, "t1_5"), (1.0, "t1_0")] {
        let shot = screenshot(&page, &fragment(t, ""), name);
        assert_eq!((shot.1, shot.2), (WIDTH, HEIGHT), "screenshot size");
        let (x, y) = project(ball_at(t), shot.1, shot.2);
        let magenta = where_(&shot, is_magenta);
        assert!(magenta.len() > 500, "t = {t}: the ball shows ({} magenta pixels)", magenta.len());
        let (mx, my) = mean(&magenta);
        let off = ((mx - x).powi(2) + (my - y).powi(2)).sqrt();
        assert!(off < 12.0, "t = {t}: ball seen at ({mx:.0}, {my:.0}), the run puts it at ({x:.0}, {y:.0})");
        // Half a turn away there is no ball.
        let (ox, oy) = project(ball_at(t + 1.0), shot.1, shot.2);
        let near_other = magenta.iter().filter(|p| (p.0 - ox).hypot(p.1 - oy) < 20.0).count();
        assert_eq!(near_other, 0, "t = {t}: no ball at ({ox:.0}, {oy:.0}), half a turn away");
    }
}

#[test]
fn space_axis_two_drawn_up_turns_the_picture() {
    let dir = folder("up");
    let page = page_of(&dir, &ViewSpec { up: Some(2), ..view() });
    // Drawn axes (x, y, z) are space (N3, N1, N2): at t = 0.5 the ball, at N2 * ARM in space,
    // is drawn straight above the support.
    let shot = screenshot(&page, &fragment(0.5, ""), "up2");
    let [sx, sy, sz] = ball_at(0.5);
    let (x, y) = project([sz, sx, sy], shot.1, shot.2);
    let (mx, my) = mean(&where_(&shot, is_magenta));
    let off = ((mx - x).powi(2) + (my - y).powi(2)).sqrt();
    assert!(off < 12.0, "ball seen at ({mx:.0}, {my:.0}), drawn N2-up it is at ({x:.0}, {y:.0})");
}

#[test]
fn an_arrow_toggled_off_leaves_the_picture() {
    let dir = folder("arrow");
    let page = page(&dir);
    let on = screenshot(&page, &fragment(1.0, "L"), "arrow_on");
    let off = screenshot(&page, &fragment(1.0, ""), "arrow_off");
    let yellow_on = where_(&on, is_yellow);
    assert!(yellow_on.len() > 100, "the arrow shows ({} yellow pixels)", yellow_on.len());
    // The arrow's tip (-0.6, 0, 1) is in the yellow.
    let (tx, ty) = project([-0.6, 0.0, 1.0], on.1, on.2);
    assert!(
        yellow_on.iter().any(|p| (p.0 - tx).hypot(p.1 - ty) < 8.0),
        "yellow at the tip ({tx:.0}, {ty:.0})"
    );
    assert_eq!(where_(&off, is_yellow).len(), 0, "no yellow once the arrow is off");
    assert!(where_(&off, is_magenta).len() > 500, "the rest of the scene is still drawn");
}

fn is_cyan(p: &[u8]) -> bool {
    p[0] < 90 && p[1] > 150 && p[2] > 150
}

#[test]
fn an_arrow_through_a_body_is_drawn_over_it() {
    let dir = folder("arrow_through");
    let through = ArrowView {
        label: "W".to_string(),
        colour: "#00ffff".to_string(),
        columns: ["W_N1", "W_N2", "W_N3"].map(String::from),
        scale: 1.0,
    };
    let mut spec = view();
    spec.arrows = vec![through];
    let page = page_of(&dir, &spec);
    // At t = 0 the ball is centred on the arrow's shaft (x = ARM), in front of it.
    let shot = screenshot(&page, &fragment(0.0, "W"), "arrow_through");
    let (cx, cy) = project(ball_at(0.0), shot.1, shot.2);
    let cyan = where_(&shot, is_cyan);
    let over_ball = cyan.iter().filter(|p| (p.0 - cx).hypot(p.1 - cy) < 6.0).count();
    assert!(over_ball > 0, "the shaft shows across the ball's centre ({cx:.0}, {cy:.0})");
    assert!(where_(&shot, is_magenta).len() > 500, "the ball is drawn");
}

#[test]
fn the_page_with_its_panels_renders() {
    let dir = folder("panels");
    let page = page(&dir);
    let shot = screenshot(&page, "t=1.25", "panels");
    assert!(where_(&shot, is_magenta).len() > 300, "the ball shows under the default camera");
    assert!(where_(&shot, is_yellow).len() > 100, "the arrow is shown by default");
}

/// Nothing a browser would fetch: no `http(s)://` anywhere except the XML namespace names
/// three.js passes to `createElementNS`; no `src`, `href`, `url(` or `@import` in the markup;
/// the page's script imports only the inline three.js text (as a blob) and fetches nothing.
#[test]
fn the_page_fetches_nothing() {
    let dir = folder("offline");
    let html = std::fs::read_to_string(page(&dir)).unwrap();
    let namespaces = ["http://www.w3.org/1999/xhtml", "http://www.w3.org/2000/svg"];
    let mut rest = html.as_str();
    while let Some(i) = rest.find("http") {
        let url = &rest[i..];
        let is_url = url.starts_with("http://") || url.starts_with("https://");
        let shown: String = url.chars().take(60).collect();
        assert!(!is_url || namespaces.iter().any(|n| url.starts_with(n)), "URL in the page: {shown}");
        rest = &rest[i + 4..];
    }
    // The markup: the page with each script element's text taken out.
    let (mut markup, mut scripts) = (String::new(), Vec::new());
    let mut rest = html.as_str();
    while let Some(open) = rest.find("<script") {
        let body = open + rest[open..].find('>').unwrap() + 1;
        let close = body + rest[body..].find("</script>").unwrap();
        markup.push_str(&rest[..body]);
        scripts.push(&rest[body..close]);
        rest = &rest[close..];
    }
    markup.push_str(rest);
    let markup = markup.to_ascii_lowercase();
    for needle in ["src=", "href=", "<link", "<img", "<iframe", "url(", "@import", "//"] {
        assert!(!markup.contains(needle), "the markup loads something: {needle}");
    }
    assert_eq!(scripts.len(), 3, "three inline scripts: three.js, the data, the page's script");
    let script = scripts[2];
    assert_eq!(script.matches("import(").count(), 1, "one import");
    assert!(script.contains("await import(URL.createObjectURL(new Blob([source]"), "of the inline text");
    for needle in ["fetch(", "XMLHttpRequest", "import ", "src =", ".src=", "href"] {
        assert!(!script.contains(needle), "the page's script loads something: {needle}");
    }
}

#[test]
fn a_model_file_s_frames_and_points_are_drawn_where_its_run_puts_them() {
    let dir = folder("model_drawing");
    let out = dir.join("out");
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/double_pendulum.al");
    let run = Command::new(serve_support::BIN)
        .args(["run", "--model", model, "--engine", "instant", "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    // The rows at t = 1.5 s: the coordinates, and where BO and P are by hand (L = 1).
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let row: Vec<f64> =
        csv.lines().find(|l| l.starts_with("1.5,")).unwrap().split(',').map(|x| x.parse().unwrap()).collect();
    let (q1, q12) = (row[1], row[1] + row[2]);
    let hand_bo = [q1.cos() + 0.5 * q12.cos(), q1.sin() + 0.5 * q12.sin(), 0.0];
    let hand_ao = [0.5 * q1.cos(), 0.5 * q1.sin(), 0.0];
    chromium();
    let url = format!("file://{}#t=1.5&play=0", out.join("view.html").display());
    let mut browser = serve_support::cdp::Browser::open(&url, &dir.join("profile"));
    browser.wait_for("window.gyroView !== undefined && gyroView.time() === 1.5");
    let points = browser.eval("gyroView.pointsDrawn()");
    let bodies = browser.eval("gyroView.bodiesDrawn()");
    let xyz = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
    };
    let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
    let bo = xyz(&points["BO"]["at"]);
    assert!(close(&bo, &hand_bo), "BO drawn at {bo:?}, by hand {hand_bo:?}");
    assert_eq!((points["BO"]["from"].as_str(), points["BO"]["line"].as_bool()), (Some("P"), Some(true)));
    assert_eq!((points["O"]["from"].as_str(), points["O"]["line"].as_bool()), (None, Some(false)));
    // Gravity along -N2: N2 is drawn upward (three's z).
    let drawn = xyz(&points["BO"]["drawn"]);
    assert!((drawn[2] - hand_bo[1]).abs() < 1e-6, "BO's N2 {} drawn at height {}", hand_bo[1], drawn[2]);
    // Frame A's axes stand at its mass centre AO.
    let a_origin = xyz(&bodies["A"]["origin"]);
    assert!(close(&a_origin, &hand_ao), "A's axes at {a_origin:?}, AO by hand {hand_ao:?}");
}
