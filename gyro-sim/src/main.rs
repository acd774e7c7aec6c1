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
        Ok(s) => {
            println!(
                "{}: {} steps ({} rejected), {} RHS evaluations, {:.3} ms; kinetic energy {:.6e} -> {:.6e} (change {:+.6e}); wrote {} rows to {} and {}",
                scene.title,
                s.stats.steps,
                s.stats.rejected,
                s.stats.rhs_evals,
                s.wall.as_secs_f64() * 1e3,
                s.kinetic_energy.0,
                s.kinetic_energy.1,
                s.kinetic_energy.1 - s.kinetic_energy.0,
                s.table.rows.len(),
                s.csv.as_ref().map_or(String::new(), |p| p.display().to_string()),
                s.plot.as_ref().map_or(String::new(), |p| p.display().to_string()),
            );
            if let Some(a) = s.accuracy {
                println!(
                    "accuracy {:e} asked: {} runs; the written one (rtol {:.1e}, atol {:.1e}) differs by {:.2e} from the run before (about that run's error; the written run's is far smaller)",
                    a.goal, a.runs, a.rtol, a.atol, a.estimate
                );
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{}: {e}", scene.path.display());
            ExitCode::FAILURE
        }
    }
}
