//! The worker thread: takes the newest request from a one-slot mailbox, renders its
//! passes, and publishes each one unless a newer request has arrived meanwhile.

use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use super::frame::{Frame, Published};
use super::job::run_caught;
use super::plan::{Pass, plan_passes};
use super::request::PreviewRequest;
use crate::trace::{Image, RayCounts, RenderOptions, RenderProgress, SampleSums, World};
use crate::trace::{render_samples, render_samples_into};

/// Called after every publish, from the worker thread (the editor asks for a repaint).
pub type Waker = Box<dyn Fn() + Send + Sync>;

/// Owns the worker thread; dropping it cancels the render and joins the thread.
pub struct PreviewWorker {
    shared: Arc<Shared>,
    published: Receiver<Published>,
    thread: Option<JoinHandle<()>>,
    /// The newest generation handed to the UI, so it never goes back.
    last_taken: Option<u64>,
}

/// State shared by the UI side and the thread.
struct Shared {
    mailbox: Mutex<Mailbox>,
    wake: Condvar,
}

#[derive(Default)]
struct Mailbox {
    /// The newest request not yet started; a newer submit replaces it.
    next: Option<PreviewRequest>,
    /// The newest generation ever submitted.
    newest: Option<u64>,
    /// Progress of the pass being rendered, to cancel it.
    running: Option<Arc<RenderProgress>>,
    shutdown: bool,
}

impl PreviewWorker {
    /// Starts the worker thread. `waker` runs after each publish.
    ///
    /// # Panics
    /// When the operating system cannot start a thread.
    #[must_use]
    pub fn spawn(waker: Waker) -> Self {
        let shared = Arc::new(Shared {
            mailbox: Mutex::new(Mailbox::default()),
            wake: Condvar::new(),
        });
        let (sender, published) = mpsc::channel();
        let thread_shared = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("raylab-preview".to_owned())
            .spawn(move || run(&thread_shared, &sender, &waker))
            .expect("cannot start the preview thread");
        Self {
            shared,
            published,
            thread: Some(thread),
            last_taken: None,
        }
    }

    /// Asks for `request` to be rendered, cancelling whatever is running at its next tile
    /// boundary. A request older than one already submitted is ignored.
    pub fn submit(&self, request: PreviewRequest) {
        let mut mailbox = lock(&self.shared.mailbox);
        if mailbox.newest.is_some_and(|g| request.generation < g) {
            return;
        }
        mailbox.newest = Some(request.generation);
        mailbox.next = Some(request);
        if let Some(running) = &mailbox.running {
            running.cancel();
        }
        self.shared.wake.notify_all();
    }

    /// The newest message published since the last call, if any; older ones are dropped.
    pub fn latest(&mut self) -> Option<Published> {
        let mut newest = None;
        while let Ok(message) = self.published.try_recv() {
            newest = Some(message);
        }
        self.accept(newest)
    }

    /// Every message published since the last call, oldest first, without any older than
    /// one already handed out (for a view that follows each pass, such as a curve).
    pub fn drain(&mut self) -> Vec<Published> {
        let mut messages = Vec::new();
        while let Ok(message) = self.published.try_recv() {
            if let Some(message) = self.accept(Some(message)) {
                messages.push(message);
            }
        }
        messages
    }

    /// Waits up to `timeout` for the next message (for tests and headless use).
    pub fn recv_timeout(&mut self, timeout: Duration) -> Option<Published> {
        let message = self.published.recv_timeout(timeout).ok();
        self.accept(message)
    }

    /// Fraction of the running pass done, 0 to 1; `None` when idle.
    #[must_use]
    pub fn pass_progress(&self) -> Option<f64> {
        lock(&self.shared.mailbox)
            .running
            .as_ref()
            .map(|p| p.fraction())
    }

    /// Passes a message on unless it is older than one already handed out.
    fn accept(&mut self, message: Option<Published>) -> Option<Published> {
        let message = message?;
        if self.last_taken.is_some_and(|g| message.generation < g) {
            return None;
        }
        self.last_taken = Some(message.generation);
        Some(message)
    }
}

