//! Sweeps through the `gyro-sim` command: a grid's rows in member order and reproducible byte for
//! byte; shards run as separate processes at once and merged equal the whole sweep; a re-run
//! skips the members already done (resume after a kill); a member that fails is a row with its
//! failure named; Latin-hypercube samples repeat from their seed.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const TRIAL1: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/paper/trial1.toml");

fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sweeps").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn gyro_sim(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gyro-sim"));
    c.args(args).env_remove("SLURM_ARRAY_TASK_ID").env_remove("SLURM_ARRAY_TASK_COUNT");
    c
}

fn ok(o: Output) -> String {
    let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{text}");
    text
}

fn sweep(out: &Path, extra: &[&str]) -> String {
    let mut args = vec!["sweep", TRIAL1, "--vary", "Y=0:20:3", "--vary", "U3=10:100:4 rad/s", "--out"];
    args.push(out.to_str().unwrap());
    args.extend(extra);
    ok(gyro_sim(&args).output().unwrap())
}

fn csv(dir: &Path) -> String {
    std::fs::read_to_string(dir.join("sweep.csv")).unwrap()
}

#[test]
fn a_grid_is_reproducible_and_in_member_order() {
    let (a, b) = (folder("grid_a"), folder("grid_b"));
    let said = sweep(&a, &[]);
    assert!(said.contains("12 members run (0 failed"), "{said}");
    sweep(&b, &[]);
    assert_eq!(csv(&a), csv(&b), "the same inputs give the same bytes");
    let text = csv(&a);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("member,Y,U3,status,steps,rhs_evals,final_q1_deg,"), "{}", lines[0]);
    assert_eq!(lines.len(), 13);
    for (i, l) in lines[1..].iter().enumerate() {
        assert!(l.starts_with(&format!("{i},")), "{l}");
    }
    // Member 7 is Y = 10 (second of three), U3 = 100 (fourth of four).
    assert!(lines[8].starts_with("7,10,100,ok,"), "{}", lines[8]);
    assert!(std::fs::read_to_string(a.join("timing.csv")).unwrap().starts_with("member,wall_ms\n0,"));
}

#[test]
fn shards_in_separate_processes_merge_into_the_whole() {
    let (whole, s1, s2, merged) = (folder("whole"), folder("shard1"), folder("shard2"), folder("merged"));
    sweep(&whole, &[]);
    let spawn = |dir: &Path, k: &str| {
        let mut args =
            vec!["sweep", TRIAL1, "--vary", "Y=0:20:3", "--vary", "U3=10:100:4 rad/s", "--shard", k, "--out"];
        args.push(dir.to_str().unwrap());
        gyro_sim(&args).spawn().unwrap()
    };
    let (c1, c2) = (spawn(&s1, "1/2"), spawn(&s2, "2/2"));
    for c in [c1, c2] {
        ok(c.wait_with_output().unwrap());
    }
    assert_eq!(csv(&s1).lines().count(), 7);
    let said = ok(gyro_sim(&[
        "sweep-merge",
        "--out",
        merged.to_str().unwrap(),
        s2.to_str().unwrap(),
        s1.to_str().unwrap(),
    ])
    .output()
    .unwrap());
    assert!(said.contains("merged 12 members from 2 shards"), "{said}");
    assert_eq!(csv(&merged), csv(&whole));
    // A shard merged twice is refused.
    let twice = gyro_sim(&[
        "sweep-merge",
        "--out",
        merged.to_str().unwrap(),
        s1.to_str().unwrap(),
        s1.to_str().unwrap(),
    ])
    .output()
    .unwrap();
    assert!(!twice.status.success() && String::from_utf8_lossy(&twice.stderr).contains("is in two shards"));
}

#[test]
fn a_rerun_resumes_where_a_killed_run_stopped() {
    let (whole, partial) = (folder("resume_whole"), folder("resume_partial"));
    sweep(&whole, &[]);
    let all = csv(&whole);
    let first_four: Vec<&str> = all.lines().take(5).collect();
    std::fs::write(partial.join("sweep.csv"), first_four.join("\n") + "\n").unwrap();
    let said = sweep(&partial, &[]);
    assert!(said.contains("8 members run (0 failed, named in their rows), 4 already done"), "{said}");
    assert_eq!(csv(&partial), csv(&whole));
}

