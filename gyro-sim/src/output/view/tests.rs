//! Unit tests of the view writer: in come small views and trajectories; out go checks of the
//! vendored three.js's hash, the embedded data, the errors and the page's text.

use std::time::Duration;

use super::*;
use crate::ode::Stats;
use crate::problem::Column;
use crate::scene::{Orientation, Shape};

/// The sha256 in `gyro-sim/assets/three/README.md`.
const THREE_SHA256: &str = "08fd7545d13d2c7fb65ab691530a802dafefd638596501854f267d0fb13c39e7";

/// SHA-256 (FIPS 180-4) of `bytes`, as lowercase hex.
fn sha256_hex(bytes: &[u8]) -> String {
    const K: [u32; 64] = [
        0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
        0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
        0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
        0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
        0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
        0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
        0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
        0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
    ];
    let mut h: [u32; 8] =
        [0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19];
    let mut message = bytes.to_vec();
    message.push(0x80);
    while message.len() % 64 != 56 {
        message.push(0);
    }
    message.extend_from_slice(&(bytes.len() as u64 * 8).to_be_bytes());
    for block in message.chunks(64) {
        let mut w = [0u32; 64];
        for (i, word) in block.chunks(4).enumerate() {
            w[i] = u32::from_be_bytes([word[0], word[1], word[2], word[3]]);
        }
        for i in 16..64 {
            let s0 = w[i - 15].rotate_right(7) ^ w[i - 15].rotate_right(18) ^ (w[i - 15] >> 3);
            let s1 = w[i - 2].rotate_right(17) ^ w[i - 2].rotate_right(19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16].wrapping_add(s0).wrapping_add(w[i - 7]).wrapping_add(s1);
        }
        let [mut a, mut b, mut c, mut d, mut e, mut f, mut g, mut hh] = h;
        for i in 0..64 {
            let s1 = e.rotate_right(6) ^ e.rotate_right(11) ^ e.rotate_right(25);
            let ch = (e & f) ^ (!e & g);
            let t1 = hh.wrapping_add(s1).wrapping_add(ch).wrapping_add(K[i]).wrapping_add(w[i]);
            let s0 = a.rotate_right(2) ^ a.rotate_right(13) ^ a.rotate_right(22);
            let maj = (a & b) ^ (a & c) ^ (b & c);
            let t2 = s0.wrapping_add(maj);
            (hh, g, f, e, d, c, b, a) = (g, f, e, d.wrapping_add(t1), c, b, a, t1.wrapping_add(t2));
        }
        for (x, y) in h.iter_mut().zip([a, b, c, d, e, f, g, hh]) {
            *x = x.wrapping_add(y);
        }
    }
    h.iter().map(|x| format!("{x:08x}")).collect()
}

