//! The `gyro-sim` command (see [`gyro_sim::main_with`]).

fn main() -> std::process::ExitCode {
    gyro_sim::main_with(gyro_sim::Registry::builtin(), None)
}
