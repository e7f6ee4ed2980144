//! The worker thread: takes the newest request from a one-slot mailbox, renders its
//! passes, and publishes each one into a small outbox, unless a newer request has arrived
//! meanwhile. The currency check and the publish happen under one lock, and a submit
//! clears the outbox of older generations, so once `submit` returns nothing older can be
//! taken. The outbox keeps at most [`OUTBOX_CAPACITY`] messages, dropping the oldest: a
//! window that does not poll (minimised) does not buffer a whole plan, and since every
//! frame carries its generation's convergence curve nothing is lost but older pictures.
//!
//! Between requests the thread keeps the hit cache of the last one-sample pass, so an
//! edit that moves nothing re-shades instead of re-tracing ([`super::render_plan_cached`]).

use std::collections::{BTreeMap, VecDeque};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use super::frame::{Frame, Published};
use super::job::run_caught;
use super::meshes::MeshFacts;
use super::progressive::render_plan_cached;
use super::request::PreviewRequest;
use crate::scene::{LoadWatch, mesh_objects};
use crate::trace::{HitCache, RenderProgress, World};

/// Called after every publish, from the worker thread (the editor asks for a repaint).
pub type Waker = Box<dyn Fn() + Send + Sync>;

/// Messages the outbox holds at most before it drops the oldest.
pub const OUTBOX_CAPACITY: usize = 4;

