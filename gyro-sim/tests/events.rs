//! Events (`[[events]]`): the Lagrange top's nutation turning points and the time its axle goes
//! below the horizontal equal the closed form's, to 1e-9 s; stop events end the run there;
//! direction filters and counts; the gimbal-lock preset on the paper's Trial 2; bad expressions
//! and presets named with the file, the event and the place.
//!
//! Closed form (the Lagrange top's Jacobi solution): with `u = cos(theta)` starting at its
//! largest root `u2` (theta at its minimum, "start": "u2"), `u(t) = u1 + (u2 - u1) cd^2(lambda t
//! | m)`: the nutation period is `T = 2 K(m) / lambda` and the turning points are at `k T / 2`;
//! `u` first falls to a level `v` at `(K(m) - F(phi | m)) / lambda`, `sin^2(phi) = (v - u1) /
//! (u2 - u1)` (as `cd(x) = sn(K - x)`). The numbers
//! (`jacobi` and `cubic_roots`) are read from `tests/data/ejs/top_{cusp,loops}_conserved.json`,
//! copies of the project's shared closed-form references (see PROVENANCE.md there), computed in
//! 40-digit arithmetic.

use gyro_sim::run;
use gyro_sim::Scene;
use gyro_sim::Trajectory;

/// The closed form's numbers for `case` (`cusp`, `loops`).
struct Closed {
    period: f64,
    m: f64,
    lambda: f64,
    u1: f64,
    u2: f64,
}

fn closed(case: &str) -> Closed {
    let path = format!("{}/tests/data/ejs/top_{case}_conserved.json", env!("CARGO_MANIFEST_DIR"));
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let num = |section: &str, key: &str| -> f64 { json[section][key].as_str().unwrap().parse().unwrap() };
    assert_eq!(json["jacobi"]["start"], "u2", "the references start at theta's minimum");
    Closed {
        period: num("jacobi", "nutation_period"),
        m: num("jacobi", "m=k^2"),
        lambda: num("jacobi", "lambda"),
        u1: num("cubic_roots", "u1"),
        u2: num("cubic_roots", "u2"),
    }
}

impl Closed {
    /// When `u = cos(theta)` first falls to `v`: `(K - F(phi | m)) / lambda`, the integral of
    /// `1 / sqrt(1 - m sin^2)` from `phi` to `pi/2`, by Gauss-Legendre quadrature (the integrand
    /// is smooth: 64 panels of 5 points are exact to round-off).
    fn time_of(&self, v: f64) -> f64 {
        let phi = ((v - self.u1) / (self.u2 - self.u1)).sqrt().asin();
        let nodes = [
            0.0,
            0.538_469_310_105_683_1,
            -0.538_469_310_105_683_1,
            0.906_179_845_938_664,
            -0.906_179_845_938_664,
        ];
        let weights = [
            0.568_888_888_888_888_9,
            0.478_628_670_499_366_5,
            0.478_628_670_499_366_5,
            0.236_926_885_056_189_1,
            0.236_926_885_056_189_1,
        ];
        let panels = 64;
        let h = (std::f64::consts::FRAC_PI_2 - phi) / panels as f64;
        let f = |x: f64| 1.0 / (1.0 - self.m * x.sin().powi(2)).sqrt();
        let mut sum = 0.0;
        for p in 0..panels {
            let mid = phi + (p as f64 + 0.5) * h;
            sum += nodes.iter().zip(&weights).map(|(x, w)| w * f(mid + 0.5 * h * x)).sum::<f64>() * 0.5 * h;
        }
        sum / self.lambda
    }
}

fn scene_path(rel: &str) -> String {
    format!("{}/scenes/{rel}", env!("CARGO_MANIFEST_DIR"))
}

/// A scene file's text with `extra` appended, parsed as `name`.
fn scene_with(rel: &str, extra: &str) -> Result<Scene, String> {
    let text = std::fs::read_to_string(scene_path(rel)).unwrap() + extra;
    Scene::parse("bad.toml", &text).map_err(|e| e.to_string())
}

