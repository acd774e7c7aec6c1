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
    c.args(args);
    for v in ["ID", "COUNT", "MIN", "MAX", "STEP"] {
        c.env_remove(format!("SLURM_ARRAY_TASK_{v}"));
    }
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
    let said = String::from_utf8_lossy(&twice.stderr);
    assert!(!twice.status.success() && said.contains("are both shard 1/2: give each shard once"), "{said}");
}

#[test]
fn a_rerun_resumes_where_a_killed_run_stopped() {
    let (whole, partial) = (folder("resume_whole"), folder("resume_partial"));
    sweep(&whole, &[]);
    let all = csv(&whole);
    let first_four: Vec<&str> = all.lines().take(5).collect();
    std::fs::write(partial.join("sweep.csv"), first_four.join("\n") + "\n").unwrap();
    // Rows of an unknown sweep are refused; with the plan they came from, they are resumed.
    let unknown = gyro_sim(&["sweep", TRIAL1, "--vary", "Y=0:20:3", "--vary", "U3=10:100:4 rad/s", "--out"])
        .arg(&partial)
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&unknown.stderr);
    assert!(unknown.status.code() == Some(1) && said.contains("without sweep.plan.toml"), "{said}");
    std::fs::copy(whole.join("sweep.plan.toml"), partial.join("sweep.plan.toml")).unwrap();
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
    while lines() < 21 && child.try_wait().unwrap().is_none() {
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    // The journal's first two lines are the plan's fingerprint and the header.
    let kept = lines().saturating_sub(2);
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

/// A fast scene of the built-in gimbal, `t_final` seconds, written to `dir/name`.
fn gimbal(dir: &Path, name: &str, t_final: f64) -> PathBuf {
    let path = dir.join(name);
    let text = format!(
        "model = \"gimbal_gyroscope\"\nt_final = {t_final:?}\noutput_step = 0.05\n[parameters]\nZ = 10.0\n[initial]\nU3 = \"100 rad/s\"\n"
    );
    std::fs::write(&path, text).unwrap();
    path
}

/// `gyro-sim sweep SCENE --out OUT ARGS...`.
fn sweep_of(scene: &Path, out: &Path, args: &[&str]) -> Command {
    let mut c = gyro_sim(&["sweep", scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    c.args(args);
    c
}

/// The standard error of a command refused with exit code 1 (not a panic's 101).
fn refused(o: Output) -> String {
    let text = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(1), "{}{text}", String::from_utf8_lossy(&o.stdout));
    text
}

#[test]
fn a_rerun_of_another_plan_is_refused_naming_the_difference_and_new_starts_over() {
    let dir = folder("plans");
    let (scene, other) = (gimbal(&dir, "gimbal.toml", 0.2), gimbal(&dir, "other.toml", 0.3));
    let out = dir.join("out");
    let run = |scene: &Path, args: &[&str]| sweep_of(scene, &out, args).output().unwrap();
    ok(run(&scene, &["--vary", "Y=5:50:8"]));
    let before = csv(&out);
    let cases: [(&[&str], &str); 3] = [
        (&["--vary", "Y=500:5000:8"], "the folder's sweep varied Y=5:50:8; this one Y=500:5000:8"),
        (
            &["--vary", "Y=5:50:8", "--samples", "8"],
            "was a grid; this one a Latin-hypercube sample of 8 from seed 1",
        ),
        (&["--vary", "Y=5:50:8", "--shard", "1/2"], "was shard 1/1; this one 1/2"),
    ];
    for (args, says) in cases {
        let e = refused(run(&scene, args));
        assert!(
            e.contains(says) && e.contains("give another --out, or --new to start over"),
            "{args:?}: {e}"
        );
    }
    let e = refused(run(&other, &["--vary", "Y=5:50:8"]));
    assert!(e.contains("ran the scene") && e.contains("this one") && e.contains("other.toml"), "{e}");
    assert_eq!(csv(&out), before, "a refused sweep leaves the folder's rows");
    let said = ok(run(&scene, &["--vary", "Y=5:50:8"]));
    assert!(said.contains("0 members run (0 failed, named in their rows), 8 already done"), "{said}");
    let said = ok(run(&scene, &["--vary", "Y=500:5000:8", "--new"]));
    assert!(said.contains("8 members run (0 failed, named in their rows), 0 already done"), "{said}");
    let fresh = dir.join("fresh");
    ok(sweep_of(&scene, &fresh, &["--vary", "Y=500:5000:8"]).output().unwrap());
    assert_eq!(csv(&out), csv(&fresh), "--new starts over: the folder holds the new sweep alone");
    assert_ne!(csv(&out), before);
}

#[test]
fn a_merge_refuses_a_missing_shard_a_lost_member_and_another_plans_shard() {
    let dir = folder("merge_refusals");
    let scene = gimbal(&dir, "gimbal.toml", 0.2);
    let shard = |name: &str, vary: &str, k: &str| {
        let out = dir.join(name);
        ok(sweep_of(&scene, &out, &["--vary", vary, "--shard", k]).output().unwrap());
        out
    };
    let (s1, s2, s3) =
        (shard("s1", "Y=5:50:8", "1/3"), shard("s2", "Y=5:50:8", "2/3"), shard("s3", "Y=5:50:8", "3/3"));
    let elsewhere = shard("s3_other", "Y=5:60:8", "3/3");
    let merged = dir.join("merged");
    let merge = |shards: &[&Path]| {
        let mut c = gyro_sim(&["sweep-merge", "--out", merged.to_str().unwrap()]);
        c.args(shards);
        c.output().unwrap()
    };
    let e = refused(merge(&[&s1, &s2]));
    assert!(e.contains("shard 3/3 (members 2, 5) of the sweep is missing (2 of 3 shards given)"), "{e}");
    let e = refused(merge(&[&s1, &s2, &elsewhere]));
    assert!(
        e.contains("is another sweep's shard") && e.contains("varied Y=5:50:8; this one Y=5:60:8"),
        "{e}"
    );
    // Shard 2/3 holds members 1, 4 and 7: lose member 4.
    let text = csv(&s2);
    let kept: String = text.lines().filter(|l| !l.starts_with("4,")).map(|l| format!("{l}\n")).collect();
    std::fs::write(s2.join("sweep.csv"), kept).unwrap();
    let e = refused(merge(&[&s1, &s2, &s3]));
    assert!(e.contains("refusing to merge: 1 of 8 members are missing: 4 "), "{e}");
    assert!(!merged.join("sweep.csv").exists(), "nothing is written when a merge is refused");
}

#[test]
fn a_stepped_slurm_array_merges_into_the_whole_sweep_and_a_sparse_one_asks_for_shard() {
    let dir = folder("slurm_stepped");
    let scene = gimbal(&dir, "gimbal.toml", 0.2);
    let vary = ["--vary", "Y=5:50:9", "--vary", "U3=50:150:2 rad/s"];
    let whole = dir.join("whole");
    ok(sweep_of(&scene, &whole, &vary).output().unwrap());
    // --array=0-6:2: ids 0, 2, 4, 6, each its own process.
    let task = |id: usize, min: usize, max: usize, step: usize, count: usize| {
        let mut c = sweep_of(&scene, &dir.join(format!("shard-{id}")), &vary);
        for (name, v) in [("ID", id), ("MIN", min), ("MAX", max), ("STEP", step), ("COUNT", count)] {
            c.env(format!("SLURM_ARRAY_TASK_{name}"), v.to_string());
        }
        c
    };
    let children: Vec<_> = [0, 2, 4, 6].map(|id| task(id, 0, 6, 2, 4).spawn().unwrap()).into();
    for c in children {
        ok(c.wait_with_output().unwrap());
    }
    let merged = dir.join("merged");
    let mut merge = gyro_sim(&["sweep-merge", "--out", merged.to_str().unwrap()]);
    merge.args([0, 2, 4, 6].map(|id| dir.join(format!("shard-{id}"))));
    let said = ok(merge.output().unwrap());
    assert!(said.contains("merged 18 members from 4 shards"), "{said}");
    assert_eq!(csv(&merged), csv(&whole), "the stepped array's shards are the whole sweep");
    // --array=1,3,8: the ids are not evenly spaced, whatever step Slurm reports.
    let e = refused(task(3, 1, 8, 1, 3).output().unwrap());
    assert!(e.contains("not evenly spaced") && e.contains("--shard $((SLURM_ARRAY_TASK_ID+1))/9"), "{e}");
}

#[test]
fn a_sweep_into_a_folder_where_another_runs_is_refused_at_once() {
    let dir = folder("locked");
    let scene = gimbal(&dir, "gimbal.toml", 0.2);
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let held = std::fs::File::create(out.join("sweep.lock")).unwrap();
    held.try_lock().unwrap();
    let e = refused(sweep_of(&scene, &out, &["--vary", "Y=5:50:4"]).output().unwrap());
    assert!(e.contains(&format!("another sweep is running in {}", out.display())), "{e}");
    assert!(!out.join("sweep.plan.toml").exists(), "the refused sweep wrote nothing");
    drop(held);
    ok(sweep_of(&scene, &out, &["--vary", "Y=5:50:4"]).output().unwrap());
}

#[test]
fn sweeps_past_the_size_limit_are_refused_naming_it_without_a_panic() {
    let dir = folder("sizes");
    let scene = gimbal(&dir, "gimbal.toml", 0.2);
    let out = dir.join("out");
    let huge: Vec<String> = (0..6).flat_map(|i| ["--vary".to_string(), format!("A{i}=0:1:2048")]).collect();
    let huge: Vec<&str> = huge.iter().map(String::as_str).collect();
    let e = refused(sweep_of(&scene, &out, &huge).output().unwrap());
    assert!(
        e.contains(
            "2048 x 2048 x 2048 x 2048 x 2048 x 2048 = 73786976294838206464 members, more than the 10000000"
        ),
        "{e}"
    );
    for n in ["18446744073709551615", "0"] {
        let e = refused(sweep_of(&scene, &out, &["--vary", "Y=0:1", "--samples", n]).output().unwrap());
        assert!(e.contains(&format!("--samples {n}: give 1 to 10000000 samples")), "{e}");
    }
}

/// Lines in the journal of the sweep in `out` (0 when there is none).
fn journal_lines(out: &Path) -> usize {
    std::fs::read_to_string(out.join("sweep.journal.csv")).map_or(0, |t| t.lines().count())
}

#[cfg(unix)]
#[test]
fn sigint_stops_a_sweep_keeping_its_journal_and_the_same_command_resumes_it() {
    let dir = folder("sigint");
    let scene = gimbal(&dir, "gimbal.toml", 100.0);
    let vary = ["--vary", "Y=5:50:40", "--vary", "Z=0:10:2"];
    let (whole, part) = (dir.join("whole"), dir.join("part"));
    ok(sweep_of(&scene, &whole, &vary).output().unwrap());
    let child = sweep_of(&scene, &part, &vary)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while journal_lines(&part) < 2 + 4 && start.elapsed().as_secs() < 60 {
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    assert!(Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap().success());
    let done = child.wait_with_output().unwrap();
    let said = String::from_utf8_lossy(&done.stderr);
    assert_eq!(done.status.code(), Some(130), "the sweep ended before the signal? make it longer: {said}");
    let journal = part.join("sweep.journal.csv");
    let kept = journal_lines(&part).saturating_sub(2);
    let expected = format!(
        "interrupted by SIGINT: {kept} members done are kept in {}; run the same command again to resume",
        journal.display()
    );
    assert!(said.contains(&expected), "{said}");
    assert!((4..80).contains(&kept), "{kept} of 80 members were kept");
    assert!(
        !std::fs::read_to_string(&journal).unwrap().contains("interrupted by"),
        "a member cut short is not a row"
    );
    assert!(!part.join("sweep.csv").exists());
    let said = ok(sweep_of(&scene, &part, &vary).output().unwrap());
    assert!(
        said.contains(&format!(
            "{} members run (0 failed, named in their rows), {kept} already done",
            80 - kept
        )),
        "{said}"
    );
    assert_eq!(csv(&part), csv(&whole));
    assert!(!journal.exists());
}

#[test]
fn twenty_kills_at_random_instants_each_resumed_end_equal_to_an_uninterrupted_sweep() {
    let dir = folder("kills");
    let scene = gimbal(&dir, "gimbal.toml", 1.0);
    let vary = ["--vary", "Y=5:50:30", "--vary", "U3=50:150:5 rad/s"];
    let (whole, part) = (dir.join("whole"), dir.join("part"));
    let start = std::time::Instant::now();
    ok(sweep_of(&scene, &whole, &vary).output().unwrap());
    let full = start.elapsed().as_micros() as u64;
    // A fixed xorshift sequence: the same instants on every run of the test.
    let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut running = 0;
    for _ in 0..20 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let mut child = sweep_of(&scene, &part, &vary)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_micros(x % (full / 4)));
        running += usize::from(child.try_wait().unwrap().is_none());
        let _ = child.kill();
        child.wait().unwrap();
    }
    assert!(running >= 10, "only {running} of 20 kills found the sweep running");
    let said = ok(sweep_of(&scene, &part, &vary).output().unwrap());
    assert_eq!(csv(&part), csv(&whole), "after 20 kills: {said}");
    let timing = std::fs::read_to_string(part.join("timing.csv")).unwrap();
    assert_eq!(timing.lines().count(), 151);
    assert!(!part.join("sweep.journal.csv").exists());
}

#[test]
fn fresh_sweeps_killed_at_any_instant_resume_to_the_uninterrupted_bytes() {
    // `SWEEP_KILL_TRIALS` sets the number of trials (default 10): each a new sweep killed once
    // at a random instant of its run (its end included), then resumed to the end.
    let trials: u64 = std::env::var("SWEEP_KILL_TRIALS").ok().and_then(|n| n.parse().ok()).unwrap_or(10);
    let dir = folder("fresh_kills");
    let scene = gimbal(&dir, "gimbal.toml", 1.0);
    let vary = ["--vary", "Y=5:50:12", "--vary", "U3=50:150:5 rad/s"];
    let whole = dir.join("whole");
    let start = std::time::Instant::now();
    ok(sweep_of(&scene, &whole, &vary).output().unwrap());
    let full = start.elapsed().as_micros() as u64;
    let (expected, expected_timing_rows) = (csv(&whole), 61);
    let mut x: u64 = 0x2545_f491_4f6c_dd1d;
    let mut cut_short = 0;
    // The whole sweep may have been timed under other tests' load: a kill that finds the sweep
    // already ended narrows the window, and trials go on until half found it running.
    let mut window = full + full / 10;
    let mut trial = 0;
    while trial < trials || (cut_short * 2 < trial && trial < 4 * trials) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let part = dir.join(format!("part{trial}"));
        let mut child = sweep_of(&scene, &part, &vary)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(std::time::Duration::from_micros(x % window));
        let running = child.try_wait().unwrap().is_none();
        cut_short += u64::from(running);
        if !running {
            window = (window * 2 / 3).max(1);
        }
        let _ = child.kill();
        child.wait().unwrap();
        let said = ok(sweep_of(&scene, &part, &vary).output().unwrap());
        assert_eq!(csv(&part), expected, "trial {trial}: {said}");
        let timing = std::fs::read_to_string(part.join("timing.csv")).unwrap();
        assert_eq!(timing.lines().count(), expected_timing_rows, "trial {trial}");
        let left: Vec<_> = std::fs::read_dir(&part).unwrap().flatten().map(|e| e.file_name()).collect();
        let stray = left.iter().filter(|n| n.to_string_lossy().starts_with('.')).count();
        assert_eq!(stray, 0, "trial {trial}: files left behind: {left:?}");
        std::fs::remove_dir_all(&part).unwrap();
        trial += 1;
    }
    println!("sweep kill trials: {trial}, {cut_short} killed while running, each resumed equal to the whole");
    assert!(
        trials < 4 || cut_short * 2 >= trial,
        "only {cut_short} of {trial} kills found the sweep running"
    );
}
