//! The reader under the OBJ loader: it counts lines (for error messages), reports how
//! many bytes are read (for a progress bar) and stops when the user cancels.

use std::io::{BufRead, Read};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Progress of one file being read, and its cancel switch; shared between the thread
/// that reads and the one that shows it.
#[derive(Debug, Default)]
pub struct LoadWatch {
    read: AtomicU64,
    total: AtomicU64,
    cancelled: AtomicBool,
}

impl LoadWatch {
    /// Fraction of the file read so far, 0 to 1 (0 before the size is known).
    #[must_use]
    pub fn fraction(&self) -> f64 {
        let total = self.total.load(Ordering::Relaxed);
        if total == 0 {
            return 0.0;
        }
        (self.read.load(Ordering::Relaxed) as f64 / total as f64).min(1.0)
    }

    /// Asks the reading to stop at its next buffer.
    pub fn cancel(&self) {
        self.cancelled.store(true, Ordering::Relaxed);
    }

    /// Whether [`LoadWatch::cancel`] was called.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        self.cancelled.load(Ordering::Relaxed)
    }

    pub(super) fn start(&self, total: u64) {
        self.total.store(total, Ordering::Relaxed);
        self.read.store(0, Ordering::Relaxed);
    }
}

/// A buffered reader that counts the newlines passed, adds what it reads to a
/// [`LoadWatch`], and fails with "cancelled" once the watch is cancelled.
pub(super) struct WatchedReader<'w, R> {
    pub(super) inner: R,
    pub(super) newlines: usize,
    pub(super) watch: &'w LoadWatch,
}

impl<R: BufRead> WatchedReader<'_, R> {
    fn passed(&mut self, bytes: &[u8]) {
        self.newlines += bytes.iter().filter(|b| **b == b'\n').count();
        self.watch
            .read
            .fetch_add(bytes.len() as u64, Ordering::Relaxed);
    }
}

fn cancelled() -> std::io::Error {
    std::io::Error::other("cancelled")
}

impl<R: BufRead> Read for WatchedReader<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if self.watch.is_cancelled() {
            return Err(cancelled());
        }
        let read = self.inner.read(buf)?;
        self.passed(&buf[..read]);
        Ok(read)
    }
}

impl<R: BufRead> BufRead for WatchedReader<'_, R> {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        if self.watch.is_cancelled() {
            return Err(cancelled());
        }
        self.inner.fill_buf()
    }

    fn consume(&mut self, amount: usize) {
        if let Ok(buffer) = self.inner.fill_buf() {
            let taken = amount.min(buffer.len());
            let newlines = buffer[..taken].iter().filter(|b| **b == b'\n').count();
            self.newlines += newlines;
            self.watch.read.fetch_add(taken as u64, Ordering::Relaxed);
        }
        self.inner.consume(amount);
    }
}