fn solve(scene: &Scene) -> Trajectory {
    run(scene, None).unwrap_or_else(|e| panic!("{e}")).trajectory
}

/// The times of event `name`.
fn times(t: &Trajectory, name: &str) -> Vec<f64> {
    t.events.records.iter().filter(|r| r.name == name).map(|r| r.row[0]).collect()
}

#[test]
fn nutation_turning_points_are_the_closed_forms_extrema() {
    for case in ["cusp", "loops"] {
        let c = closed(case);
        let t = solve(&Scene::load(std::path::Path::new(&scene_path(&format!("ejs/{case}.toml")))).unwrap());
        let found = times(&t, "turning_point");
        let half = c.period / 2.0;
        assert_eq!(found.len(), (50.0 / half).floor() as usize, "{case}: {found:?}");
        let worst =
            found.iter().enumerate().map(|(k, t)| (t - (k + 1) as f64 * half).abs()).fold(0.0, f64::max);
        assert!(worst < 1e-9, "{case}: turning points off by {worst:e} s");
        // Alternately the lowest (elevation rising after it) and the highest points.
        let rising: Vec<bool> =
            t.events.records.iter().filter(|r| r.name == "turning_point").map(|r| r.rising).collect();
        assert!(rising.iter().enumerate().all(|(k, r)| *r == (k % 2 == 0)), "{case}: {rising:?}");
        assert!(t.events.stopped.is_none() && t.rows.last().unwrap()[0] == 50.0);
    }
}

#[test]
fn the_taylor_method_finds_the_turning_points_on_its_series() {
    let c = closed("cusp");
    let text = std::fs::read_to_string(scene_path("ejs/cusp.toml")).unwrap();
    let taylor = text.replace("method = \"dop853\"", "method = \"taylor\"");
    assert_ne!(taylor, text);
    let t = solve(&Scene::parse("cusp.toml", &taylor).unwrap());
    let found = times(&t, "turning_point");
    let half = c.period / 2.0;
    assert_eq!(found.len(), (50.0 / half).floor() as usize);
    let worst = found.iter().enumerate().map(|(k, t)| (t - (k + 1) as f64 * half).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-9, "turning points off by {worst:e} s");
}

#[test]
fn a_stop_event_ends_the_run_at_the_axle_going_below_the_horizontal() {
    let c = closed("loops");
    let want = c.time_of(0.0);
    let scene = Scene::load(std::path::Path::new(&scene_path("events/loops_stop.toml"))).unwrap();
    let t = solve(&scene);
    let (name, at) = t.events.stopped.clone().expect("stopped");
    assert_eq!(name, "below_horizontal");
    assert!((at - want).abs() < 1e-9, "stopped at {at}, closed form {want}: {:e}", at - want);
    let last = t.rows.last().unwrap();
    assert_eq!(last[0], at);
    let before: Vec<f64> = t.rows[..t.rows.len() - 1].iter().map(|r| r[0]).collect();
    assert_eq!(
        before.len(),
        (at / 0.1).floor() as usize + 1,
        "rows at the output times before it: {before:?}"
    );
    // The axle's space z component (AXLE_N3, the 10th column) is zero there.
    assert!(last[10].abs() < 1e-12, "axle_n3 = {:e}", last[10]);
    // The elevation crossing 10 deg was recorded on the way.
    let ten = times(&t, "ten_degrees");
    let want_ten = c.time_of(10f64.to_radians().sin());
    assert!(ten.len() == 1 && (ten[0] - want_ten).abs() < 1e-9, "{ten:?} vs {want_ten}");
}