#[test]
fn a_killed_sweep_keeps_its_finished_members_and_a_rerun_completes_it() {
    let (whole, killed) = (folder("kill_whole"), folder("kill_partial"));
    let big = |out: &Path| {
        let out = out.to_str().unwrap().to_string();
        let args = ["sweep", TRIAL1, "--vary", "Y=0:20:40", "--vary", "U3=10:100:10 rad/s", "--out", &out];
        args.map(String::from)
    };
    ok(gyro_sim(&big(&whole).iter().map(String::as_str).collect::<Vec<_>>()).output().unwrap());
    let mut child = gyro_sim(&big(&killed).iter().map(String::as_str).collect::<Vec<_>>())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let journal = killed.join("sweep.journal.csv");
    let lines = || std::fs::read_to_string(&journal).map(|t| t.lines().count()).unwrap_or(0);
    while lines() < 20 && child.try_wait().unwrap().is_none() {
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let kept = lines().saturating_sub(1);
    assert!((19..400).contains(&kept), "the kill came after {kept} of 400 members: make the sweep longer");
    assert!(!killed.join("sweep.csv").exists(), "sweep.csv is written only when the sweep ends");
    let args = big(&killed);
    let said = ok(gyro_sim(&args.iter().map(String::as_str).collect::<Vec<_>>()).output().unwrap());
    let finished = kept.saturating_sub(1)..=kept;
    let done = said.split(" already done").next().unwrap().rsplit(' ').next().unwrap();
    assert!(finished.contains(&done.parse::<usize>().unwrap()), "{said} (journal had {kept})");
    assert_eq!(csv(&killed), csv(&whole));
    assert!(!journal.exists(), "the journal is removed once sweep.csv holds its rows");
    let timing = std::fs::read_to_string(killed.join("timing.csv")).unwrap();
    assert_eq!(timing.lines().count(), 401);
}

#[test]
fn failing_members_are_rows_and_samples_repeat_from_their_seed() {
    let dir = folder("failing");
    let args = ["sweep", TRIAL1, "--vary", "NOT_A_NAME=0:1:2", "--out", dir.to_str().unwrap()];
    let said = ok(gyro_sim(&args).output().unwrap());
    assert!(said.contains("2 members run (2 failed"), "{said}");
    let text = csv(&dir);
    assert!(text.lines().nth(1).unwrap().contains("`NOT_A_NAME` is not a parameter"), "{text}");
    let (a, b, c) = (folder("lhs_a"), folder("lhs_b"), folder("lhs_c"));
    let lhs = |dir: &Path, seed: &str| {
        let args = [
            "sweep",
            TRIAL1,
            "--vary",
            "Y=0:20",
            "--samples",
            "5",
            "--seed",
            seed,
            "--out",
            dir.to_str().unwrap(),
        ];
        ok(gyro_sim(&args).output().unwrap());
        csv(dir)
    };
    assert_eq!(lhs(&a, "3"), lhs(&b, "3"));
    assert_ne!(lhs(&a, "3"), lhs(&c, "4"));
}

#[test]
fn a_metric_is_drawn_over_one_or_two_varied_values_and_unknown_names_are_named() {
    let dir = folder("plot");
    sweep(&dir, &[]);
    let d = dir.to_str().unwrap();
    let said = ok(gyro_sim(&["sweep-plot", d, "--metric", "max_ap_m_per_s2"]).output().unwrap());
    assert!(said.contains("12 members, 0 failed"), "{said}");
    let one = dir.join("over_y.png");
    ok(gyro_sim(&[
        "sweep-plot",
        d,
        "--metric",
        "final_q1_deg",
        "--over",
        "Y",
        "--out",
        one.to_str().unwrap(),
    ])
    .output()
    .unwrap());
    for png in [dir.join("max_ap_m_per_s2.png"), one] {
        let bytes = std::fs::read(&png).unwrap();
        assert!(bytes.starts_with(b"\x89PNG") && bytes.len() > 10_000, "{}", png.display());
    }
    let bad = gyro_sim(&["sweep-plot", d, "--metric", "max_q9"]).output().unwrap();
    let text = String::from_utf8_lossy(&bad.stderr);
    assert!(
        !bad.status.success() && text.contains("no column `max_q9`") && text.contains("max_q2_deg"),
        "{text}"
    );
    let bad = gyro_sim(&["sweep-plot", d, "--metric", "max_q1_deg", "--over", "Q7"]).output().unwrap();
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no column `Q7`; the columns are: Y, U3"));
}
