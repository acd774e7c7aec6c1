//! A counting gate: at most N holders at once, the others waiting their turn (runs are CPU
//! bound: more at once than cores only slows every one).

use std::sync::{Condvar, Mutex};

/// At most `limit` holders at once.
pub struct Gate {
    held: Mutex<usize>,
    freed: Condvar,
    limit: usize,
}

/// A place in the gate, given back when dropped.
pub struct Pass<'a>(&'a Gate);

impl Gate {
    /// A gate for `limit` holders (at least one).
    pub fn new(limit: usize) -> Gate {
        Gate { held: Mutex::new(0), freed: Condvar::new(), limit: limit.max(1) }
    }

    /// Waits for a place.
    pub fn enter(&self) -> Pass<'_> {
        let mut held = self.held.lock().unwrap_or_else(|e| e.into_inner());
        while *held >= self.limit {
            held = self.freed.wait(held).unwrap_or_else(|e| e.into_inner());
        }
        *held += 1;
        Pass(self)
    }
}

impl Drop for Pass<'_> {
    fn drop(&mut self) {
        let mut held = self.0.held.lock().unwrap_or_else(|e| e.into_inner());
        *held -= 1;
        self.0.freed.notify_one();
    }
}
