//! Output sets (issue 14): runs into one folder never mix. Each run stages its files under
//! names of its own (process id and counter) and puts them in place together under the
//! folder's lock, removing the files of an earlier set that it lacks.

use std::path::{Path, PathBuf};
use std::process::{Child, Command};

fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A gimbal scene whose rows depend on `spin`, with dense figure points.
fn scene(dir: &Path, spin: usize) -> PathBuf {
    let path = dir.join(format!("spin{spin}.toml"));
    let text = format!(
        "model = \"gimbal_gyroscope\"\nt_final = 2.0\noutput_step = 0.01\nplot_points = 20\n[parameters]\nZ = 10.0\n[initial]\nU3 = \"{spin} rad/s\"\n"
    );
    std::fs::write(&path, text).unwrap();
    path
}

fn start(scene: &Path, out: &Path) -> Child {
    Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap()
}

fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    names.sort();
    names
}

#[test]
fn concurrent_runs_into_one_folder_leave_one_whole_set() {
    let dir = folder("concurrent_sets");
    let spins = [5, 10, 20, 40];
    let scenes: Vec<PathBuf> = spins.iter().map(|s| scene(&dir, *s)).collect();
    // Each run alone, for reference.
    let solo: Vec<(Vec<u8>, Vec<u8>)> = scenes
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let out = dir.join(format!("solo{k}"));
            assert!(start(s, &out).wait().unwrap().success());
            (
                std::fs::read(out.join("trajectory.csv")).unwrap(),
                std::fs::read(out.join("trajectory.png")).unwrap(),
            )
        })
        .collect();
    let shared = dir.join("shared");
    for round in 0..3 {
        let children: Vec<Child> = scenes.iter().map(|s| start(s, &shared)).collect();
        for mut c in children {
            assert!(c.wait().unwrap().success(), "round {round}");
        }
        let csv = std::fs::read(shared.join("trajectory.csv")).unwrap();
        let png = std::fs::read(shared.join("trajectory.png")).unwrap();
        let k = solo.iter().position(|(c, _)| *c == csv).expect("the CSV is one run's, whole");
        assert!(solo[k].1 == png, "round {round}: the figure is from another run than the CSV");
        let left: Vec<String> = files(&shared).into_iter().filter(|n| n.starts_with(".partial")).collect();
        assert!(left.is_empty(), "temporaries left: {left:?}");
    }
}

#[test]
fn a_new_set_removes_the_files_of_the_old_one_it_lacks() {
    let dir = folder("replaced_sets");
    let out = dir.join("out");
    let loops = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/ejs/loops.toml");
    assert!(start(Path::new(loops), &out).wait().unwrap().success());
    assert!(files(&out).contains(&"view.html".to_string()), "{:?}", files(&out));
    assert!(start(&scene(&dir, 10), &out).wait().unwrap().success());
    assert_eq!(files(&out), [".gyro-sim.lock", "trajectory.csv", "trajectory.png"]);
}