#[test]
fn directions_and_counts() {
    let c = closed("cusp");
    let half = c.period / 2.0;
    let with = |extra: &str| solve(&scene_with("ejs/cusp.toml", extra).unwrap());
    let t = with("[[events]]\nname = \"up\"\nwhen = \"ELEVATION'\"\ndirection = \"up\"\n[[events]]\nname = \"down\"\nwhen = \"ELEVATION'\"\ndirection = \"down\"\n");
    let (up, down) = (times(&t, "up"), times(&t, "down"));
    assert!((up[0] - half).abs() < 1e-9 && (up[1] - 3.0 * half).abs() < 1e-9, "{up:?}");
    assert!((down[0] - 2.0 * half).abs() < 1e-9, "{down:?}");
    assert_eq!(up.len() + down.len(), times(&t, "turning_point").len());
    // A count ends a recording event's run at that crossing: the fourth turning point, 2 T.
    let t = with("[[events]]\nname = \"fourth\"\nwhen = \"(AXLE_N3)'\"\ncount = 4\n");
    let (_, at) = t.events.stopped.clone().unwrap();
    assert!((at - 2.0 * c.period).abs() < 1e-9 && times(&t, "fourth").len() == 4, "{at}");
    // The second time u = cos(theta) falls to 0.45, as a stop with a count: T + t(0.45).
    let t = with("[[events]]\nname = \"level\"\nwhen = \"AXLE_N3 - 0.45\"\ndirection = \"down\"\naction = \"stop\"\ncount = 2\n");
    let (_, at) = t.events.stopped.clone().unwrap();
    let want = c.period + c.time_of(0.45);
    assert!((at - want).abs() < 1e-9, "{at} vs {want}: {:e}", at - want);
    assert_eq!(t.rows.last().unwrap()[0], at);
}

#[test]
fn the_gimbal_lock_preset_finds_the_inner_gimbal_near_lock() {
    // Trial 2 starts at lock (Q2 = 0) and turns Q2 down through -180 deg, lock again.
    let extra = "[[events]]\nname = \"lock\"\npreset = \"gimbal_lock\"\nangle = \"Q2\"\nmargin = \"5 deg\"\n";
    let t = solve(&scene_with("paper/trial2.toml", extra).unwrap());
    let q2 = t.columns.iter().position(|c| c.name == "Q2").unwrap() + 1;
    let found: Vec<f64> = t.events.records.iter().map(|r| r.row[q2].to_degrees()).collect();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!((found[0] + 175.0).abs() < 1e-6, "entered the margin at Q2 = {} deg", found[0]);
    // Both ways: leaving the margin around 0 first (Q2 = -5 deg), then entering it at -175.
    let t = solve(&scene_with("paper/trial2.toml", &format!("{extra}direction = \"both\"\n")).unwrap());
    let found: Vec<f64> = t.events.records.iter().map(|r| r.row[q2].to_degrees()).collect();
    assert!(
        found.len() >= 2 && (found[0] + 5.0).abs() < 1e-6 && (found[1] + 175.0).abs() < 1e-6,
        "{found:?}"
    );
}

