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

/// Waits in the page until `condition` holds (60 s at most).
const UNTIL: &str = "const until = async (f) => { for (let i = 0; i < 1200; i++) { if (f()) return; \
    await new Promise((r) => setTimeout(r, 50)); } throw new Error('timed out waiting for ' + f); };";

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
    let speeds: Vec<f64> = (0..20).map(|k| 120.0 + 2.0 * k as f64).collect();
    report("trial3", "U3", move_slider(&mut browser, "U3", &speeds));
    let u3 = speeds[speeds.len() - 1];
    let q2 = browser.eval("gyroView.valueAt('Q2', 2.5)").as_f64().unwrap();
    let (header, rows) = run_saved(&server.address, &format!("{{\"values\": {{\"U3\": {u3}}}}}"), &dir);
    let row = rows.iter().position(|r| (r[0] - 2.5).abs() < 1e-9).expect("a row at t = 2.5");
    let run = csv_column(&header, &rows, "q2_deg")[row];
    assert!((q2.to_degrees() - run).abs() < 1e-7, "Q2 at t = 2.5: page {} deg, run {run}", q2.to_degrees());
}

/// Every EJS preset of the heavy top is served with its controls: the spin slider moved 10 times
/// redraws each time with no error shown, and the latency is printed for BENCHMARKS.md.
#[test]
#[ignore = "fails at the DevTools call (serve_support/cdp.rs:57) on some preset: not yet diagnosed"]
fn every_top_preset_redraws_as_its_spin_slider_moves() {
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
        let spins: Vec<f64> = (1..=10).map(|k| spin + step * k as f64).collect();
        report(preset, "spin", move_slider(&mut browser, "spin", &spins));
        let state = browser.eval("({ spin: gyroState.values.spin, error: gyroState.error })");
        assert_eq!(state["spin"], spins[9], "{preset}");
        assert_eq!(state["error"], "", "{preset}");
    }
}
