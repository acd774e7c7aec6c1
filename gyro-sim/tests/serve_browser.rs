//! `gyro-sim serve`'s page in a real browser: in comes the EJS cusp preset, served, shown in
//! headless Chromium (Debian's `chromium`, driven over the DevTools protocol); out go checks
//! that moving the spin slider redraws the run `gyro-sim run` gives for that spin (the rotor's
//! orientation and the elevation at a known time, read from the page's state), that the arrow
//! toggles hide and show arrows and that an out-of-range value shows the server's error. The
//! latency from a slider change to the new run drawn is printed (median of 20 changes), for the
//! cusp's spin and Trial 3's rotor speed U3.

mod serve_support;

use serve_support::cdp::Browser;
use serve_support::*;

/// The time at which the page's state is compared with the run, s (a row of the CSV).
const AT: f64 = 2.0;

/// Moves the slider of control `name` to each value in turn as a user would (an input event),
/// each time waiting for the redraw; gives the latencies the page measured, ms.
fn move_slider(browser: &mut Browser, name: &str, values: &[f64]) -> Vec<f64> {
    let script = format!(
        "(async () => {{ {UNTIL}
           const slider = document.getElementById('control-{name}');
           const out = [];
           for (const v of {values:?}) {{
             const n = gyroState.redraws;
             slider.value = String(v);
             slider.dispatchEvent(new Event('input'));
             await until(() => gyroState.redraws > n);
             out.push(gyroState.latencies[gyroState.latencies.length - 1]);
           }}
           return out; }})()"
    );
    let value = browser.eval(&script);
    value.as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect()
}

/// Prints the median, least and most of the latencies of a scene's slider.
fn report(scene: &str, control: &str, mut latencies: Vec<f64>) {
    latencies.sort_by(f64::total_cmp);
    println!(
        "{scene}: {control} slider change to redraw over {} changes: median {:.1} ms, least {:.1} ms, most {:.1} ms",
        latencies.len(),
        latencies[latencies.len() / 2],
        latencies[0],
        latencies[latencies.len() - 1]
    );
}

#[test]
fn the_spin_slider_redraws_the_run_gyro_sim_run_gives() {
    let server = serve(&scene_path("ejs/cusp.toml"));
    let dir = folder("browser_cusp");
    let url = format!("http://{}/", server.address);
    let mut browser = Browser::open(&url, &dir.join("profile"));
    browser.wait_for("window.gyroState?.ready === true");
    browser.eval("gyroView.pause()");
    let before = browser.eval(&format!("gyroView.valueAt('ELEVATION', {AT})")).as_f64().unwrap();

    let spins: Vec<f64> = (0..20).map(|k| 12.0 + 0.5 * k as f64).collect();
    report("cusp", "spin", move_slider(&mut browser, "spin", &spins));
    let spin = spins[spins.len() - 1];
    let state = browser.eval(&format!(
        "({{ spin: gyroState.values.spin, e: ['E4', 'E1', 'E2', 'E3'].map((n) => gyroView.valueAt(n, {AT})), \
            elevation: gyroView.valueAt('ELEVATION', {AT}), unit: gyroView.data().units.ELEVATION, \
            box: document.querySelector('#serve input[type=number]').value }})"
    ));
    assert_eq!(state["spin"], spin);
    assert_eq!(state["box"], format!("{spin}"), "the number box follows the slider");
    let (header, rows) = run_saved(&server.address, &format!("{{\"values\": {{\"spin\": {spin}}}}}"), &dir);
    let row = rows.iter().position(|r| (r[0] - AT).abs() < 1e-9).expect("a row at the time compared");
    for (k, name) in ["e4", "e1", "e2", "e3"].iter().enumerate() {
        let (page, run) = (state["e"][k].as_f64().unwrap(), csv_column(&header, &rows, name)[row]);
        assert!((page - run).abs() < 1e-9, "{name} at t = {AT}: page {page}, run {run}");
    }
    let elevation = state["elevation"].as_f64().unwrap();
    assert_eq!(state["unit"], "DEG", "the elevation is an angle (radians in the run, degrees in the CSV)");
    let run = csv_column(&header, &rows, "elevation_deg")[row];
    assert!(
        (elevation.to_degrees() - run).abs() < 1e-7,
        "elevation at t = {AT}: page {}, run {run}",
        elevation.to_degrees()
    );
    assert!((elevation - before).abs() > 1e-3, "the spin changed the elevation at t = {AT}");
}

