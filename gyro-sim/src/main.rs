//! The `gyro-sim` command.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use gyro_sim::run;
use gyro_sim::scene::Scene;

/// Simulate models derived with Kane's method.
#[derive(Parser)]
#[command(name = "gyro-sim", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene: writes DIR/trajectory.csv and DIR/trajectory.png, prints a summary.
    Run {
        /// The scene file (TOML).
        scene: PathBuf,
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
    },
}

fn main() -> ExitCode {
    let Command::Run { scene, out } = Cli::parse().command;
    let scene = match Scene::load(&scene) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    match run::run(&scene, Some(&out)) {
        Ok(summary) => {
            print_summary(&scene.title, &summary);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{}: {e}", scene.path.display());
            ExitCode::FAILURE
        }
    }
}

/// The run's statistics, energy, files and accuracy.
fn print_summary(title: &str, summary: &run::RunSummary) {
    let t = &summary.trajectory;
    let energy = match t.kinetic_energy {
        Some((a, b)) => format!("; kinetic energy {a:.6e} -> {b:.6e} (change {:+.6e})", b - a),
        None => String::new(),
    };
    let files = match &summary.written {
        Some(w) => format!("; wrote {} rows to {} and {}", t.rows.len(), w.csv.display(), w.plot.display()),
        None => String::new(),
    };
    println!(
        "{title}: {} steps ({} rejected), {} RHS evaluations, {:.3} ms{energy}{files}",
        t.stats.steps,
        t.stats.rejected,
        t.stats.rhs_evals,
        t.wall.as_secs_f64() * 1e3,
    );
    for line in conserved_drifts(t) {
        println!("{line}");
    }
    if let Some(d) = t.norm_drift {
        println!(
            "Euler-parameter norm: largest drift {:.2e} (projected back past {:.0e}: {} times); outputs use the normalised parameters",
            d.largest, d.threshold, d.projections
        );
    }
    if let Some(a) = t.accuracy {
        println!(
            "accuracy {:e} asked: {} runs; the written one (rtol {:.1e}, atol {:.1e}) differs by {:.2e} from the run before (about that run's error; the written run's is far smaller)",
            a.goal, a.runs, a.rtol, a.atol, a.estimate
        );
    }
}

/// The drift of the conserved quantities the run wrote (`ENERGY`, `LZ`, `L3`): start, end and
/// the change relative to max(1, |start|).
fn conserved_drifts(t: &gyro_sim::trajectory::Trajectory) -> Vec<String> {
    let (Some(first), Some(last)) = (t.rows.first(), t.rows.last()) else { return Vec::new() };
    t.columns
        .iter()
        .enumerate()
        .filter(|(_, c)| ["ENERGY", "LZ", "L3"].iter().any(|n| c.name.eq_ignore_ascii_case(n)))
        .map(|(k, c)| {
            let (a, b) = (first[k + 1], last[k + 1]);
            format!(
                "{}: {a:.12e} -> {b:.12e} (drift {:.2e} relative)",
                c.name,
                (b - a).abs() / a.abs().max(1.0)
            )
        })
        .collect()
}
