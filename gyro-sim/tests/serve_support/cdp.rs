//! A headless Chromium driven over the DevTools protocol: in comes a URL; out go the values of
//! scripts evaluated in its page. The protocol's WebSocket is spoken over a plain socket (text
//! frames, masked as a client must), enough for one request at a time.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// A browser showing one page, killed when dropped.
pub struct Browser {
    child: Child,
    socket: TcpStream,
    next_id: u64,
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Browser {
    /// Headless Chromium (Debian's `chromium`) on `url`, its profile in `profile`.
    pub fn open(url: &str, profile: &Path) -> Browser {
        let mut child = Command::new("chromium")
            .args(["--headless", "--disable-gpu", "--no-sandbox", "--no-first-run", "--hide-scrollbars"])
            .args(["--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--window-size=1200,800"])
            .args(["--remote-debugging-port=0", "--remote-allow-origins=*"])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg(url)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("chromium starts (apt-get install chromium; tests/run installs it)");
        // Its DevTools port, from its error output (read to the end, so that it never blocks).
        let stderr = BufReader::new(child.stderr.take().unwrap());
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in stderr.lines().map_while(Result::ok) {
                if let Some(rest) = line.strip_prefix("DevTools listening on ws://127.0.0.1:") {
                    let _ = tx.send(rest.split('/').next().unwrap_or("").to_string());
                }
            }
        });
        let port = rx.recv_timeout(Duration::from_secs(120)).ok();
        let port = port.expect("chromium prints its DevTools address");
        let page = page_socket(&port, url);
        let socket = handshake(&format!("127.0.0.1:{port}"), &page);
        Browser { child, socket, next_id: 1 }
    }

    /// The value of `expression` in the page (a promise is awaited), as JSON.
    pub fn eval(&mut self, expression: &str) -> serde_json::Value {
        self.try_eval(expression).unwrap_or_else(|e| panic!("the page's script failed: {e}"))
    }

    /// Waits until `condition` is true in the page, the page loaded (120 s at most).
    pub fn wait_for(&mut self, condition: &str) {
        for _ in 0..1200 {
            if self.try_eval(condition) == Ok(serde_json::Value::Bool(true)) {
                return;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        panic!("the page never had {condition}");
    }

    /// The value of `expression`, or the exception or protocol error it met.
    pub fn try_eval(&mut self, expression: &str) -> Result<serde_json::Value, String> {
        let id = self.next_id;
        self.next_id += 1;
        let message = serde_json::json!({
            "id": id,
            "method": "Runtime.evaluate",
            "params": { "expression": expression, "awaitPromise": true, "returnByValue": true },
        });
        send_text(&mut self.socket, &message.to_string());
        loop {
            let answer: serde_json::Value = serde_json::from_str(&read_text(&mut self.socket)).unwrap();
            if answer["id"] != id {
                continue;
            }
            if let Some(e) = answer.get("error") {
                return Err(e.to_string());
            }
            let result = &answer["result"];
            if let Some(e) = result.get("exceptionDetails") {
                return Err(e.to_string());
            }
            return Ok(result["result"]["value"].clone());
        }
    }
}

/// The WebSocket path of the page showing `url`, once the browser lists it.
fn page_socket(port: &str, url: &str) -> String {
    for _ in 0..200 {
        let mut s = TcpStream::connect(format!("127.0.0.1:{port}")).unwrap();
        write!(s, "GET /json/list HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n").unwrap();
        // The browser keeps the connection open: the body is read to its Content-Length.
        let head = read_head(&mut s);
        let length = head
            .lines()
            .find_map(|l| {
                l.to_ascii_lowercase().strip_prefix("content-length:").map(|n| n.trim().parse().unwrap_or(0))
            })
            .unwrap_or(0);
        let mut body = vec![0u8; length];
        s.read_exact(&mut body).unwrap();
        let list: serde_json::Value = serde_json::from_slice(&body).unwrap_or_default();
        let found = list.as_array().into_iter().flatten().find(|t| t["type"] == "page" && t["url"] == url);
        if let Some(ws) = found.and_then(|t| t["webSocketDebuggerUrl"].as_str()) {
            return ws
                .split_once("127.0.0.1:")
                .and_then(|(_, r)| r.split_once('/'))
                .map(|(_, p)| format!("/{p}"))
                .unwrap();
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    panic!("chromium did not list a page for {url}");
}

/// Opens the WebSocket at `path`.
fn handshake(address: &str, path: &str) -> TcpStream {
    let mut s = TcpStream::connect(address).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(600))).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {address}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
         Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
    )
    .unwrap();
    let head = read_head(&mut s);
    assert!(head.starts_with("HTTP/1.1 101"), "no WebSocket: {head}");
    s
}

/// An HTTP answer's head, read byte by byte up to the blank line.
fn read_head(s: &mut TcpStream) -> String {
    let mut head = Vec::new();
    let mut byte = [0u8];
    while !head.ends_with(b"\r\n\r\n") {
        s.read_exact(&mut byte).unwrap();
        head.push(byte[0]);
    }
    String::from_utf8_lossy(&head).into_owned()
}

/// Sends one masked text frame.
fn send_text(s: &mut TcpStream, text: &str) {
    let payload = text.as_bytes();
    let mut frame = vec![0x81u8];
    match payload.len() {
        n if n < 126 => frame.push(0x80 | n as u8),
        n if n < 65536 => {
            frame.push(0x80 | 126);
            frame.extend_from_slice(&(n as u16).to_be_bytes());
        }
        n => {
            frame.push(0x80 | 127);
            frame.extend_from_slice(&(n as u64).to_be_bytes());
        }
    }
    let mask = [0x12u8, 0x34, 0x56, 0x78];
    frame.extend_from_slice(&mask);
    frame.extend(payload.iter().enumerate().map(|(i, b)| b ^ mask[i % 4]));
    s.write_all(&frame).unwrap();
}

/// Reads one text message (its frames joined; control frames skipped).
fn read_text(s: &mut TcpStream) -> String {
    let mut message = Vec::new();
    loop {
        let mut head = [0u8; 2];
        s.read_exact(&mut head).unwrap();
        let (fin, opcode) = (head[0] & 0x80 != 0, head[0] & 0x0f);
        let mut len = (head[1] & 0x7f) as u64;
        if len == 126 {
            let mut b = [0u8; 2];
            s.read_exact(&mut b).unwrap();
            len = u16::from_be_bytes(b) as u64;
        } else if len == 127 {
            let mut b = [0u8; 8];
            s.read_exact(&mut b).unwrap();
            len = u64::from_be_bytes(b);
        }
        let mut payload = vec![0u8; len as usize];
        s.read_exact(&mut payload).unwrap();
        if opcode == 0x8 {
            panic!("the browser closed the DevTools socket");
        }
        if opcode == 0x1 || opcode == 0x0 {
            message.extend_from_slice(&payload);
            if fin {
                return String::from_utf8(message).unwrap();
            }
        }
    }
}
