//! Questions about single rays, answered off the caller's thread: which object is under
//! the cursor, what lies behind a pixel. Each question runs as a [`BackgroundJob`] on the
//! world of its own scene snapshot and isolation switches (muted lights and hidden
//! objects left out, [`World::isolated`]); the newest world is kept, so a click or an
//! open pixel inspector builds a world only after an edit, and never on the UI thread.
//!
//! One question runs at a time per [`Probe`]; a question asked meanwhile waits, and a
//! newer one replaces it (only the newest state is worth answering).

use std::sync::{Arc, Mutex, PoisonError};

use super::job::BackgroundJob;
use crate::scene::Scene;
use crate::trace::{Isolation, World};

/// The world of the newest scene (and isolation) a question was asked about, shared by
/// the probes.
#[derive(Default)]
pub struct WorldCache {
    newest: Mutex<Option<(Arc<Scene>, Arc<World>)>>,
}

impl WorldCache {
    /// The world of `scene` without what `isolation` leaves out: the kept one if it was
    /// built from an equal scene and isolation, else a new one (which is then kept).
    ///
    /// # Errors
    /// The scene's validation message, or an isolation index the scene does not have.
    pub fn world(&self, scene: &Arc<Scene>, isolation: &Isolation) -> Result<Arc<World>, String> {
        {
            let newest = self.newest.lock().unwrap_or_else(PoisonError::into_inner);
            if let Some((kept, world)) = newest.as_ref()
                && world.isolation == *isolation
                && (Arc::ptr_eq(kept, scene) || **kept == **scene)
            {
                return Ok(Arc::clone(world));
            }
        }
        // Built without the lock: another probe may use the old world meanwhile.
        let world = Arc::new(World::isolated(scene, isolation).map_err(|e| e.to_string())?);
        *self.newest.lock().unwrap_or_else(PoisonError::into_inner) =
            Some((Arc::clone(scene), Arc::clone(&world)));
        Ok(world)
    }
}

/// The work of one question, given the world of its scene.
pub type ProbeWork<T> = Box<dyn FnOnce(&World) -> T + Send>;

/// A question not started yet.
struct Question<T> {
    tag: u64,
    scene: Arc<Scene>,
    isolation: Isolation,
    work: ProbeWork<T>,
}

/// Runs questions of one kind (answers of type `T`), one at a time.
pub struct Probe<T> {
    cache: Arc<WorldCache>,
    waker: Arc<dyn Fn() + Send + Sync>,
    running: Option<(u64, BackgroundJob<Result<T, String>>)>,
    waiting: Option<Question<T>>,
    next_tag: u64,
}

impl<T: Send + 'static> Probe<T> {
    /// A probe sharing `cache`; `waker` runs on the job's thread once an answer is ready.
    #[must_use]
    pub fn new(cache: Arc<WorldCache>, waker: Arc<dyn Fn() + Send + Sync>) -> Self {
        Self {
            cache,
            waker,
            running: None,
            waiting: None,
            next_tag: 0,
        }
    }

    /// Asks `work` about `scene` under `isolation`; returns the tag its answer will
    /// carry. Starts at once when idle, else waits for the running question (replacing
    /// any waiting one).
    pub fn ask(&mut self, scene: Arc<Scene>, isolation: Isolation, work: ProbeWork<T>) -> u64 {
        self.next_tag += 1;
        let tag = self.next_tag;
        self.waiting = Some(Question {
            tag,
            scene,
            isolation,
            work,
        });
        if self.running.is_none() {
            self.start_waiting();
        }
        tag
    }

    /// The answer of the running question once it is ready, `(tag, answer)`; then the
    /// waiting question, if any, starts.
    pub fn poll(&mut self) -> Option<(u64, Result<T, String>)> {
        let (tag, job) = self.running.as_ref()?;
        let outcome = job.try_result()?;
        let tag = *tag;
        self.running = None;
        self.start_waiting();
        Some((tag, outcome.and_then(|answer| answer)))
    }

    /// Whether a question is running or waiting.
    #[must_use]
    pub fn is_busy(&self) -> bool {
        self.running.is_some() || self.waiting.is_some()
    }

    fn start_waiting(&mut self) {
        let Some(Question {
            tag,
            scene,
            isolation,
            work,
        }) = self.waiting.take()
        else {
            return;
        };
        let cache = Arc::clone(&self.cache);
        let waker = Arc::clone(&self.waker);
        let job = BackgroundJob::spawn(
            "probe",
            move |_| Some(cache.world(&scene, &isolation).map(|world| work(&world))),
            move || waker(),
        );
        match job {
            Ok(job) => self.running = Some((tag, job)),
            // No thread: the question is dropped; the next poll has nothing to report.
            Err(_) => self.running = None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    fn wait<T: Send + 'static>(probe: &mut Probe<T>) -> (u64, Result<T, String>) {
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            if let Some(answer) = probe.poll() {
                return answer;
            }
            assert!(Instant::now() < deadline, "no answer");
            std::thread::sleep(Duration::from_millis(1));
        }
    }

    #[test]
    fn answers_come_back_tagged_and_the_world_is_kept_for_an_equal_scene() {
        let cache = Arc::new(WorldCache::default());
        let mut probe: Probe<usize> = Probe::new(Arc::clone(&cache), Arc::new(|| {}));
        let scene = Arc::new(crate::scene::examples::default_scene());
        let tag = probe.ask(
            Arc::clone(&scene),
            Isolation::NONE,
            Box::new(|world| world.objects.len()),
        );
        assert_eq!(wait(&mut probe), (tag, Ok(scene.objects.len())));
        assert!(!probe.is_busy());
        let first = cache.world(&scene, &Isolation::NONE).unwrap();
        let copy = Arc::new((*scene).clone());
        assert!(
            Arc::ptr_eq(&first, &cache.world(&copy, &Isolation::NONE).unwrap()),
            "kept"
        );

        let mut broken = (*scene).clone();
        broken.objects[0].material = "no such material".to_owned();
        let tag = probe.ask(
            Arc::new(broken),
            Isolation::NONE,
            Box::new(|world| world.objects.len()),
        );
        let (answered, result) = wait(&mut probe);
        assert_eq!(answered, tag);
        assert!(result.unwrap_err().contains("no such material"));
    }

    #[test]
    fn a_newer_question_replaces_the_waiting_one() {
        let cache = Arc::new(WorldCache::default());
        let mut probe: Probe<u32> = Probe::new(cache, Arc::new(|| {}));
        let scene = Arc::new(crate::scene::examples::default_scene());
        let (release, gate) = std::sync::mpsc::channel::<()>();
        let first = probe.ask(
            Arc::clone(&scene),
            Isolation::NONE,
            Box::new(move |_| {
                let _ = gate.recv();
                1
            }),
        );
        let _second = probe.ask(Arc::clone(&scene), Isolation::NONE, Box::new(|_| 2));
        let third = probe.ask(scene, Isolation::NONE, Box::new(|_| 3));
        release.send(()).unwrap();
        assert_eq!(wait(&mut probe), (first, Ok(1)));
        assert_eq!(wait(&mut probe), (third, Ok(3)), "the second was replaced");
        assert!(!probe.is_busy());
    }
}
