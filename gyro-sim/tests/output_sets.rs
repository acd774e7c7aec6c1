//! Output sets (issues 14 and 25): runs into one folder never mix. Each run stages its files in a
//! folder of its own beside the output folder (`.OUT.gyro-sim/`) and makes them the folder's set
//! in one atomic step, the earlier set's files it lacks gone, the folder's other files kept; a
//! live run's staging is never removed by another run.

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
        assert_eq!(files(&shared), ["trajectory.csv", "trajectory.png"], "round {round}");
        assert_eq!(files(&dir.join(".shared.gyro-sim")), ["commit.lock"], "round {round}: staging left");
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
    assert_eq!(files(&out), ["trajectory.csv", "trajectory.png"]);
}

#[test]
fn a_runs_other_files_stay_and_a_folder_inside_is_refused_by_name() {
    let dir = folder("foreign_files");
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    std::fs::write(out.join("notes.txt"), "mine").unwrap();
    assert!(start(&scene(&dir, 10), &out).wait().unwrap().success());
    assert_eq!(files(&out), ["notes.txt", "trajectory.csv", "trajectory.png"]);
    assert_eq!(std::fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
    let csv = std::fs::read(out.join("trajectory.csv")).unwrap();
    std::fs::create_dir(out.join("keep")).unwrap();
    let refused = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene(&dir, 20).to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success() && stderr.contains("keep") && stderr.contains("move them"), "{stderr}");
    assert_eq!(std::fs::read(out.join("trajectory.csv")).unwrap(), csv, "the earlier set is unchanged");
}

/// The bytes of the CSVs staged for `out`, and the staging folders.
fn staged(out: &Path) -> (u64, Vec<PathBuf>) {
    let work = out.with_file_name(format!(".{}.gyro-sim", out.file_name().unwrap().to_string_lossy()));
    let Ok(entries) = std::fs::read_dir(work) else { return (0, Vec::new()) };
    let folders: Vec<PathBuf> = entries.flatten().map(|e| e.path()).filter(|p| p.is_dir()).collect();
    let bytes =
        folders.iter().filter_map(|p| std::fs::metadata(p.join("trajectory.csv")).ok()).map(|m| m.len());
    (bytes.sum(), folders)
}

#[cfg(unix)]
#[test]
fn a_live_runs_staging_survives_another_runs_commit() {
    let dir = folder("live_staging");
    let out = dir.join("out");
    let long = dir.join("long.toml");
    let text = "model = \"gimbal_gyroscope\"\nt_final = 5.0e4\noutput_step = 0.01\n[parameters]\nZ = 10.0\n";
    std::fs::write(&long, text).unwrap();
    let mut live = start(&long, &out);
    let began = std::time::Instant::now();
    while staged(&out).0 < 100_000 && began.elapsed().as_secs() < 60 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let (before, folders) = staged(&out);
    assert!(before >= 100_000 && folders.len() == 1, "the long run did not start writing: {folders:?}");
    assert!(start(&scene(&dir, 10), &out).wait().unwrap().success());
    assert!(folders[0].exists(), "the live run's staging was removed by the other run's commit");
    std::thread::sleep(std::time::Duration::from_millis(200));
    assert!(staged(&out).0 > before, "the live run's CSV stopped growing");
    assert!(Command::new("kill").args(["-TERM", &live.id().to_string()]).status().unwrap().success());
    assert_eq!(live.wait().unwrap().code(), Some(143));
    let partial = std::fs::read_to_string(out.join("trajectory.partial.csv")).unwrap();
    assert!(partial.len() as u64 > before, "rows were lost: {} bytes kept of {before}", partial.len());
    assert!(partial.lines().nth(1).unwrap().starts_with("0,"), "the rows start at t = 0");
    assert_eq!(files(&out), ["trajectory.csv", "trajectory.partial.csv", "trajectory.png"]);
}
