//! A run's rows as they are produced: in come rows at output times; out they go to a
//! [`RowStream`] (a CSV being written) at once, and only a bounded, evenly thinned set stays in
//! memory for the figures, the view and the summary, so a long run's memory stays flat.
//! Without a stream every row is kept, as before.

use std::sync::{Arc, Mutex};

use thiserror::Error;

/// Most rows kept in memory beside a stream (figures are drawn from them).
pub const MAX_KEPT_ROWS: usize = 20_000;

/// Takes rows (`t`, then the columns, model units) one at a time.
pub trait RowSink: Send {
    /// Takes one row; an error stops the run.
    fn row(&mut self, row: &[f64]) -> Result<(), RowError>;
}

/// Why a row could not be taken.
#[derive(Clone, Debug, Error)]
pub enum RowError {
    /// The sink failed at an earlier row (a thread panicked while it held the sink).
    #[error("the row writer failed earlier")]
    Poisoned,
    /// The sink could not take the row: its own error (a file's, for a CSV).
    #[error("{0}")]
    Sink(#[source] Arc<dyn std::error::Error + Send + Sync>),
}

impl RowError {
    /// The sink's error `e`.
    pub fn sink(e: impl std::error::Error + Send + Sync + 'static) -> RowError {
        RowError::Sink(Arc::new(e))
    }
}

impl PartialEq for RowError {
    /// Equal when both are [`RowError::Poisoned`] or both hold the same sink error.
    fn eq(&self, other: &RowError) -> bool {
        match (self, other) {
            (RowError::Poisoned, RowError::Poisoned) => true,
            (RowError::Sink(a), RowError::Sink(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}

/// A shared `RowSink`, as a problem carries it.
#[derive(Clone)]
pub struct RowStream(pub Arc<Mutex<dyn RowSink>>);

impl RowStream {
    /// Sends one row.
    fn send(&self, row: &[f64]) -> Result<(), RowError> {
        let mut sink = self.0.lock().map_err(|_| RowError::Poisoned)?;
        sink.row(row)
    }
}

impl std::fmt::Debug for RowStream {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("RowStream")
    }
}

/// The rows of one integration: all of them, or with a stream, every `stride`-th (the stride
/// doubling whenever more than [`MAX_KEPT_ROWS`] are held) and the last.
pub(crate) struct Rows {
    kept: Vec<Vec<f64>>,
    stream: Option<RowStream>,
    bounded: bool,
    stride: usize,
    seen: usize,
    last: Option<Vec<f64>>,
}

impl Rows {
    /// All rows kept in memory.
    pub(crate) fn all() -> Rows {
        Rows { kept: Vec::new(), stream: None, bounded: false, stride: 1, seen: 0, last: None }
    }

    /// Rows sent to `stream` (when there is one) and, then, a thinned set kept.
    pub(crate) fn streamed(stream: Option<RowStream>) -> Rows {
        let bounded = stream.is_some();
        Rows { stream, bounded, ..Rows::all() }
    }

    /// A bounded, thinned set kept, nothing sent (the figures' denser rows beside a stream).
    pub(crate) fn thinned(bounded: bool) -> Rows {
        Rows { bounded, ..Rows::all() }
    }

    /// Takes one row.
    pub(crate) fn push(&mut self, row: Vec<f64>) -> Result<(), RowError> {
        if let Some(s) = &self.stream {
            s.send(&row)?;
        }
        let index = self.seen;
        self.seen += 1;
        if !self.bounded {
            self.kept.push(row);
            return Ok(());
        }
        if index.is_multiple_of(self.stride) {
            self.kept.push(row);
            if self.kept.len() > MAX_KEPT_ROWS {
                self.stride *= 2;
                let mut i = 0;
                self.kept.retain(|_| {
                    i += 1;
                    (i - 1) % 2 == 0
                });
            }
            self.last = None;
        } else {
            self.last = Some(row);
        }
        Ok(())
    }

    /// The rows kept (with the last row taken).
    pub(crate) fn into_rows(mut self) -> Vec<Vec<f64>> {
        self.kept.extend(self.last);
        self.kept
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Count(usize);
    impl RowSink for Count {
        fn row(&mut self, _: &[f64]) -> Result<(), RowError> {
            self.0 += 1;
            Ok(())
        }
    }

    #[test]
    fn a_stream_gets_every_row_and_memory_keeps_a_bounded_evenly_spaced_set() {
        let sink = Arc::new(Mutex::new(Count(0)));
        let mut rows = Rows::streamed(Some(RowStream(sink.clone())));
        let n = 5 * MAX_KEPT_ROWS + 7;
        for i in 0..n {
            rows.push(vec![i as f64]).unwrap();
        }
        let kept = rows.into_rows();
        assert_eq!(sink.lock().unwrap().0, n);
        assert!(kept.len() <= MAX_KEPT_ROWS + 1 && kept.len() > MAX_KEPT_ROWS / 2, "{}", kept.len());
        assert_eq!(kept[0][0], 0.0);
        assert_eq!(kept.last().unwrap()[0], (n - 1) as f64);
        let gaps: Vec<f64> = kept.windows(2).take(kept.len() - 2).map(|w| w[1][0] - w[0][0]).collect();
        assert!(gaps.iter().all(|g| *g == gaps[0]), "evenly spaced");
        let mut all = Rows::all();
        for i in 0..n {
            all.push(vec![i as f64]).unwrap();
        }
        assert_eq!(all.into_rows().len(), n);
    }
}
