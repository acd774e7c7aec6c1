//! Stopping on request: SIGINT, SIGTERM and SIGHUP set a flag that long loops (an integration's
//! steps, a sweep's members) read between steps, so a run stops cleanly, keeps what it computed
//! and exits with the shell's code for the signal (128 + its number). A second signal of the same
//! kind ends the process at once.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// The number of the first stop signal received (0: none).
static RECEIVED: AtomicUsize = AtomicUsize::new(0);
/// Set once a signal arrived: a second one exits at once.
static ARMED: AtomicBool = AtomicBool::new(false);

/// A stop requested by a signal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Interrupted {
    /// The signal's number.
    pub signal: i32,
}

impl Interrupted {
    /// The signal's name (`SIGINT`, `SIGTERM`, `SIGHUP`).
    pub fn name(&self) -> &'static str {
        match self.signal {
            2 => "SIGINT",
            15 => "SIGTERM",
            1 => "SIGHUP",
            _ => "a signal",
        }
    }

    /// The exit code a shell gives a process ended by the signal: 128 + its number.
    pub fn exit_code(&self) -> u8 {
        u8::try_from(128 + self.signal).unwrap_or(1)
    }
}

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "interrupted by {}", self.name())
    }
}

/// Starts listening for SIGINT, SIGTERM and SIGHUP (once per process; later calls do nothing).
#[cfg(unix)]
pub fn listen() -> std::io::Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    static LISTENING: AtomicBool = AtomicBool::new(false);
    if LISTENING.swap(true, Ordering::SeqCst) {
        return Ok(());
    }
    for signal in [SIGINT, SIGTERM, SIGHUP] {
        // The second signal: the default action (the first set ARMED, below).
        signal_hook::flag::register_conditional_shutdown(signal, 128 + signal, &ARMED)?;
        signal_hook::flag::register_usize(signal, &RECEIVED, signal as usize)?;
        signal_hook::flag::register(signal, &ARMED)?;
    }
    Ok(())
}

/// Nothing to listen for where there are no Unix signals.
#[cfg(not(unix))]
pub fn listen() -> std::io::Result<()> {
    Ok(())
}

/// The stop requested so far, if any.
pub fn requested() -> Option<Interrupted> {
    match RECEIVED.load(Ordering::Relaxed) {
        0 => None,
        n => Some(Interrupted { signal: i32::try_from(n).unwrap_or(0) }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_signal_is_named_with_the_shells_exit_code() {
        let int = Interrupted { signal: 2 };
        assert_eq!((int.name(), int.exit_code()), ("SIGINT", 130));
        let term = Interrupted { signal: 15 };
        assert_eq!((term.to_string().as_str(), term.exit_code()), ("interrupted by SIGTERM", 143));
        assert_eq!(Interrupted { signal: 1 }.exit_code(), 129);
    }
}
