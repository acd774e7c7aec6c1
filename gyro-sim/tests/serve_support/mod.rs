//! What the `gyro-sim serve` tests share: in come a scene and requests; out go a running server
//! (stopped when dropped), HTTP answers over a plain socket, `gyro-sim run`'s CSV for a scene, and
//! a slider moved in the page as a user would.

#![allow(dead_code)]

pub mod cdp;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// The binary under test.
pub const BIN: &str = env!("CARGO_BIN_EXE_gyro-sim");

/// A `gyro-sim serve` process, killed when dropped.
pub struct Server {
    child: Child,
    /// `127.0.0.1:PORT`.
    pub address: String,
}

impl Server {
    /// The server's process id.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The path of a scene under gyro-sim/scenes.
pub fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// Starts `gyro-sim serve SCENE --port 0` and waits for the address it prints.
pub fn serve(scene: &Path) -> Server {
    let mut child = Command::new(BIN)
        .arg("serve")
        .arg(scene)
        .args(["--port", "0"])
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .expect("gyro-sim starts");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).unwrap();
    let address = line
        .strip_prefix("serving http://")
        .and_then(|rest| rest.split('/').next())
        .unwrap_or_else(|| panic!("gyro-sim serve printed {line:?}"))
        .to_string();
    Server { child, address }
}

/// A request's status and body (HTTP/1.1, the connection closed after it).
pub fn request(address: &str, method: &str, path: &str, body: &[u8]) -> (u16, Vec<u8>) {
    let head = format!(
        "{method} {path} HTTP/1.1\r\nHost: {address}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        body.len()
    );
    let mut raw = head.into_bytes();
    raw.extend_from_slice(body);
    send_raw(address, &raw)
}

/// Sends bytes as they are; the answer's status and body.
pub fn send_raw(address: &str, raw: &[u8]) -> (u16, Vec<u8>) {
    let mut stream = TcpStream::connect(address).unwrap();
    stream.set_read_timeout(Some(Duration::from_secs(300))).unwrap();
    let _ = stream.write_all(raw);
    let mut answer = Vec::new();
    let _ = stream.read_to_end(&mut answer);
    let split = answer.windows(4).position(|w| w == b"\r\n\r\n").expect("an HTTP answer");
    let head = String::from_utf8_lossy(&answer[..split]).to_string();
    assert!(!head.to_ascii_lowercase().contains("transfer-encoding: chunked"), "{head}");
    let status = head.split_whitespace().nth(1).and_then(|s| s.parse().ok()).expect("a status");
    (status, answer[split + 4..].to_vec())
}

/// A JSON request's status and its answer's JSON.
pub fn post_json(address: &str, path: &str, body: &str) -> (u16, serde_json::Value) {
    let (status, body) = request(address, "POST", path, body.as_bytes());
    (status, serde_json::from_slice(&body).unwrap_or(serde_json::Value::Null))
}

/// The folder `name` under the tests' temporary folder, emptied.
pub fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("serve").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The CSV `gyro-sim run` writes for the scene the server saves with `values` (its header and
/// rows), the scene written into `dir`.
pub fn run_saved(address: &str, values: &str, dir: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    run_saved_outcome(address, values, dir).unwrap_or_else(|stderr| panic!("{stderr}"))
}

/// What `gyro-sim run` gives for the scene the server saves with `values`: the CSV's header and
/// rows, or its error message when the run fails.
pub fn run_saved_outcome(
    address: &str,
    values: &str,
    dir: &Path,
) -> Result<(Vec<String>, Vec<Vec<f64>>), String> {
    let (status, text) = request(address, "POST", "/api/scene", values.as_bytes());
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&text));
    let scene = dir.join("saved.toml");
    std::fs::write(&scene, &text).unwrap();
    let out = dir.join("run");
    let run = Command::new(BIN).arg("run").arg(&scene).arg("--out").arg(&out).output().unwrap();
    if !run.status.success() {
        return Err(String::from_utf8_lossy(&run.stderr).into_owned());
    }
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines.map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    Ok((header, rows))
}

/// A column of a CSV by its header name.
pub fn csv_column(header: &[String], rows: &[Vec<f64>], name: &str) -> Vec<f64> {
    let i = header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no {name} in {header:?}"));
    rows.iter().map(|r| r[i]).collect()
}

/// Waits in the page until `condition` holds (60 s at most).
pub const UNTIL: &str = "const until = async (f) => { for (let i = 0; i < 1200; i++) { if (f()) return; \
    await new Promise((r) => setTimeout(r, 50)); } throw new Error('timed out waiting for ' + f); };";

/// Moves the slider of control `name` to `value` as a user would and waits for the server's
/// answer: whether the page redrew, the error it shows and the latency it measured, ms.
pub fn move_slider_once(browser: &mut cdp::Browser, name: &str, value: f64) -> serde_json::Value {
    browser.eval(&format!(
        "(async () => {{ {UNTIL}
           const slider = document.getElementById('control-{name}');
           const [n, answered] = [gyroState.redraws, gyroState.answers];
           slider.value = String({value});
           slider.dispatchEvent(new Event('input'));
           await until(() => gyroState.answers > answered);
           return {{ redrew: gyroState.redraws > n, error: gyroState.error,
                     latency: gyroState.latencies[gyroState.latencies.length - 1] ?? null }}; }})()"
    ))
}
