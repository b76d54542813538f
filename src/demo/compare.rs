//! "Compare with reference": the current frame against forward rendering,
//! the reference every other path is measured against, drawn with the same
//! camera at the same size. The panel shows the RMSE and the largest
//! difference in 8-bit steps; the inspector shows the difference image
//! (8x, as the tests' difference images).

use crate::gl::Gl;
use crate::gl::debug::DebugLog;
use crate::gl::program::Sources;
use crate::gl::texture::{Sampling, Texture};
use crate::image_compare::{Metrics, compare_rgba8, diff_image};
use crate::renderer::Renderer;
use crate::scene::{Camera, RenderPath};
use anyhow::Result;

pub struct Comparison {
    pub metrics: Metrics,
    /// |frame - reference| x 8, bottom row first as GL textures are.
    pub difference: Texture,
    /// What was compared, for the panel.
    pub what: String,
}

/// Render the forward reference of `renderer`'s scene from `camera` and
/// compare the renderer's last frame with it.
pub fn compare(
    gl: &Gl,
    debug: &DebugLog,
    sources: &Sources,
    renderer: &Renderer,
    camera: &Camera,
) -> Result<Comparison> {
    let mut scene = renderer.scene.clone();
    scene.render.path = RenderPath::Forward;
    let mut reference = Renderer::new(gl, debug, &scene, sources, renderer.width, renderer.height)?;
    reference.render(camera)?;
    let (frame, forward) = (renderer.read_image(), reference.read_image());
    let metrics = compare_rgba8(&frame, &forward, 1.0 / 255.0)?;
    let diff = image::imageops::flip_vertical(&diff_image(&frame, &forward));
    let difference = Texture::from_rgba8(
        gl,
        diff.width(),
        diff.height(),
        diff.as_raw(),
        false,
        Sampling::NEAREST_CLAMP,
    )?;
    let what = format!(
        "{} against forward, {}x{}",
        renderer.scene.render.path, renderer.width, renderer.height
    );
    Ok(Comparison {
        metrics,
        difference,
        what,
    })
}
