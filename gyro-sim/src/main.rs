//! The `gyro-sim` command (see [`gyro_sim::cli`]).

fn main() -> std::process::ExitCode {
    gyro_sim::cli::main_with(gyro_sim::registry::Registry::builtin(), None)
}
