//! The background preview worker: the editor sends immutable scene snapshots, each with a
//! generation number; a worker thread renders them progressively (a coarse pass, then
//! full resolution at one sample, then accumulated anti-aliasing samples) and publishes
//! each finished pass as `(generation, frame)`. An edit that moves no object and not the
//! camera re-shades the previous one-sample pass's cached hits and starts at full
//! resolution. No egui types here: the UI passes a waker closure and polls
//! [`PreviewWorker::latest`].
//!
//! Ordering guarantee: once a submit returns, no frame of an older generation can be
//! taken, and the running pass stops within one batch of samples per tile. A panic while
//! rendering is published as an error and the worker waits for the next request.

mod convergence;
mod frame;
mod job;
mod latency;
mod meshes;
mod plan;
mod probe;
mod progressive;
mod request;
mod worker;

pub use convergence::{ConvergenceCurve, ConvergencePoint, estimated_rmse, rmse_nearest};
pub use frame::{Frame, Published};
pub use job::{BackgroundJob, panic_message, run_caught};
pub use latency::{PreviewLatency, measure_latency, measure_restart_latency, median};
pub use meshes::{MeshCache, MeshFacts};
pub use plan::{
    COARSE_MAX_DIVIDER, COARSE_MIN_LONG_SIDE, Pass, coarse_divider, coarse_dividers, plan_passes,
};
pub use probe::{Probe, ProbeWork, WorldCache};
pub use progressive::{render_plan, render_plan_cached};
pub use request::{MAX_PREVIEW_LONG_SIDE, PreviewRequest};
pub use worker::{OUTBOX_CAPACITY, PreviewWorker, Waker};