#[test]
fn toggles_hide_arrows_and_bad_values_show_the_error() {
    let server = serve(&scene_path("ejs/cusp.toml"));
    let dir = folder("browser_errors");
    let mut browser = Browser::open(&format!("http://{}/", server.address), &dir.join("profile"));
    browser.wait_for("window.gyroState?.ready === true");
    let title = browser.eval("document.querySelector('#plot .title').textContent");
    assert_eq!(title.as_str(), Some("Elevation against time"));
    let result = browser.eval(&format!(
        "(async () => {{ {UNTIL}
           await until(() => window.gyroState?.ready);
           gyroView.pause();
           const shown = [gyroView.arrowsShown().L];
           const box = [...document.querySelectorAll('#arrows label')].find((l) => l.textContent === 'L').querySelector('input');
           box.click();
           shown.push(gyroView.arrowsShown().L);
           box.click();
           shown.push(gyroView.arrowsShown().L);
           const number = document.querySelector('#serve input[type=number]');
           number.value = '99';
           number.dispatchEvent(new Event('change'));
           await until(() => gyroState.error !== '');
           return {{ shown, error: document.getElementById('serve-error').textContent, redraws: gyroState.redraws }};
         }})()"
    ));
    assert_eq!(result["shown"], serde_json::json!([true, false, true]));
    assert_eq!(result["error"], "spin = 99 is outside its range, 0 to 40 rad/s");
    assert_eq!(result["redraws"], 0, "nothing was run or drawn");
}

#[test]
fn trial_three_redraws_the_run_for_its_rotor_speed() {
    let server = serve(&scene_path("paper/trial3.toml"));
    let dir = folder("browser_trial3");
    let mut browser = Browser::open(&format!("http://{}/", server.address), &dir.join("profile"));
    browser.wait_for("window.gyroState?.ready === true");
    browser.eval("gyroView.pause()");
    // The second window says what it plots: the gimbal's angles, not a top's elevation.
    let title = browser.eval("document.querySelector('#plot .title').textContent");
    assert_eq!(title.as_str(), Some("Q1, Q2, Q3 against time"));
    let speeds: Vec<f64> = (0..20).map(|k| 120.0 + 2.0 * k as f64).collect();
    report("trial3", "U3", move_slider(&mut browser, "U3", &speeds));
    let u3 = speeds[speeds.len() - 1];
    let q2 = browser.eval("gyroView.valueAt('Q2', 2.5)").as_f64().unwrap();
    let (header, rows) = run_saved(&server.address, &format!("{{\"values\": {{\"U3\": {u3}}}}}"), &dir);
    let row = rows.iter().position(|r| (r[0] - 2.5).abs() < 1e-9).expect("a row at t = 2.5");
    let run = csv_column(&header, &rows, "q2_deg")[row];
    assert!((q2.to_degrees() - run).abs() < 1e-7, "Q2 at t = 2.5: page {} deg, run {run}", q2.to_degrees());
}