#[test]
fn events_csv_is_written_with_the_set_and_the_csv_is_unchanged() {
    let dir = std::env::temp_dir().join(format!("gyro-sim-events-{}", std::process::id()));
    let scene = Scene::load(std::path::Path::new(&scene_path("events/loops_stop.toml"))).unwrap();
    run(&scene, Some(&dir)).unwrap();
    let events = std::fs::read_to_string(dir.join("events.csv")).unwrap();
    let lines: Vec<&str> = events.lines().collect();
    assert!(lines[0].starts_with("event,direction,t,e4,e1,e2,e3,"), "{}", lines[0]);
    assert!(
        lines[1].starts_with("ten_degrees,down,") && lines[2].starts_with("below_horizontal,down,"),
        "{events}"
    );
    // The same scene without events writes the same rows up to the stop, and no events.csv.
    let text = std::fs::read_to_string(scene_path("events/loops_stop.toml")).unwrap();
    let plain = Scene::parse("plain.toml", &text[..text.find("[[events]]").unwrap()]).unwrap();
    run(&plain, Some(&dir)).unwrap();
    assert!(!dir.join("events.csv").exists(), "an earlier set's events.csv is removed");
    let stopped = solve(&scene);
    let full = solve(&plain);
    let n = stopped.rows.len() - 1;
    assert_eq!(stopped.rows[..n], full.rows[..n]);
    assert!(stopped.stats.steps < full.stats.steps);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The error of a cusp scene with `extra` appended.
fn error(extra: &str) -> String {
    match scene_with("ejs/cusp.toml", extra) {
        Ok(s) => run(&s, None).map(|_| ()).unwrap_err().to_string(),
        Err(e) => e,
    }
}

/// The 1-based line of the first line of `extra` after the cusp scene.
fn first_line() -> usize {
    std::fs::read_to_string(scene_path("ejs/cusp.toml")).unwrap().lines().count() + 1
}

#[test]
fn bad_expressions_are_named_with_the_event_and_the_place() {
    let l = first_line();
    let e = error("[[events]]\nname = \"x\"\nwhen = \"ELEVATION - Q9\"\n");
    assert!(
        e.starts_with(&format!("bad.toml:{}:21: error: [[events]] 2 (`x`): unknown name `Q9`", l + 2)),
        "{e}"
    );
    assert!(e.contains("help: an event reads t, pi and these"), "{e}");
    let e = error("[[events]]\nwhen = \"ELEVATION - * 3\"\n");
    assert!(
        e.starts_with(&format!(
            "bad.toml:{}:21: error: [[events]] 2 (`event2`): expected an expression",
            l + 1
        )),
        "{e}"
    );
    let e = error("[[events]]\nwhen = \"ELEVATION''\"\n");
    assert!(e.contains("only one time derivative"), "{e}");
    let e = error("[[events]]\nwhen = \"L'\"\n");
    assert!(e.contains("unknown name `L`"), "a vector output names its columns: {e}");
    let e = error("[[events]]\nwhen = \"ELEVATION\"\ndirection = \"sideways\"\n");
    assert!(
        e.contains(&format!(
            "bad.toml:{}:13: error: [[events]] 2 (`event2`): unknown direction `sideways`",
            l + 2
        )),
        "{e}"
    );
    assert!(e.contains("\"up\", \"down\", \"both\""), "{e}");
    let e = error("[[events]]\nwhen = \"ELEVATION\"\ncount = 0\n");
    assert!(e.contains("count must be at least 1"), "{e}");
    let e = error("[[events]]\nname = \"turning_point\"\nwhen = \"ELEVATION\"\n");
    assert!(e.contains("has the name of [[events]] 1"), "{e}");
    let e = error("[[events]]\nwhen = \"ELEVATION\"\nwhenn = 1\n");
    assert!(e.contains("unknown field `whenn`"), "{e}");
}

#[test]
fn bad_presets_are_named() {
    let e = error("[[events]]\npreset = \"nutation\"\n");
    assert!(e.contains("unknown preset `nutation`") && e.contains("nutation_turning_points"), "{e}");
    let e = error("[[events]]\npreset = \"gimbal_lock\"\nmargin = \"5 deg\"\n");
    assert!(e.contains("preset gimbal_lock needs `angle`"), "{e}");
    let e = error("[[events]]\npreset = \"gimbal_lock\"\nangle = \"Q2\"\nmargin = \"5 deg\"\n");
    assert!(e.contains("`Q2` is not a state of heavy_top"), "{e}");
    let e = error("[[events]]\nwhen = \"E1\"\nmargin = \"5 deg\"\n");
    assert!(e.contains("`margin` belongs to preset = \"gimbal_lock\""), "{e}");
    let e = error("[[events]]\nwhen = \"E1\"\npreset = \"axle_below_horizontal\"\n");
    assert!(e.contains("gives both `when` and `preset`"), "{e}");
    let trial = "[[events]]\npreset = \"axle_below_horizontal\"\n";
    let e = scene_with("paper/trial1.toml", trial)
        .map(|s| run(&s, None).map(|_| ()).unwrap_err().to_string())
        .unwrap_or_else(|e| e);
    assert!(e.contains("this preset needs the scene's [axle] table"), "{e}");
    let rk4 = "[[events]]\nwhen = \"Q2\"\n";
    let text = std::fs::read_to_string(scene_path("paper/trial1.toml"))
        .unwrap()
        .replace("method = \"dopri5\"", "method = \"rk4\"")
        .replace("accuracy = 1e-7", "");
    let e = run(&Scene::parse("bad.toml", &(text + rk4)).unwrap(), None).map(|_| ()).unwrap_err().to_string();
    assert!(
        e.contains("method = \"rk4\" has none") && e.contains("help: set method under [integrator]"),
        "{e}"
    );
}

/// `gyro-sim run SCENE --engine ENGINE --out DIR`; the rows of DIR/events.csv after the name
/// and direction.
fn events_by_command(
    scene: &std::path::Path,
    engine: &str,
    out: &std::path::Path,
) -> Vec<(String, Vec<f64>)> {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene.to_str().unwrap(), "--engine", engine, "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success() && text.contains(&format!("ran {engine}")), "{text}");
    assert!(text.contains("event rate: ") && text.contains("stopped by event level at t = "), "{text}");
    let csv = std::fs::read_to_string(out.join("events.csv")).unwrap();
    csv.lines()
        .skip(1)
        .map(|l| {
            let mut f = l.split(',');
            let name = f.next().unwrap().to_string();
            (name, f.skip(1).map(|x| x.parse().unwrap()).collect())
        })
        .collect()
}

#[test]
fn the_instant_path_finds_the_same_events_as_the_compiled_model() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("events_instant");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/heavy_top.al");
    let text = std::fs::read_to_string(scene_path("events/loops_stop.toml")).unwrap();
    let head = &text[text.find("title").unwrap()..text.find("[[events]]").unwrap()];
    // Rates of a state expression, of an output (dual numbers through its code) and a stop.
    let events = "[[events]]\nname = \"rate\"\nwhen = \"ELEVATION'\"\n[[events]]\nname = \"energy\"\nwhen = \"(ENERGY - E1*W1)'\"\n[[events]]\nname = \"level\"\nwhen = \"AXLE_N3 + 0.1\"\naction = \"stop\"\ncount = 2\n";
    let head = head.replace("outputs = [", "outputs = [\"ENERGY\", ");
    let scene = dir.join("top.toml");
    std::fs::write(
        &scene,
        format!("{head}{events}").replace("model = \"heavy_top\"", &format!("model = {model:?}")),
    )
    .unwrap();
    let instant = events_by_command(&scene, "instant", &dir.join("instant"));
    std::fs::write(&scene, format!("{head}{events}")).unwrap();
    let compiled = events_by_command(&scene, "compiled", &dir.join("compiled"));
    assert_eq!(
        instant.iter().map(|e| &e.0).collect::<Vec<_>>(),
        compiled.iter().map(|e| &e.0).collect::<Vec<_>>()
    );
    assert!(instant.iter().any(|e| e.0 == "rate") && instant.iter().any(|e| e.0 == "energy"), "{instant:?}");
    let worst = instant
        .iter()
        .zip(&compiled)
        .flat_map(|(a, b)| a.1.iter().zip(&b.1).map(|(x, y)| (x - y).abs() / y.abs().max(1.0)))
        .fold(0.0, f64::max);
    assert!(worst < 1e-10, "instant vs compiled events: {worst:e}");
}

