//! The reader under the OBJ loader: it counts the bytes read (for a progress bar, and to
//! find an error's line afterwards) and stops when the user cancels.

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

/// A buffered reader that adds what it hands out to a [`LoadWatch`], and fails with
/// "cancelled" once the watch is cancelled. It does not count lines as it goes (that
/// cost 2% of reading a large file): [`line_of_byte`] finds an error's line afterwards.
pub(super) struct WatchedReader<'w, R> {
    pub(super) inner: R,
    pub(super) watch: &'w LoadWatch,
}

impl LoadWatch {
    /// Bytes handed out so far.
    pub(super) fn bytes_read(&self) -> u64 {
        self.read.load(Ordering::Relaxed)
    }
}

/// The 1-based line of `text` that the byte at `offset` ends (the line a parser stopped
/// in, once it has taken that line and its newline).
pub(super) fn line_of_byte(text: impl Read, offset: u64) -> usize {
    let mut newlines = 0;
    let mut reader = std::io::BufReader::new(text.take(offset));
    while let Ok(buffer) = reader.fill_buf()
        && !buffer.is_empty()
    {
        newlines += buffer.iter().filter(|b| **b == b'\n').count();
        let taken = buffer.len();
        reader.consume(taken);
    }
    newlines.max(1)
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
        self.watch.read.fetch_add(read as u64, Ordering::Relaxed);
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
        self.watch.read.fetch_add(amount as u64, Ordering::Relaxed);
        self.inner.consume(amount);
    }
}
