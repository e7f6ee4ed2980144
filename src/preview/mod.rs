//! The background preview worker: the editor sends immutable scene snapshots, each with a
//! generation number; a worker thread renders them progressively (a coarse pass, then
//! full resolution at one sample, then accumulated anti-aliasing samples) and publishes
//! each finished pass as `(generation, frame)`. No egui types here: the UI passes a waker
//! closure and polls [`PreviewWorker::latest`].
//!
//! Ordering guarantee: a frame of an older generation is never published after a frame of
//! a newer one, and a submit cancels the running pass at its next tile boundary. A panic
//! while rendering is published as an error and the worker waits for the next request.

mod convergence;
mod frame;
mod job;
mod latency;
mod plan;
mod probe;
mod request;
mod worker;

pub use convergence::{ConvergenceCurve, ConvergencePoint, rmse_nearest};
pub use frame::{Frame, Published};
pub use job::{BackgroundJob, panic_message, run_caught};
pub use latency::{PreviewLatency, measure_latency};
pub use plan::{
    COARSE_MAX_DIVIDER, COARSE_MIN_LONG_SIDE, Pass, coarse_divider, coarse_dividers, plan_passes,
};
pub use probe::{Probe, ProbeWork, WorldCache};
pub use request::{MAX_PREVIEW_LONG_SIDE, PreviewRequest};
pub use worker::{PreviewWorker, Waker};
