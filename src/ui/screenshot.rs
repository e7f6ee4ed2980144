//! The test hook behind `RAYLAB_SCREENSHOT=/path/out.png`: once the first
//! full-resolution preview frame is on screen, take a screenshot of the window, save it
//! as PNG, and let the app close.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use image::ImageEncoder as _;

use crate::scene::write_atomically;

/// Frames to wait after the frame is first shown, so it has surely been painted.
const SETTLE_FRAMES: u32 = 2;

type Outcome = Arc<Mutex<Option<Result<(), String>>>>;

/// Waits for a full frame, requests the screenshot, reports when it is saved.
pub struct ScreenshotHook {
    path: PathBuf,
    settled: u32,
    requested: Option<Outcome>,
}

impl ScreenshotHook {
    /// A hook that saves to `path`.
    #[must_use]
    pub fn new(path: PathBuf) -> Self {
        Self {
            path,
            settled: 0,
            requested: None,
        }
    }

    /// Call once per frame with whether the full-resolution frame is shown. Returns the
    /// outcome once the screenshot has been written (or failed).
    pub fn step(&mut self, ctx: &egui::Context, ready: bool) -> Option<Result<(), String>> {
        if let Some(outcome) = &self.requested {
            let done = outcome.lock().ok().and_then(|mut o| o.take());
            if done.is_none() {
                ctx.request_repaint_after(std::time::Duration::from_millis(50));
            }
            return done;
        }
        if !ready {
            return None;
        }
        self.settled += 1;
        ctx.request_repaint();
        if self.settled <= SETTLE_FRAMES {
            return None;
        }
        let outcome: Outcome = Arc::default();
        let slot = Arc::clone(&outcome);
        let path = self.path.clone();
        let repaint = ctx.clone();
        ctx.request_screenshot(move |image| {
            let result = save_png(&image, &path);
            if let Ok(mut slot) = slot.lock() {
                *slot = Some(result);
            }
            repaint.request_repaint();
        });
        self.requested = Some(outcome);
        None
    }
}

/// Writes an egui image (sRGB bytes, as on screen) to a PNG file.
fn save_png(image: &egui::ColorImage, path: &Path) -> Result<(), String> {
    let [width, height] = image.size;
    let rgba: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
    let mut bytes = Vec::new();
    image::codecs::png::PngEncoder::new(&mut bytes)
        .write_image(
            &rgba,
            width as u32,
            height as u32,
            image::ExtendedColorType::Rgba8,
        )
        .map_err(|e| e.to_string())?;
    write_atomically(path, &bytes).map_err(|e| format!("{}: {e}", path.display()))
}
