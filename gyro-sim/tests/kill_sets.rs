//! Output sets under kills: runs killed with SIGKILL at random instants, the commit's
//! among them, one writer at a time or two into one folder, leave the folder holding one whole
//! set (every file of the earlier set or of a new one, byte for byte, and no other set file) and
//! every file that is not a set's. `KILL_TRIALS` sets the number of trials (default 100),
//! `KILL_SEED` the seed of the instants; the counts of each outcome are printed.
#![cfg(unix)]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Files that are not a run's, kept in the output folder.
const FOREIGN: [(&str, &str); 2] = [("notes.txt", "my notes\n"), ("sweep.csv", "member,q1\n0,1.5\n")];

/// The files of one whole set, by name.
type Set = BTreeMap<String, Vec<u8>>;

fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A short gimbal run whose files depend on `spin`; with `events`, an events.csv too.
fn scene(dir: &Path, spin: u32, events: bool) -> PathBuf {
    let path = dir.join(format!("spin{spin}.toml"));
    let mut text = format!(
        "model = \"gimbal_gyroscope\"\nt_final = 2.0\noutput_step = 0.01\nplot_points = 10\n[parameters]\nZ = 10.0\n[initial]\nU3 = \"{spin} rad/s\"\n"
    );
    if events {
        text.push_str("[[events]]\nname = \"quarter\"\nwhen = \"t - 0.1\"\n");
    }
    std::fs::write(&path, text).unwrap();
    path
}

fn start(scene: &Path, out: &Path) -> Child {
    Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

/// The set files in `dir` (every entry but the foreign files).
fn set_in(dir: &Path) -> Set {
    let foreign: Vec<&str> = FOREIGN.iter().map(|(name, _)| *name).collect();
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| !foreign.contains(&name.as_str()))
        .map(|name| (name.clone(), std::fs::read(dir.join(name)).unwrap()))
        .collect()
}

/// Each scene run alone into a folder of its own: its whole set, and the median wall time.
fn references(dir: &Path, scenes: &[PathBuf]) -> (Vec<Set>, Duration) {
    let mut times = Vec::new();
    let mut sets = Vec::new();
    for (k, scene) in scenes.iter().enumerate() {
        let out = dir.join(format!("reference{k}"));
        for _ in 0..3 {
            let began = Instant::now();
            assert!(start(scene, &out).wait().unwrap().success());
            times.push(began.elapsed());
        }
        sets.push(set_in(&out));
    }
    times.sort();
    (sets, times[times.len() / 2])
}

/// Which reference set `out` holds, whole; panics on a mixture, a missing or stray file, or a
/// foreign file changed or lost.
fn whole_set(out: &Path, references: &[Set], trial: usize) -> usize {
    for (name, text) in FOREIGN {
        let kept = std::fs::read_to_string(out.join(name));
        assert_eq!(kept.ok().as_deref(), Some(text), "trial {trial}: {name} was lost or changed");
    }
    let found = set_in(out);
    if let Some(k) = references.iter().position(|r| *r == found) {
        return k;
    }
    let origin: Vec<String> = found
        .iter()
        .map(|(name, bytes)| {
            let from: Vec<usize> =
                (0..references.len()).filter(|k| references[*k].get(name) == Some(bytes)).collect();
            format!("{name} from scenes {from:?}")
        })
        .collect();
    panic!("trial {trial}: the folder holds no whole set: {origin:?}");
}

/// Kill instants: half over the whole run, half near the commit, whose instant is tracked from
/// the outcomes (later after a kill that left the earlier set, earlier after one that did not).
struct Instants {
    rng: StdRng,
    commit: Duration,
}

impl Instants {
    /// The next instant; whether it was drawn near the commit.
    fn next(&mut self) -> (Duration, bool) {
        let near = self.rng.random_bool(0.5);
        let fraction = if near { self.rng.random_range(0.9..1.1) } else { self.rng.random_range(0.0..1.3) };
        (self.commit.mul_f64(fraction), near)
    }

    /// Learns from a kill near the commit whether the commit had happened.
    fn learn(&mut self, committed: bool) {
        self.commit = self.commit.mul_f64(if committed { 0.97 } else { 1.03 });
    }
}

