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
