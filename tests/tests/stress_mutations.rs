//! Stress suite, part two: 1,000 scenes made by mutating the preset scenes of
//! gyro-sim/scenes with a fixed seed (a line deleted or duplicated, a value of another type, an
//! extreme number, NaN or infinity as text, a misspelt key, a unit that is not one), each run
//! in this process with its files written: no panic, every failure a named error, every
//! success finite. Run: `cargo test --release -p kane-tests --test stress_mutations`.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use gyro_sim::Scene;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Scenes made.
const MUTANTS: usize = 1000;
/// The seed of the mutations.
const SEED: u64 = 14;

/// The preset scenes, shortened to 1 s and at most 200,000 steps so that a thousand runs take
/// seconds (the mutations never touch these two lines).
fn presets() -> Vec<(String, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gyro-sim/scenes");
    let mut out = Vec::new();
    for group in ["paper", "ejs"] {
        let mut paths: Vec<PathBuf> =
            std::fs::read_dir(root.join(group)).unwrap().map(|e| e.unwrap().path()).collect();
        paths.sort();
        for p in paths.into_iter().filter(|p| p.extension().is_some_and(|e| e == "toml")) {
            let text = std::fs::read_to_string(&p).unwrap();
            let text: String = text
                .lines()
                .map(|l| if l.starts_with("t_final") { "t_final = 1.0".to_string() } else { l.to_string() })
                .collect::<Vec<_>>()
                .join("\n");
            let text = text.replacen("[integrator]", "[integrator]\nmax_steps = 200000", 1);
            out.push((p.file_name().unwrap().to_string_lossy().into_owned(), text));
        }
    }
    out
}

/// Values a mutation puts in place of a value.
const REPLACEMENTS: &[&str] = &[
    "\"text\"",
    "true",
    "[1, 2]",
    "{ a = 1 }",
    "42",
    "1e308",
    "-1e308",
    "0",
    "-1",
    "0.0",
    "1e-308",
    "5e-324",
    "9223372036854775807",
    "-9223372036854775808",
    "nan",
    "inf",
    "-inf",
    "\"nan deg\"",
    "\"inf rad/s\"",
    "\"1e400 rad/s\"",
    "\"10 furlongs\"",
    "\"\"",
    "[]",
    "\"-0 deg\"",
    "1e-9",
    "1e9",
];

/// One mutation of `lines` (never the two lines [`presets`] added).
fn mutate(lines: &mut Vec<String>, rng: &mut StdRng) {
    let candidates: Vec<usize> = (0..lines.len())
        .filter(|i| {
            let l = lines[*i].trim();
            !l.is_empty() && !l.starts_with('#') && !l.starts_with("t_final") && !l.starts_with("max_steps")
        })
        .collect();
    if candidates.is_empty() {
        return;
    }
    let i = candidates[rng.random_range(0..candidates.len())];
    let line = lines[i].clone();
    match rng.random_range(0..5) {
        0 => {
            lines.remove(i);
        }
        1 => lines.insert(i, line),
        2 | 3 => {
            if let Some((key, _)) = line.split_once('=') {
                let value = REPLACEMENTS[rng.random_range(0..REPLACEMENTS.len())];
                lines[i] = format!("{key}= {value}");
            }
        }
        _ => {
            let mut chars: Vec<char> = line.chars().collect();
            let end = line.find('=').unwrap_or(chars.len()).min(chars.len());
            if end >= 2 {
                let k = rng.random_range(0..end - 1);
                chars.swap(k, k + 1);
            }
            lines[i] = chars.into_iter().collect();
        }
    }
}

/// How one mutant ended.
enum Outcome {
    Ran,
    Failed,
    Panicked(String),
    Unnamed(String),
    NotFinite,
}

/// Runs `text` as the scene `name` into `out`.
fn try_scene(name: &str, text: &str, out: &Path) -> Outcome {
    let result = catch_unwind(AssertUnwindSafe(|| {
        let scene = Scene::parse(name, text).map_err(|e| e.to_string())?;
        gyro_sim::run(&scene, Some(out)).map_err(|e| e.to_string())
    }));
    match result {
        Err(p) => Outcome::Panicked(
            p.downcast_ref::<String>()
                .cloned()
                .or(p.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default(),
        ),
        Ok(Ok(summary)) => {
            if summary.trajectory.rows.iter().flatten().all(|v| v.is_finite()) {
                Outcome::Ran
            } else {
                Outcome::NotFinite
            }
        }
        // Named: it says where (the scene's name, a key or a file) or what stopped.
        Ok(Err(e)) if e.contains(name) || e.contains("integration") => Outcome::Failed,
        Ok(Err(e)) => Outcome::Unnamed(e),
    }
}

#[test]
fn a_thousand_mutated_scenes_never_panic_and_every_failure_is_named() {
    let presets = presets();
    assert!(presets.len() >= 10, "{} presets", presets.len());
    let mut rng = StdRng::seed_from_u64(SEED);
    let mutants: Vec<(String, String)> = (0..MUTANTS)
        .map(|n| {
            let (name, text) = &presets[n % presets.len()];
            let mut lines: Vec<String> = text.lines().map(String::from).collect();
            for _ in 0..rng.random_range(1..=3) {
                mutate(&mut lines, &mut rng);
            }
            (format!("mutant{n}-{name}"), lines.join("\n"))
        })
        .collect();
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("stress_mutations");
    let _ = std::fs::remove_dir_all(&out);
    std::panic::set_hook(Box::new(|_| {}));
    let outcomes: Vec<(usize, Outcome)> = std::thread::scope(|s| {
        let workers: Vec<_> = (0..2)
            .map(|w| {
                let (mutants, out) = (&mutants, &out);
                s.spawn(move || {
                    (w..mutants.len())
                        .step_by(2)
                        .map(|n| (n, try_scene(&mutants[n].0, &mutants[n].1, &out.join(format!("w{w}")))))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers.into_iter().flat_map(|w| w.join().unwrap()).collect()
    });
    let _ = std::panic::take_hook();
    let count = |f: fn(&Outcome) -> bool| outcomes.iter().filter(|(_, o)| f(o)).count();
    let ran = count(|o| matches!(o, Outcome::Ran));
    let failed = count(|o| matches!(o, Outcome::Failed));
    println!("{MUTANTS} mutants (seed {SEED}): {ran} ran, {failed} refused or stopped with a named error");
    let bad: Vec<String> = outcomes
        .iter()
        .filter_map(|(n, o)| match o {
            Outcome::Panicked(m) => Some(format!("{}: panic: {m}\n{}", mutants[*n].0, mutants[*n].1)),
            Outcome::Unnamed(m) => Some(format!("{}: unnamed error: {m}", mutants[*n].0)),
            Outcome::NotFinite => Some(format!("{}: ran with values that are not finite", mutants[*n].0)),
            _ => None,
        })
        .collect();
    assert!(bad.is_empty(), "{} bad outcomes:\n{}", bad.len(), bad.join("\n---\n"));
    assert_eq!(ran + failed, MUTANTS);
}