/// Starts `scenes` into `out`, each killed at its own instant (or finished before it); whether
/// each had finished.
fn run_and_kill(scenes: &[&Path], out: &Path, instants: &[Duration]) -> Vec<bool> {
    let began = Instant::now();
    let mut children: Vec<(Child, Duration)> =
        scenes.iter().zip(instants).map(|(s, at)| (start(s, out), *at)).collect();
    let mut order: Vec<usize> = (0..children.len()).collect();
    order.sort_by_key(|k| children[*k].1);
    let mut finished = vec![false; children.len()];
    for k in order {
        let (child, at) = &mut children[k];
        std::thread::sleep(at.saturating_sub(began.elapsed()));
        finished[k] = child.try_wait().unwrap().is_some();
        let _ = child.kill();
        child.wait().unwrap();
    }
    finished
}

#[test]
fn runs_killed_at_any_instant_leave_one_whole_set_and_the_other_files() {
    let trials: usize = std::env::var("KILL_TRIALS").ok().and_then(|n| n.parse().ok()).unwrap_or(100);
    let seed: u64 = std::env::var("KILL_SEED").ok().and_then(|n| n.parse().ok()).unwrap_or(25);
    let dir = folder("kill_sets");
    let scenes = [scene(&dir, 50, true), scene(&dir, 80, false), scene(&dir, 120, false)];
    let (references, run) = references(&dir, &scenes);
    assert!(references[0].contains_key("events.csv") && !references[1].contains_key("events.csv"));
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    for (name, text) in FOREIGN {
        std::fs::write(out.join(name), text).unwrap();
    }
    assert!(start(&scenes[0], &out).wait().unwrap().success());
    let mut current = whole_set(&out, &references, 0);
    let mut instants = Instants { rng: StdRng::seed_from_u64(seed), commit: run };
    // [single writer: old, new killed after its commit, new finished; two: old, first, second]
    let (mut single, mut two) = ([0usize; 3], [0usize; 3]);
    let began = Instant::now();
    for trial in 0..trials {
        let others = [(current + 1) % 3, (current + 2) % 3];
        if trial % 4 == 3 {
            // Two runs share the cores: each takes longer.
            let at = [instants.next().0.mul_f64(1.6), instants.next().0.mul_f64(1.6)];
            run_and_kill(&[&scenes[others[0]], &scenes[others[1]]], &out, &at);
            let now = whole_set(&out, &references, trial);
            two[[current, others[0], others[1]].iter().position(|k| *k == now).unwrap()] += 1;
            current = now;
        } else {
            let (at, near) = instants.next();
            let finished = run_and_kill(&[&scenes[others[0]]], &out, &[at])[0];
            let now = whole_set(&out, &references, trial);
            assert!(now == current || now == others[0], "trial {trial}: a set no run of it wrote");
            if near {
                instants.learn(now != current);
            }
            single[if now == current {
                0
            } else if finished {
                2
            } else {
                1
            }] += 1;
            current = now;
        }
    }
    println!(
        "kill trials: {trials} (seed {seed}, run {:.0} ms, commit at about {:.0} ms, {:.1} s in all); one writer: {} old set kept, {} new set (killed after its commit {}, finished {}); two writers: {} old set kept, {} first's set, {} second's set; no mixture, no foreign file lost",
        run.as_secs_f64() * 1e3,
        instants.commit.as_secs_f64() * 1e3,
        began.elapsed().as_secs_f64(),
        single[0],
        single[1] + single[2],
        single[1],
        single[2],
        two[0],
        two[1],
        two[2]
    );
    if trials >= 20 {
        assert!(single[0] > 0 && single[1] + single[2] > 0, "the instants missed one outcome: {single:?}");
    }
    // The next whole run settles what the killed ones left beside the folder.
    assert!(start(&scenes[0], &out).wait().unwrap().success());
    let work: Vec<String> = std::fs::read_dir(dir.join(".out.gyro-sim"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(work, ["commit.lock"], "left in the work folder");
}
