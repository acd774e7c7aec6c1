//! Stop signals: SIGINT, SIGTERM and SIGHUP stop a long run cleanly. The rows computed
//! so far are kept as `trajectory.partial.csv` beside the folder's earlier set (left as it was),
//! a message says so, and the exit code is the shell's for the signal (128 + its number).
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A gimbal run of `t_final` seconds, written every 0.01 s.
fn scene(dir: &Path, t_final: f64) -> PathBuf {
    let path = dir.join(format!("gimbal_{t_final}.toml"));
    let text = format!(
        "model = \"gimbal_gyroscope\"\nt_final = {t_final:?}\noutput_step = 0.01\n[parameters]\nZ = 10.0\n[initial]\nU3 = \"100 rad/s\"\n"
    );
    std::fs::write(&path, text).unwrap();
    path
}

/// The bytes of the run's CSV being staged for `out` (in the staging folders beside it).
fn staged_bytes(out: &Path) -> u64 {
    let work = out.with_file_name(format!(".{}.gyro-sim", out.file_name().unwrap().to_string_lossy()));
    let Ok(entries) = std::fs::read_dir(work) else { return 0 };
    entries
        .flatten()
        .filter(|e| e.path().is_dir())
        .filter_map(|e| std::fs::metadata(e.path().join("trajectory.csv")).ok())
        .map(|m| m.len())
        .sum()
}

/// Starts a long run into `out`, waits until it has written rows, sends `signal`; its exit code
/// and standard error.
fn interrupt(scene: &Path, out: &Path, signal: &str) -> (Option<i32>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while staged_bytes(out) < 100_000 && start.elapsed() < Duration::from_secs(60) {
        assert!(child.try_wait().unwrap().is_none(), "the run ended before it was signalled");
        std::thread::sleep(Duration::from_millis(20));
    }
    let sent = Command::new("kill").args([&format!("-{signal}"), &child.id().to_string()]).status();
    assert!(sent.unwrap().success(), "kill -{signal}");
    let done = child.wait_with_output().unwrap();
    (done.status.code(), String::from_utf8_lossy(&done.stderr).into_owned())
}

#[test]
fn a_signal_keeps_the_rows_so_far_leaves_the_old_set_and_exits_with_the_shells_code() {
    let dir = folder("signals");
    let out = dir.join("out");
    // An earlier, finished set in the folder.
    let short = scene(&dir, 0.5);
    let earlier = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", short.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(earlier.status.success(), "{}", String::from_utf8_lossy(&earlier.stderr));
    let old_csv = std::fs::read(out.join("trajectory.csv")).unwrap();
    let long = scene(&dir, 5.0e4);
    for (signal, code) in [("INT", 130), ("TERM", 143), ("HUP", 129)] {
        let (exit, stderr) = interrupt(&long, &out, signal);
        assert_eq!(exit, Some(code), "SIG{signal}: {stderr}");
        assert!(stderr.contains(&format!("interrupted by SIG{signal}")), "{stderr}");
        assert!(stderr.contains("trajectory.partial.csv"), "{stderr}");
        let partial = std::fs::read_to_string(out.join("trajectory.partial.csv")).unwrap();
        let rows: Vec<&str> = partial.lines().collect();
        assert!(rows.len() > 100, "SIG{signal}: {} rows kept", rows.len());
        assert!(partial.ends_with('\n'), "the last row is whole");
        // Rows are consecutive output times from the start, every value finite.
        let times: Vec<f64> =
            rows[1..].iter().map(|r| r.split(',').next().unwrap().parse().unwrap()).collect();
        assert_eq!(times[0], 0.0);
        assert!(times.windows(2).all(|w| ((w[1] - w[0]) - 0.01).abs() < 1e-9));
        assert!(rows[1..].iter().flat_map(|r| r.split(',')).all(|v| v.parse::<f64>().unwrap().is_finite()));
        assert_eq!(
            std::fs::read(out.join("trajectory.csv")).unwrap(),
            old_csv,
            "the earlier set is unchanged"
        );
    }
}