#[test]
fn sha256_matches_known_digests() {
    assert_eq!(sha256_hex(b""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    assert_eq!(sha256_hex(b"abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    let long = b"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    assert_eq!(sha256_hex(long), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

/// The sha256s in `gyro-sim/assets/uplot/README.md`: the script and the style sheet.
const UPLOT_SHA256: [&str; 2] = [
    "19c8d4c6ad88929a79f4ae49d6f7161566dfd0ba3d15cc495e974f787eb78f1f",
    "df630c6a8d6f8eeaff264b50f73ce5b114f646ffd9a0bb74f049b0a00135fa04",
];

#[test]
fn vendored_uplot_is_the_pinned_file() {
    let files = [
        include_str!("../../../assets/uplot/uPlot.iife.min.js"),
        include_str!("../../../assets/uplot/uPlot.min.css"),
    ];
    let readme = include_str!("../../../assets/uplot/README.md");
    for (file, hash) in files.iter().zip(UPLOT_SHA256) {
        assert_eq!(sha256_hex(file.as_bytes()), hash, "a vendored uPlot file was changed");
        assert!(readme.contains(hash), "README names the pinned file");
    }
    assert!(files[0].starts_with("/*! https://github.com/leeoniya/uPlot (v1.6.32) */"));
}

#[test]
fn vendored_three_is_the_pinned_file() {
    assert_eq!(sha256_hex(THREE_JS.as_bytes()), THREE_SHA256, "three.module.min.js was changed");
    let readme = include_str!("../../../assets/three/README.md");
    assert!(readme.contains(THREE_SHA256) && readme.contains("0.170.0"), "README names the pinned file");
    assert!(THREE_JS.contains("const t=\"170\""), "three.js says it is r170");
}

#[test]
fn inlined_texts_cannot_end_their_script_elements() {
    for (name, text) in [("three.js", THREE_JS), ("page.js", PAGE_JS)] {
        let lower = text.to_ascii_lowercase();
        for bad in ["</script", "<!--", "<script"] {
            assert!(!lower.contains(bad), "{name} contains {bad}");
        }
    }
}

fn trajectory() -> Trajectory {
    let names = ["Q_E0", "Q_E1", "Q_E2", "Q_E3", "L_N1", "L_N2", "L_N3", "KE"];
    let columns = names
        .iter()
        .map(|n| Column { name: n.to_string(), unit: String::new(), output: true, hidden: false })
        .collect();
    let rows = (0..3)
        .map(|i| {
            let t = i as f64 * 0.5;
            vec![t, (t / 2.0).cos(), 0.0, 0.0, (t / 2.0).sin(), 0.0, 0.0, 2.0, 7.0]
        })
        .collect();
    Trajectory {
        title: "spin <test> & co".to_string(),
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
    toml::from_str(
        r##"
        [[bodies]]
        name = "rotor"
        shape = { kind = "cylinder", radius = 0.5, length = 0.1 }
        colour = "#ff00ff"
        orientation = { quaternion = ["Q_E0", "Q_E1", "Q_E2", "Q_E3"] }
        offset = [0.0, 0.0, 1.0]

        [[arrows]]
        label = "L"
        colour = "#ffff00"
        columns = ["L_N1", "L_N2", "L_N3"]
        scale = 0.5

        [[traces]]
        body = "rotor"
        point = [0.0, 0.0, 1.0]
        colour = "#303030"
        "##,
    )
    .expect("view parses")
}

#[test]
fn a_view_reads_from_toml_with_defaults() {
    let v = view();
    assert_eq!(v.bodies[0].shape, Shape::Cylinder { radius: 0.5.into(), length: 0.1.into() });
    assert_eq!(v.arrows[0].scale, 0.5);
    let fixed: ViewSpec = toml::from_str(
        "[[bodies]]\nname = \"b\"\nshape = { kind = \"rod\", length = 1.0 }\ncolour = \"#000000\"\n",
    )
    .unwrap();
    assert_eq!(fixed.bodies[0].orientation, Orientation::Fixed);
    assert_eq!(fixed.bodies[0].offset, [0.0.into(), 0.0.into(), 0.0.into()]);
    assert_eq!(fixed.bodies[0].opacity, 1.0);
    let dcm: Orientation =
        toml::from_str::<toml::Table>("o = { dcm = ['a','b','c','d','e','f','g','h','i'] }").unwrap()["o"]
            .clone()
            .try_into()
            .unwrap();
    assert_eq!(dcm.columns().len(), 9);
    assert!(toml::from_str::<ViewSpec>(
        "[[bodies]]\nname = 'b'\nshape = { kind = 'cone' }\ncolour = '#000000'"
    )
    .is_err());
}

#[test]
fn data_hold_t_and_only_the_columns_read() {
    let data = view_data(&trajectory(), &view(), &[]).unwrap();
    assert_eq!(data["t"], serde_json::json!([0.0, 0.5, 1.0]));
    let columns = data["columns"].as_object().unwrap();
    let mut names: Vec<&str> = columns.keys().map(|k| k.as_str()).collect();
    names.sort();
    assert_eq!(names, ["L_N1", "L_N2", "L_N3", "Q_E0", "Q_E1", "Q_E2", "Q_E3"]);
    assert_eq!(columns["L_N3"], serde_json::json!([2.0, 2.0, 2.0]));
    assert_eq!(data["view"]["bodies"][0]["orientation"]["quaternion"][3], "Q_E3");
}

#[test]
fn an_arrow_labelled_as_the_space_axes_is_tagged_with_its_vector() {
    let mut t = trajectory();
    for c in t.columns.iter_mut().filter(|c| c.name.starts_with("L_")) {
        c.unit = "KG*M^2/SEC".to_string();
    }
    let data = view_data(&t, &view(), &[]).unwrap();
    assert_eq!(data["view"]["arrows"][0]["tag"], "L", "a label apart from N1, N2, N3 stays");
    let mut v = view();
    v.arrows[0].label = "N".to_string();
    let data = view_data(&t, &v, &[]).unwrap();
    assert_eq!(data["view"]["arrows"][0]["tag"], "l (kg·m²/s)");
    assert_eq!(data["view"]["arrows"][0]["label"], "N", "the label still names it in the URL");
}

#[test]
fn a_missing_column_is_named_with_the_known_ones() {
    let mut v = view();
    v.arrows[0].columns[1] = "H_N2".to_string();
    let e = view_data(&trajectory(), &v, &[]).unwrap_err();
    let text = e.to_string();
    assert!(text.contains("arrow L") && text.contains("`H_N2`"), "{text}");
    assert!(text.contains("Q_E0, Q_E1, Q_E2, Q_E3, L_N1, L_N2, L_N3, KE"), "{text}");
    let dir = std::env::temp_dir().join(format!("gyro-view-unit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("view.html");
    let err = write_view(&trajectory(), &v, &path).unwrap_err();
    assert!(err.to_string().contains("H_N2") && !path.exists(), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_colours_sizes_and_bodies_are_refused() {
    let mut v = view();
    v.bodies[0].colour = "magenta".to_string();
    assert!(matches!(v.check(), Err(ViewError::Colour { .. })));
    let mut v = view();
    v.bodies[0].shape = Shape::Box { x: 1.0.into(), y: 0.0.into(), z: 1.0.into() };
    assert!(matches!(v.check(), Err(ViewError::Number { .. })));
    let mut v = view();
    v.bodies[0].opacity = 1.5;
    assert!(v.check().unwrap_err().to_string().contains("opacity 1.5"));
    let mut v = view();
    v.traces[0].body = "axle".to_string();
    assert!(v.check().unwrap_err().to_string().contains("it has: rotor"));
    let mut t = trajectory();
    t.rows.clear();
    assert_eq!(view_data(&t, &view(), &[]).unwrap_err(), ViewError::Empty);
}

#[test]
fn the_page_is_filled_and_escaped() {
    let mut v = view();
    v.bodies[0].name = "</script><b>".to_string();
    v.traces[0].body = v.bodies[0].name.clone();
    let html = view_html(&trajectory(), &v).unwrap();
    assert!(!html.contains("{{"), "every marker filled");
    assert_eq!(html.matches("</script>").count(), 3, "only the page's own script ends");
    assert!(html.contains("<title>spin &lt;test&gt; &amp; co</title>"));
    assert!(html.contains(THREE_JS) && html.contains(PAGE_JS));
    assert!(html.contains("\\u003c/script>\\u003cb>"));
}

#[test]
fn fill_leaves_unknown_markers_and_does_not_search_values() {
    let out = fill("a{{X}}b{{Y}}c{{", &[("X", "{{Y}}"), ("Y", "y")]);
    assert_eq!(out, "a{{Y}}byc{{");
}