impl Drop for PreviewWorker {
    fn drop(&mut self) {
        {
            let mut mailbox = lock(&self.shared.mailbox);
            mailbox.shutdown = true;
            if let Some(running) = &mailbox.running {
                running.cancel();
            }
            self.shared.wake.notify_all();
        }
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// Locks the mailbox; a panic elsewhere cannot leave it inconsistent, so poison is ignored.
fn lock(mutex: &Mutex<Mailbox>) -> MutexGuard<'_, Mailbox> {
    mutex
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The thread's loop: wait for a request, render it, repeat until shutdown.
fn run(shared: &Shared, sender: &Sender<Published>, waker: &Waker) {
    while let Some(request) = next_request(shared) {
        let publish = |result: Result<Frame, String>| {
            if is_current(shared, request.generation) {
                let message = Published {
                    generation: request.generation,
                    result,
                };
                if sender.send(message).is_ok() {
                    waker();
                }
            }
        };
        // A panic in the tracer must not end the worker: report it and wait for the next
        // request (an edit may well avoid whatever caused it).
        let outcome = run_caught("the renderer", || {
            match World::isolated(&request.scene, &request.options.isolation) {
                Ok(world) => render_plan(shared, &world, &request.options, &publish),
                Err(error) => publish(Err(error.to_string())),
            }
        });
        if let Err(message) = outcome {
            lock(&shared.mailbox).running = None;
            publish(Err(message));
        }
    }
}

/// Blocks until a request is waiting (`Some`) or the worker shuts down (`None`).
fn next_request(shared: &Shared) -> Option<PreviewRequest> {
    let mut mailbox = lock(&shared.mailbox);
    loop {
        if mailbox.shutdown {
            return None;
        }
        if let Some(request) = mailbox.next.take() {
            return Some(request);
        }
        mailbox = shared
            .wake
            .wait(mailbox)
            .unwrap_or_else(std::sync::PoisonError::into_inner);
    }
}

/// Whether `generation` is still the newest request and nothing is waiting to replace it.
fn is_current(shared: &Shared, generation: u64) -> bool {
    let mailbox = lock(&shared.mailbox);
    !mailbox.shutdown && mailbox.next.is_none() && mailbox.newest == Some(generation)
}

/// Renders the passes of the plan in order; stops when one is cancelled.
fn render_plan(
    shared: &Shared,
    world: &World,
    target: &RenderOptions,
    publish: &dyn Fn(Result<Frame, String>),
) {
    let passes = plan_passes(target);
    let mut accumulated = None;
    for (index, &pass) in passes.iter().enumerate() {
        let Some(progress) = start_pass(shared) else {
            return;
        };
        let started = Instant::now();
        let image_and_rays = render_pass(world, target, pass, &mut accumulated, &progress);
        lock(&shared.mailbox).running = None;
        let Some(rendered) = image_and_rays else {
            return;
        };
        publish(Ok(Frame {
            image: rendered.image,
            pass,
            elapsed: started.elapsed(),
            rays: rendered.rays,
            is_final: index + 1 == passes.len(),
            non_finite_samples: rendered.non_finite_samples,
            non_finite_pixels: rendered.non_finite_pixels,
        }));
    }
}

/// Registers a fresh progress for the next pass, unless a newer request is waiting.
fn start_pass(shared: &Shared) -> Option<Arc<RenderProgress>> {
    let mut mailbox = lock(&shared.mailbox);
    if mailbox.shutdown || mailbox.next.is_some() {
        return None;
    }
    let progress = Arc::new(RenderProgress::default());
    mailbox.running = Some(Arc::clone(&progress));
    Some(progress)
}

/// Anti-aliasing samples summed so far at full resolution.
struct Accumulated {
    sums: SampleSums,
    samples: u32,
}

/// What one pass made.
struct Rendered {
    image: Image,
    /// Rays of this pass alone.
    rays: RayCounts,
    non_finite_samples: u64,
    non_finite_pixels: Vec<u32>,
}

impl Rendered {
    fn new(sums: &SampleSums, count: u32, rays: RayCounts) -> Self {
        Self {
            image: sums.average(count),
            rays,
            non_finite_samples: sums.non_finite,
            non_finite_pixels: sums.non_finite_pixels.clone(),
        }
    }
}

/// Renders one pass; accumulating passes continue the sums in `accumulated` (sample by
/// sample in index order, exactly as [`crate::trace::render`] sums them, so the final
/// frame is bit-identical to a direct render). `None` if cancelled.
fn render_pass(
    world: &World,
    target: &RenderOptions,
    pass: Pass,
    accumulated: &mut Option<Accumulated>,
    progress: &RenderProgress,
) -> Option<Rendered> {
    match pass {
        Pass::Coarse { .. } | Pass::Full { target: 1, .. } => {
            let (width, height) = pass.size(target.width, target.height);
            let options = RenderOptions {
                width,
                height,
                samples_per_pixel: 1,
                ..target.clone()
            };
            let sums = render_samples(world, &options, 0..1, progress)?;
            Some(Rendered::new(&sums, 1, sums.rays))
        }
        Pass::Full {
            samples,
            target: count,
        } => {
            let options = RenderOptions {
                samples_per_pixel: count,
                ..target.clone()
            };
            let state = accumulated.get_or_insert_with(|| Accumulated {
                sums: SampleSums::zero(options.width, options.height),
                samples: 0,
            });
            let rays = render_samples_into(
                world,
                &options,
                state.samples..samples,
                &mut state.sums,
                progress,
            )?;
            state.samples = samples;
            Some(Rendered::new(&state.sums, samples, rays))
        }
    }
}