/// Owns the worker thread; dropping it cancels the render and joins the thread.
pub struct PreviewWorker {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

/// State shared by the UI side and the thread.
struct Shared {
    mailbox: Mutex<Mailbox>,
    /// Wakes the thread for a request or shutdown.
    wake: Condvar,
    /// Wakes a [`PreviewWorker::recv_timeout`] for a publish.
    published: Condvar,
}

#[derive(Default)]
struct Mailbox {
    /// The newest request not yet started; a newer submit replaces it.
    next: Option<PreviewRequest>,
    /// The newest generation ever submitted.
    newest: Option<u64>,
    /// Progress of the pass being rendered, to cancel it; `None` between passes.
    running: Option<Arc<RenderProgress>>,
    /// The mesh file being read before the next pass, as the scene writes its path.
    loading: Option<(String, Arc<LoadWatch>)>,
    /// What is known of each mesh read so far, by path as the scene writes it.
    mesh_facts: BTreeMap<String, MeshFacts>,
    /// Published messages not yet taken, oldest first, all of the newest generation.
    outbox: VecDeque<Published>,
    shutdown: bool,
}

impl Mailbox {
    /// Whether `generation` is still the newest request and nothing waits to replace it.
    fn is_current(&self, generation: u64) -> bool {
        !self.shutdown && self.next.is_none() && self.newest == Some(generation)
    }
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
            published: Condvar::new(),
        });
        let thread_shared = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("raylab-preview".to_owned())
            .spawn(move || run(&thread_shared, &waker))
            .expect("cannot start the preview thread");
        Self {
            shared,
            thread: Some(thread),
        }
    }

    /// Asks for `request` to be rendered, cancelling whatever is running before its next
    /// batch of samples and dropping unread messages of older generations. A request
    /// older than one already submitted is ignored.
    pub fn submit(&self, request: PreviewRequest) {
        let mut mailbox = lock(&self.shared.mailbox);
        if mailbox.newest.is_some_and(|g| request.generation < g) {
            return;
        }
        // A file the new scene no longer refers to (the import was undone) is not worth
        // finishing.
        if let Some((path, watch)) = &mailbox.loading
            && !mesh_objects(&request.scene).iter().any(|(_, p)| p == path)
        {
            watch.cancel();
        }
        let generation = request.generation;
        mailbox.newest = Some(generation);
        mailbox.next = Some(request);
        mailbox.outbox.retain(|m| m.generation >= generation);
        if let Some(running) = &mailbox.running {
            running.cancel();
        }
        self.shared.wake.notify_all();
    }

    /// The mesh file being read for the preview (its path as the scene writes it) and
    /// the fraction read; `None` when no file is being read.
    #[must_use]
    pub fn loading(&self) -> Option<(String, f64)> {
        lock(&self.shared.mailbox)
            .loading
            .as_ref()
            .map(|(path, watch)| (path.clone(), watch.fraction()))
    }

    /// What is known of each mesh file the preview has read, by path as the scene
    /// writes it.
    #[must_use]
    pub fn mesh_facts(&self) -> BTreeMap<String, MeshFacts> {
        lock(&self.shared.mailbox).mesh_facts.clone()
    }

    /// Stops reading the mesh file being read; the preview then reports the object
    /// whose file it was as not loaded.
    pub fn cancel_loading(&self) {
        if let Some((_, watch)) = &lock(&self.shared.mailbox).loading {
            watch.cancel();
        }
    }

    /// The newest message published since the last call, if any; older ones are dropped.
    pub fn latest(&mut self) -> Option<Published> {
        lock(&self.shared.mailbox).outbox.drain(..).next_back()
    }

    /// Every message still in the outbox, oldest first (for a view that follows each
    /// pass; at most [`OUTBOX_CAPACITY`] when the caller fell behind).
    pub fn drain(&mut self) -> Vec<Published> {
        lock(&self.shared.mailbox).outbox.drain(..).collect()
    }

    /// Waits up to `timeout` for the next message (for tests and headless use).
    pub fn recv_timeout(&mut self, timeout: Duration) -> Option<Published> {
        let deadline = Instant::now() + timeout;
        let mut mailbox = lock(&self.shared.mailbox);
        loop {
            if let Some(message) = mailbox.outbox.pop_front() {
                return Some(message);
            }
            let left = deadline.checked_duration_since(Instant::now())?;
            mailbox = self
                .shared
                .published
                .wait_timeout(mailbox, left)
                .unwrap_or_else(std::sync::PoisonError::into_inner)
                .0;
        }
    }

    /// Fraction of the running pass done, 0 to 1; `None` when idle or between passes.
    #[must_use]
    pub fn pass_progress(&self) -> Option<f64> {
        lock(&self.shared.mailbox)
            .running
            .as_ref()
            .map(|p| p.fraction())
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
fn run(shared: &Shared, waker: &Waker) {
    // The rays of the last one-sample pass: an edit that moves nothing re-shades them.
    let mut cache: Option<HitCache> = None;
    let mut meshes = super::meshes::MeshCache::default();
    while let Some(request) = next_request(shared) {
        let generation = request.generation;
        let publish = |result: Result<Frame, String>| {
            if put_in_outbox(shared, Published { generation, result }) {
                waker();
            }
        };
        // A panic in the tracer must not end the worker: report it and wait for the next
        // request (an edit may well avoid whatever caused it).
        let outcome = run_caught("the renderer", || {
            let mut watch_read = |path: &str| {
                let watch = Arc::new(LoadWatch::default());
                lock(&shared.mailbox).loading = Some((path.to_owned(), Arc::clone(&watch)));
                watch
            };
            let store = meshes.for_request(&request, &mut watch_read);
            let mut mailbox = lock(&shared.mailbox);
            mailbox.loading = None;
            if let Ok(store) = &store {
                for (_, path) in mesh_objects(&request.scene) {
                    if let Some(mesh) = store.get(path) {
                        mailbox
                            .mesh_facts
                            .insert(path.to_owned(), MeshFacts::of(mesh));
                    }
                }
            }
            drop(mailbox);
            let world = store.and_then(|store| {
                World::isolated_with_meshes(&request.scene, &request.options.isolation, &store)
                    .map_err(|e| e.to_string())
            });
            match world {
                Ok(world) => render_plan_cached(
                    &world,
                    &request.options,
                    &mut cache,
                    &mut || start_pass(shared),
                    &mut |frame| publish(Ok(frame)),
                ),
                Err(error) => publish(Err(error)),
            }
        });
        lock(&shared.mailbox).running = None;
        if let Err(message) = outcome {
            cache = None;
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

/// Puts `message` in the outbox if its generation is still current, under the same lock
/// a submit takes; returns whether it went in. The pass it reports is over.
fn put_in_outbox(shared: &Shared, message: Published) -> bool {
    let mut mailbox = lock(&shared.mailbox);
    mailbox.running = None;
    if !mailbox.is_current(message.generation) {
        return false;
    }
    mailbox.outbox.push_back(message);
    while mailbox.outbox.len() > OUTBOX_CAPACITY {
        mailbox.outbox.pop_front();
    }
    shared.published.notify_all();
    true
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