#[test]
fn a_sweep_writes_each_members_first_event_times() {
    let out = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("events_sweep");
    let _ = std::fs::remove_dir_all(&out);
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args([
            "sweep",
            &scene_path("events/loops_stop.toml"),
            "--vary",
            "D=1:1.2:2",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    let col = |name: &str| {
        rows[0].iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}: {:?}", rows[0]))
    };
    let (below, turn) = (col("first_t_below_horizontal"), col("first_t_turning_point"));
    let at: f64 = rows[1][below].parse().unwrap();
    assert!((at - closed("loops").time_of(0.0)).abs() < 1e-9, "{at}");
    assert_eq!(rows[1][turn], "NaN", "no turning point before the stop");
    let later: f64 = rows[2][below].parse().unwrap();
    assert!(later > at, "a longer arm (D = 1.2) falls later: {later} vs {at}");
}

/// A free body (I = 1, 2, 3) turning about its axis 1 at `rate` rad/s from the identity, so its
/// Euler parameter E1 is `sin(rate t / 2)` exactly, to `t_final` with rows every `output_step`,
/// at tolerances `tol`, and `events` appended.
fn spinning(rate: f64, t_final: f64, output_step: f64, tol: f64, events: &str) -> String {
    format!(
        "title = \"a free body spinning about axis 1\"\nmodel = \"free_body\"\noutputs = [\"E4\", \"E1\", \"W1\"]\nt_final = {t_final:?}\noutput_step = {output_step:?}\n[integrator]\nmethod = \"dop853\"\nrtol = {tol:e}\natol = {tol:e}\n[parameters]\nI1 = 1.0\nI2 = 2.0\nI3 = 3.0\n[initial]\nE4 = 1.0\nE1 = 0.0\nE2 = 0.0\nE3 = 0.0\nW1 = \"{rate:?} rad/s\"\nW2 = \"0 rad/s\"\nW3 = \"0 rad/s\"\n{events}"
    )
}

fn solve_text(text: &str) -> Trajectory {
    solve(&Scene::parse("spinning.toml", text).unwrap_or_else(|e| panic!("{e}")))
}

#[test]
fn a_stop_a_ten_millionth_of_a_second_into_a_million_second_run() {
    let events = "[[events]]\nname = \"early\"\nwhen = \"t - 1e-7\"\naction = \"stop\"\n";
    let t = solve_text(&spinning(1.0, 1e6, 1000.0, 1e-10, events));
    let (name, at) = t.events.stopped.clone().expect("the run stops at the event");
    assert_eq!(name, "early");
    // The root finder's tolerance: a few units of round-off of the time.
    assert!((at - 1e-7).abs() <= 8.0 * f64::EPSILON * 1e-7, "stopped at {at:e}");
    assert_eq!(t.rows.iter().map(|r| r[0]).collect::<Vec<_>>(), [0.0, at]);
    assert!(t.events.unsettled.is_empty() && t.events.crowded.is_empty(), "{:?}", t.events);
}

#[test]
fn every_crossing_of_a_fast_function_of_time_inside_long_steps() {
    // sin(10000 t) over 10 s of a body turning at 1 rad/s (steps far longer than its period):
    // zero at k pi / 10000, k = 1 .. floor(1e5 / pi).
    let (omega, t_final, output_step) = (10000.0, 10.0, 0.1);
    let events = "[[events]]\nname = \"fast\"\nwhen = \"sin(10000*t)\"\n";
    let t = solve_text(&spinning(1.0, t_final, output_step, 1e-10, events));
    let pi = std::f64::consts::PI;
    let found = times(&t, "fast");
    let want = (omega * t_final / pi).floor() as usize;
    assert_eq!(found.len(), want);
    assert!(t.stats.steps < want / 100, "{} steps: many crossings per step", t.stats.steps);
    let worst =
        found.iter().enumerate().map(|(k, t)| (t - (k + 1) as f64 * pi / omega).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-12, "crossings off by {worst:e} s");
    let rising: Vec<bool> = t.events.records.iter().map(|r| r.rising).collect();
    assert!(rising.iter().enumerate().all(|(k, r)| *r == (k % 2 == 1)), "sin falls first");
    // The most crossings between two rows, from the closed form, are reported as such.
    let count_to = |s: f64| (omega * s / pi).floor() as usize;
    let rows = (t_final / output_step).round() as usize;
    let most = (0..rows)
        .map(|j| count_to((j + 1) as f64 * output_step) - count_to(j as f64 * output_step))
        .max()
        .unwrap();
    assert_eq!(t.events.crowded.len(), 1);
    assert_eq!(t.events.crowded[0].most, most);
    assert!((t.events.crowded[0].gap - pi / omega).abs() < 1e-9, "{:?}", t.events.crowded);
    assert!(t.events.unsettled.is_empty(), "{:?}", t.events.unsettled);
}

#[test]
fn every_zero_of_a_fast_spins_euler_parameter() {
    // Spinning at 20000 rad/s, E1 = sin(10000 t): zero at k pi / 10000.
    let (rate, t_final) = (20000.0, 1.0);
    let events = "[[events]]\nname = \"half_turn\"\nwhen = \"E1\"\n";
    let t = solve_text(&spinning(rate, t_final, 0.01, 1e-12, events));
    let period = 2.0 * std::f64::consts::PI / rate;
    let found = times(&t, "half_turn");
    assert_eq!(found.len(), (t_final / period).floor() as usize);
    let worst =
        found.iter().enumerate().map(|(k, t)| (t - (k + 1) as f64 * period).abs()).fold(0.0, f64::max);
    assert!(worst < 1e-9, "crossings off by {worst:e} s");
}

#[test]
fn two_crossings_close_together_inside_one_step() {
    // E1 = sin(t / 2) rises through 1 - 1e-8 and falls back 2.8e-4 s apart around t = pi,
    // both inside one step of a body turning at 1 rad/s.
    let level: f64 = 1.0 - 1e-8;
    let events = format!("[[events]]\nname = \"near_top\"\nwhen = \"E1 - {level:?}\"\n");
    let t = solve_text(&spinning(1.0, 5.0, 0.1, 1e-13, &events));
    let found = times(&t, "near_top");
    let up = 2.0 * level.asin();
    let want = [up, 2.0 * std::f64::consts::PI - up];
    assert_eq!(found.len(), 2, "{found:?}");
    // E1's slope there is 0.5 cos(t / 2) = 7e-5: an error of 1e-13 in E1 moves a root 1.4e-9 s.
    for (f, w) in found.iter().zip(want) {
        assert!((f - w).abs() < 1e-8, "{found:?} vs {want:?}");
    }
    let mean_step = 5.0 / t.stats.steps as f64;
    assert!(mean_step > 100.0 * (want[1] - want[0]), "steps of {mean_step} s on average");
    assert!(t.events.unsettled.is_empty(), "{:?}", t.events.unsettled);
}

/// `gyro-sim run` of `text` (written to a folder of `name` of its own); its printed summary.
fn summary_of(name: &str, text: &str) -> String {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene.to_str().unwrap(), "--out", dir.join("out").to_str().unwrap()])
        .output()
        .unwrap();
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{text}");
    text
}

#[test]
fn the_summary_warns_of_crossings_the_rows_or_the_steps_cannot_resolve() {
    let fast = "[[events]]\nname = \"fast\"\nwhen = \"sin(10000*t)\"\n";
    let text = summary_of("events_crowded", &spinning(1.0, 1.0, 0.1, 1e-10, fast));
    let line =
        text.lines().find(|l| l.starts_with("warning: event fast: ")).unwrap_or_else(|| panic!("{text}"));
    assert!(line.contains("crossings between the rows at t = ") && line.contains("output_step of"), "{line}");
    // Touching zero without crossing at t = 0.5: no split settles it, and the summary says so.
    let touch = "[[events]]\nname = \"touch\"\nwhen = \"(t - 0.5)^2\"\n";
    let text = summary_of("events_unsettled", &spinning(1.0, 1.0, 0.1, 1e-10, touch));
    let line =
        text.lines().find(|l| l.starts_with("warning: event touch: ")).unwrap_or_else(|| panic!("{text}"));
    let near: f64 =
        line.split("near t = ").nth(1).and_then(|r| r.split(' ').next()).unwrap().parse().unwrap();
    assert!((near - 0.5).abs() < 1e-6 && line.contains("tighten rtol"), "{line}");
}
