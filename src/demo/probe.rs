//! The pixel probe in the demo: a click in the 3D view (a press and a
//! release without a drag), or with "follow the pointer" ticked the pixel
//! under the pointer, picks a pixel of the frame; each frame the renderer's
//! probe (src/renderer/probe.rs, the same code as `gloss probe`) reads what
//! that pixel holds, and the panel shows it with a magnifier
//! (src/demo/panel/probe.rs). A click also writes the read-out to stdout
//! between "gloss: probe" and "gloss: probe end" (the window tests read
//! it there).

use super::Running;
use crate::scene::Camera;
use winit::dpi::PhysicalPosition;

/// How far (window pixels) a press may move before its release and still
/// be a click rather than a drag.
const CLICK_SLOP: f64 = 3.0;

impl Running {
    /// The frame's pixel (from the top left) under window position `c`:
    /// the view's rectangle holds the frame stretched over it (at 1/2 or
    /// 1/4 of its size with a render scale), rows counted from its bottom
    /// as the blit counts them.
    pub(super) fn frame_pixel(&self, c: PhysicalPosition<f64>) -> Option<(u32, u32)> {
        let [x, y, w, h] = self.view;
        let (fw, fh) = (self.renderer.width, self.renderer.height);
        let (cx, cy) = (c.x - f64::from(x), c.y - f64::from(y));
        if cx < 0.0 || cy < 0.0 || cx >= f64::from(w) || cy >= f64::from(h) || w < 1 || h < 1 {
            return None;
        }
        let px = ((cx + 0.5) * f64::from(fw) / f64::from(w)).floor() as i32;
        let from_bottom = ((f64::from(h) - cy - 0.5) * f64::from(fh) / f64::from(h)).floor() as i32;
        let py = fh - 1 - from_bottom;
        let inside = (0..fw).contains(&px) && (0..fh).contains(&py);
        inside.then_some((px as u32, py as u32))
    }

    /// A left press in the view: remember where, to tell a click from a drag.
    pub(super) fn pressed(&mut self) {
        self.pressed_at = self.cursor;
    }

    /// A left release: a click in the view probes the pixel under it.
    pub(super) fn released(&mut self) {
        let (Some(p), Some(c)) = (self.pressed_at.take(), self.cursor) else {
            return;
        };
        if (p.x - c.x).hypot(p.y - c.y) <= CLICK_SLOP
            && let Some(pixel) = self.frame_pixel(c)
        {
            self.probe_at = Some(pixel);
            self.probe_log = true;
        }
    }

    /// Probe the chosen pixel of the frame just rendered with `camera`.
    pub(super) fn update_probe(&mut self, camera: &Camera) -> Option<String> {
        if self.panel.probe_follow
            && self.in_view(self.cursor)
            && let Some(c) = self.cursor
            && let Some(pixel) = self.frame_pixel(c)
        {
            self.probe_at = Some(pixel);
        }
        let (x, y) = self.probe_at?;
        match self.renderer.probe(camera, x, y) {
            Ok(p) => {
                if std::mem::take(&mut self.probe_log) {
                    println!("gloss: probe\n{p}gloss: probe end");
                }
                self.probe = Some(p);
                None
            }
            // The frame shrank under the pixel: nothing to show.
            Err(e) => {
                self.probe_at = None;
                self.probe = None;
                Some(format!("{e:#}"))
            }
        }
    }
}