/// The rotor's position D and radius RR move and resize the drawn rotor, axle and trace with the
/// run (the view's lengths name the parameters).
#[test]
fn the_rotor_drawn_follows_its_position_and_radius_sliders() {
    let server = serve(&scene_path("ejs/cusp.toml"));
    let dir = folder("browser_rotor_geometry");
    let mut browser = Browser::open(&format!("http://{}/", server.address), &dir.join("profile"));
    browser.wait_for("window.gyroState?.ready === true");
    browser.eval("gyroView.pause()");
    let drawn = |browser: &mut Browser| browser.eval("gyroView.bodiesDrawn()");
    let centre_z = |v: &serde_json::Value, body: &str| v[body]["centre"][2].as_f64().unwrap();
    let before = drawn(&mut browser);
    assert_eq!(centre_z(&before, "rotor"), 1.0);
    assert_eq!(move_slider_once(&mut browser, "D", 1.5)["redrew"], true);
    assert_eq!(move_slider_once(&mut browser, "RR", 0.5)["redrew"], true);
    let after = drawn(&mut browser);
    assert!((centre_z(&after, "rotor") - 1.5).abs() < 1e-12, "the rotor at D: {after}");
    assert!((centre_z(&after, "axle") - 1.8).abs() < 1e-12, "the axle's middle at 1.2 D: {after}");
    let size = |v: &serde_json::Value, body: &str, k: usize| v[body]["size"][k].as_f64().unwrap();
    assert!((size(&after, "rotor", 0) - 1.0).abs() < 1e-6, "the rotor's diameter 2 RR: {after}");
    assert!((size(&after, "rotor", 0) / size(&before, "rotor", 0) - 0.5).abs() < 1e-6, "{before} {after}");
    assert!((size(&after, "axle", 2) - 3.6).abs() < 1e-6, "the axle 2.4 D long: {after}");
}

/// Every EJS preset of the heavy top is served with its controls. Its spin slider is moved 10
/// steps, and each move gets the answer `gyro-sim run` gives for that spin: the run drawn with
/// no error, or, where the run fails (the no-spin preset's accuracy of 1e-8 cannot be reached
/// once it spins), the run's reason shown and nothing drawn. The latency of the redrawn moves
/// is printed for BENCHMARKS.md.
#[test]
fn every_top_preset_answers_its_spin_slider_as_gyro_sim_run_does() {
    for preset in ["cusp", "loops", "waves", "steady", "nospin", "sleeping", "slow", "fast"] {
        let server = serve(&scene_path(&format!("ejs/{preset}.toml")));
        let dir = folder(&format!("browser_preset_{preset}"));
        let mut browser = Browser::open(&format!("http://{}/", server.address), &dir.join("profile"));
        browser.wait_for("window.gyroState?.ready === true");
        browser.eval("gyroView.pause()");
        let names =
            browser.eval("[...document.querySelectorAll('#serve input[type=range]')].map((s) => s.id)");
        let expected = ["spin", "tilt", "precession", "nutation", "D", "RR"].map(|n| format!("control-{n}"));
        assert_eq!(names, serde_json::json!(expected), "{preset}'s sliders");
        let (spin, step) = {
            let s = browser.eval("(() => { const s = document.getElementById('control-spin'); return [Number(s.value), Number(s.step)]; })()");
            (s[0].as_f64().unwrap(), s[1].as_f64().unwrap())
        };
        let mut latencies = Vec::new();
        for k in 1..=10 {
            let value = spin + step * f64::from(k);
            let answer = move_slider_once(&mut browser, "spin", value);
            let body = format!("{{\"values\": {{\"spin\": {value}}}}}");
            match run_saved_outcome(&server.address, &body, &dir) {
                Ok(_) => {
                    assert_eq!(answer["error"], "", "{preset} at spin {value}: the run succeeds");
                    assert_eq!(answer["redrew"], true, "{preset} at spin {value}");
                    latencies.push(answer["latency"].as_f64().unwrap());
                }
                Err(stderr) => {
                    let shown = answer["error"].as_str().unwrap().to_string();
                    assert_eq!(answer["redrew"], false, "{preset} at spin {value}: the run fails: {stderr}");
                    // The run's message is the page's after the scene's path.
                    assert!(
                        !shown.is_empty()
                            && stderr.lines().next().is_some_and(|l| l.ends_with(&format!(": {shown}"))),
                        "{preset} at spin {value}: the page shows {shown:?}, the run says {stderr:?}"
                    );
                }
            }
        }
        if !latencies.is_empty() {
            report(preset, "spin", latencies);
        }
    }
}
