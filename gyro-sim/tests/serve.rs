//! `gyro-sim serve` over HTTP: in come Trial 3's scene and requests sent as a client would (good,
//! bad and malformed); out go checks that a run with a value is the trajectory `gyro-sim run`
//! writes for the scene saved with that value, and that bad requests get a 4xx and leave the
//! server answering.

mod serve_support;

use serve_support::*;

#[test]
fn a_run_with_a_value_is_what_gyro_sim_run_gives() {
    let server = serve(&scene_path("paper/trial3.toml"));
    let values = r#"{"values": {"U3": 150, "Y": -5.5}}"#;
    let (status, data) = post_json(&server.address, "/api/run", values);
    assert_eq!(status, 200, "{data}");
    assert_eq!(data["values"], serde_json::json!({ "U3": 150.0, "Y": -5.5, "Z": 10.0 }));
    assert_eq!(data["plot"], serde_json::json!(["Q1", "Q2", "Q3"]));
    let (header, rows) = run_saved(&server.address, values, &folder("trial3"));
    let t: Vec<f64> = data["t"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    assert_eq!(t.len(), rows.len());
    for (a, b) in t.iter().zip(&rows) {
        assert!((a - b[0]).abs() <= 1e-12 * a.abs().max(1.0), "t {a} against {}", b[0]);
    }
    for (name, column) in [("Q1", "q1_deg"), ("Q2", "q2_deg"), ("Q3", "q3_deg")] {
        let served = data["columns"][name].as_array().unwrap();
        let written = csv_column(&header, &rows, column);
        for (k, (s, w)) in served.iter().zip(&written).enumerate() {
            let s = s.as_f64().unwrap().to_degrees();
            assert!(
                (s - w).abs() <= 1e-9 * w.abs().max(1.0),
                "{name} row {k}: served {s} deg, run wrote {w}"
            );
        }
    }
    let (_, default) = post_json(&server.address, "/api/run", r#"{"values": {}}"#);
    assert_ne!(default["columns"]["Q2"], data["columns"]["Q2"], "the values change the motion");
}

#[test]
fn a_model_file_drawn_by_the_page_moves_its_points_with_a_slider() {
    let dir = folder("drawn_model");
    let model = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/double_pendulum.al");
    std::fs::copy(model, dir.join("double_pendulum.al")).unwrap();
    let scene = dir.join("scene.toml");
    let text = "model = \"double_pendulum.al\"\nt_final = 1.0\noutput_step = 0.1\noutputs = [\"Q1\", \"Q2\"]\n\n\
        [parameters]\nL = 1.0\n\n[[controls]]\nname = \"L\"\nmin = 0.5\nmax = 2.0\nstep = 0.1\n\n[view]\ndraw_model = true\n";
    std::fs::write(&scene, text).unwrap();
    let server = serve(&scene);
    let (status, data) = post_json(&server.address, "/api/run", r#"{"values": {"L": 2.0}}"#);
    assert_eq!(status, 200, "{data}");
    let points: Vec<&str> =
        data["view"]["points"].as_array().unwrap().iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert_eq!(points, ["AO", "BO", "O", "P"]);
    // P is at L A1> from the hinge: 2 cos q1 along N1 at the start (q1 = -1.2 rad).
    let x0 = data["columns"]["P_O_P_N1"][0].as_f64().unwrap();
    assert!((x0 - 2.0 * (-1.2f64).cos()).abs() < 1e-12, "P_O_P_N1 at t = 0: {x0}");
}

#[test]
fn bad_requests_get_a_4xx_and_the_server_goes_on() {
    let server = serve(&scene_path("paper/trial3.toml"));
    let a = server.address.as_str();
    let error = |body: &str| {
        let (status, json) = post_json(a, "/api/run", body);
        (status, json["error"].as_str().unwrap_or("").to_string())
    };
    assert_eq!(
        error(r#"{"values": {"U3": 500}}"#),
        (400, "U3 = 500 is outside its range, 0 to 200 rad/s".into())
    );
    assert_eq!(
        error(r#"{"values": {"U3": "NaN"}}"#),
        (400, "U3 must be a finite number, not \"NaN\"".into())
    );
    assert_eq!(
        error(r#"{"values": {"M": 1}}"#),
        (400, "`M` is not a control of this scene (its controls: U3, Y, Z)".into())
    );
    let (status, message) = error(r#"{"values": {"U3": NaN}}"#);
    assert!(status == 400 && message.starts_with("the request is not JSON"), "{status} {message}");
    let (status, message) = error(&format!("{{\"values\": {{\"U3\": 1{}}}}}", " ".repeat(100_000)));
    assert_eq!((status, message.as_str()), (413, "the request body is over 65536 bytes"));
    for path in ["/../../etc/passwd", "/%2e%2e/Cargo.toml", "/api/../Cargo.toml", "/favicon.ico"] {
        assert_eq!(request(a, "GET", path, b"").0, 404, "{path}");
    }
    assert_eq!(request(a, "GET", "/api/run", b"").0, 405);
    // Garbage on a socket, and a client that sends a head and goes away, do not stop the server.
    let _ = std::net::TcpStream::connect(a)
        .and_then(|mut s| std::io::Write::write_all(&mut s, b"\x00\xff garbage\r\n\r\n"));
    let _ = std::net::TcpStream::connect(a).and_then(|mut s| {
        std::io::Write::write_all(&mut s, b"POST /api/run HTTP/1.1\r\nContent-Length: 1000\r\n\r\n{\"va")
    });
    // 50 clients at once, each moving a slider twice: every request answered 200 (runs wait
    // their turn, one per core).
    let clients: Vec<_> = (0..50)
        .map(|k| {
            let a = a.to_string();
            std::thread::spawn(move || {
                (0..2)
                    .map(|i| {
                        post_json(&a, "/api/run", &format!("{{\"values\": {{\"Z\": {}}}}}", (k + i) % 20)).0
                    })
                    .collect::<Vec<_>>()
            })
        })
        .collect();
    for c in clients {
        assert_eq!(c.join().unwrap(), [200, 200]);
    }
    let (status, page) = request(a, "GET", "/", b"");
    assert!(status == 200 && String::from_utf8_lossy(&page).contains("gyroState"));
}

#[test]
fn clients_stalled_sending_their_bodies_hold_no_answer_slot() {
    let server = serve(&scene_path("paper/trial3.toml"));
    let a = server.address.as_str();
    // More stalled clients than answer slots (64), each holding its connection open; bodies over
    // 1 KiB, which the HTTP library hands over unread.
    let stalled: Vec<_> = (0..80)
        .filter_map(|_| {
            let mut s = std::net::TcpStream::connect(a).ok()?;
            let head = b"POST /api/run HTTP/1.1\r\nHost: x\r\nContent-Length: 5000\r\n\r\n{\"va";
            std::io::Write::write_all(&mut s, head).ok()?;
            Some(s)
        })
        .collect();
    assert_eq!(stalled.len(), 80);
    std::thread::sleep(std::time::Duration::from_millis(300));
    let (status, data) = post_json(a, "/api/run", r#"{"values": {"U3": 120}}"#);
    assert_eq!(status, 200, "a client behind 80 stalled ones is answered: {data}");
    drop(stalled);
    let (status, _) = post_json(a, "/api/run", r#"{"values": {"U3": 130}}"#);
    assert_eq!(status, 200);
}
