//! `gyro-sim serve` under load: in come the EJS cusp preset and many clients at once, each moving
//! sliders (a run per request, now and then a malformed one); out go checks that every request
//! gets its answer (200 for a run, the 4xx its fault calls for), the server stays up and its
//! resident memory stays flat. `SERVE_LOAD_CLIENTS` (default 50) and `SERVE_LOAD_SECONDS`
//! (default 5; RELIABILITY.md's figures are from 30) set the load.

mod serve_support;

use serve_support::*;
use std::time::{Duration, Instant};

/// A number from the environment, or `default`.
fn setting(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// The server's resident memory, KiB (Linux: /proc; elsewhere none).
fn resident_kib(pid: u32) -> Option<u64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// The `k`-th request of client `c`: mostly a slider moved, every seventh a malformed one; its
/// body and the status it must get.
fn request_for(c: usize, k: usize) -> (String, u16) {
    let spin = 5.0 + ((c * 31 + k * 7) % 60) as f64 * 0.5;
    match (c + k) % 7 {
        0 => (format!("{{\"values\": {{\"spin\": {}}}}}", spin + 100.0), 400),
        1 => ("{\"values\": {\"spin\": ".to_string(), 400),
        2 => (format!("{{\"values\": {{\"RR\": {}}}}}", 0.5 + (k % 10) as f64 * 0.1), 200),
        _ => (format!("{{\"values\": {{\"spin\": {spin}, \"tilt\": {}}}}}", 30 + (c % 60)), 200),
    }
}

#[test]
fn fifty_clients_moving_sliders_get_every_answer_and_memory_stays_flat() {
    let clients = setting("SERVE_LOAD_CLIENTS", 50) as usize;
    let seconds = setting("SERVE_LOAD_SECONDS", 5);
    let server = serve(&scene_path("ejs/cusp.toml"));
    let pid = server.pid();
    let start = Instant::now();
    let until = start + Duration::from_secs(seconds);
    let workers: Vec<_> = (0..clients)
        .map(|c| {
            let address = server.address.clone();
            std::thread::spawn(move || {
                let mut answers = Vec::new();
                for k in 0.. {
                    if Instant::now() >= until {
                        break;
                    }
                    let (body, expected) = request_for(c, k);
                    let sent = Instant::now();
                    let (status, json) = post_json(&address, "/api/run", &body);
                    answers.push((status, expected, sent.elapsed().as_secs_f64(), json["error"].clone()));
                }
                answers
            })
        })
        .collect();
    let mut memory = Vec::new();
    while Instant::now() < until {
        memory.extend(resident_kib(pid).map(|kib| (start.elapsed().as_secs_f64(), kib)));
        std::thread::sleep(Duration::from_millis(250));
    }
    let answers: Vec<_> = workers.into_iter().flat_map(|w| w.join().unwrap()).collect();
    memory.extend(resident_kib(pid).map(|kib| (start.elapsed().as_secs_f64(), kib)));
    let wrong: Vec<_> = answers.iter().filter(|(status, expected, ..)| status != expected).collect();
    assert!(
        wrong.is_empty(),
        "{} of {} answers were not the expected status: {:?}",
        wrong.len(),
        answers.len(),
        &wrong[..wrong.len().min(5)]
    );
    let (status, page) = request(&server.address, "GET", "/", b"");
    assert!(
        status == 200 && String::from_utf8_lossy(&page).contains("gyroState"),
        "the server still serves its page"
    );
    report(clients, seconds, &answers, &memory);
}

/// Prints the figures RELIABILITY.md records and checks the memory is flat: the last samples no
/// more than the warmed-up ones (after the first fifth of the run) plus 25% and 16 MiB.
fn report(
    clients: usize,
    seconds: u64,
    answers: &[(u16, u16, f64, serde_json::Value)],
    memory: &[(f64, u64)],
) {
    let runs: Vec<f64> = answers.iter().filter(|a| a.0 == 200).map(|a| a.2 * 1e3).collect();
    let mut sorted = runs.clone();
    sorted.sort_by(f64::total_cmp);
    let at = |q: f64| sorted.get(((sorted.len() as f64 - 1.0) * q) as usize).copied().unwrap_or(f64::NAN);
    println!(
        "{clients} clients for {seconds} s: {} requests ({} runs answered 200, {} malformed answered 400), \
         0 failed; a run's answer after median {:.0} ms, 99th percentile {:.0} ms",
        answers.len(),
        runs.len(),
        answers.len() - runs.len(),
        at(0.5),
        at(0.99)
    );
    let Some(&(_, last)) = memory.last() else { return };
    let warm: Vec<u64> = memory.iter().filter(|(t, _)| *t >= seconds as f64 / 5.0).map(|m| m.1).collect();
    let (first, peak) =
        (warm.first().copied().unwrap_or(last), memory.iter().map(|m| m.1).max().unwrap_or(last));
    println!(
        "server resident memory: {:.1} MiB at {:.0} s, peak {:.1} MiB, {:.1} MiB at the end",
        first as f64 / 1024.0,
        seconds as f64 / 5.0,
        peak as f64 / 1024.0,
        last as f64 / 1024.0
    );
    assert!(last as f64 <= first as f64 * 1.25 + 16.0 * 1024.0, "memory grew from {first} KiB to {last} KiB");
}
