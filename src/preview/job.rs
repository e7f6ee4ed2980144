//! Long work off the caller's thread, the one way raylab runs it: a thread of its own, a
//! [`RenderProgress`] to watch and cancel through, and a panic turned into an error
//! message instead of taking the program down. The preview worker, the editor's export
//! and `raylab render` all use this.

use std::any::Any;
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, TryRecvError};
use std::time::Duration;

use crate::trace::RenderProgress;

/// Runs `work`, turning a panic into `Err("{what} crashed: {reason}")`.
///
/// # Errors
/// When `work` panicked.
pub fn run_caught<T>(what: &str, work: impl FnOnce() -> T) -> Result<T, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))
        .map_err(|panic| format!("{what} crashed: {}", panic_message(panic.as_ref())))
}

/// The text a panic was raised with, or "unknown reason".
#[must_use]
pub fn panic_message(panic: &(dyn Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown reason".to_owned())
}

/// Work running on its own thread. Dropping the job cancels it (the thread then ends at
/// the work's next cancellation check).
pub struct BackgroundJob<T> {
    progress: Arc<RenderProgress>,
    result: Receiver<Result<T, String>>,
    what: String,
}

impl<T: Send + 'static> BackgroundJob<T> {
    /// Starts `work` on a thread named `raylab-{what}`. `work` returns `None` when it saw
    /// the cancel flag; that becomes `Err("{what} cancelled")`. `done` runs on the thread
    /// once the result is ready (the editor asks for a repaint there).
    ///
    /// # Errors
    /// When the operating system cannot start a thread.
    pub fn spawn(
        what: &str,
        work: impl FnOnce(&RenderProgress) -> Option<T> + Send + 'static,
        done: impl FnOnce() + Send + 'static,
    ) -> Result<Self, String> {
        let progress = Arc::new(RenderProgress::default());
        let (sender, result) = mpsc::channel();
        let thread_progress = Arc::clone(&progress);
        let label = what.to_owned();
        std::thread::Builder::new()
            .name(format!("raylab-{what}"))
            .spawn(move || {
                let outcome = run_caught(&label, || work(&thread_progress))
                    .and_then(|r| r.ok_or_else(|| format!("{label} cancelled")));
                let _ = sender.send(outcome);
                done();
            })
            .map_err(|e| format!("cannot start the {what}: {e}"))?;
        Ok(Self {
            progress,
            result,
            what: what.to_owned(),
        })
    }
}

impl<T> BackgroundJob<T> {
    /// Fraction done, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        self.progress.fraction()
    }

    /// Asks the work to stop at its next check.
    pub fn cancel(&self) {
        self.progress.cancel();
    }

    /// The outcome once the work has ended, `None` while it runs.
    pub fn try_result(&self) -> Option<Result<T, String>> {
        match self.result.try_recv() {
            Ok(outcome) => Some(outcome),
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => Some(Err(self.vanished())),
        }
    }

    /// Blocks until the work ends, calling `tick` with the fraction done every `interval`
    /// meanwhile. Returns as soon as the work ends, not at the next tick.
    ///
    /// # Errors
    /// The work panicked or was cancelled.
    pub fn wait(self, interval: Duration, mut tick: impl FnMut(f64)) -> Result<T, String> {
        loop {
            match self.result.recv_timeout(interval) {
                Ok(outcome) => return outcome,
                Err(RecvTimeoutError::Timeout) => tick(self.fraction()),
                Err(RecvTimeoutError::Disconnected) => return Err(self.vanished()),
            }
        }
    }

    fn vanished(&self) -> String {
        format!("the {} stopped unexpectedly", self.what)
    }
}

impl<T> Drop for BackgroundJob<T> {
    fn drop(&mut self) {
        self.progress.cancel();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_both_kinds_of_panic_payload() {
        let text = std::panic::catch_unwind(|| panic!("static text")).unwrap_err();
        assert_eq!(panic_message(text.as_ref()), "static text");
        let formatted = std::panic::catch_unwind(|| panic!("formatted {}", 42)).unwrap_err();
        assert_eq!(panic_message(formatted.as_ref()), "formatted 42");
    }

    #[test]
    fn a_job_returns_its_value_a_panic_or_its_cancellation() {
        let job = BackgroundJob::spawn("sum", |_| Some(2 + 2), || {}).unwrap();
        assert_eq!(job.wait(Duration::from_millis(5), |_| {}), Ok(4));

        let job = BackgroundJob::<u32>::spawn("export", |_| panic!("boom"), || {}).unwrap();
        assert_eq!(
            job.wait(Duration::from_millis(5), |_| {}),
            Err("export crashed: boom".to_owned())
        );

        // The work waits for the cancel flag, then reports that it saw it.
        let job = BackgroundJob::<u32>::spawn(
            "render",
            |progress| {
                while !progress.is_cancelled() {
                    std::thread::yield_now();
                }
                None
            },
            || {},
        )
        .unwrap();
        assert!(job.try_result().is_none(), "still waiting for the flag");
        job.cancel();
        let outcome = job.wait(Duration::from_millis(1), |_| {});
        assert_eq!(outcome, Err("render cancelled".to_owned()));
    }
}
