//! Overdraw: one more frame under a GL_SAMPLES_PASSED occlusion query, the
//! samples that passed the depth test over the frame's pixels. For a
//! forward frame that is the fragments shaded a pixel, which drawing
//! opaque objects front to back (notes 01 §6.2, `render.sort_opaque`) cuts;
//! a deferred frame adds one a pixel for each full-screen pass.

use crate::gl::Headless;
use crate::gl::query::SamplesQuery;
use crate::renderer::Renderer;
use crate::scene::Camera;
use anyhow::Result;

pub(super) fn fragments_per_pixel(
    ctx: &Headless,
    r: &mut Renderer,
    camera: &Camera,
) -> Result<f64> {
    let samples = SamplesQuery::new(&ctx.gl)?;
    samples.begin();
    r.render(camera)?;
    samples.end();
    let pixels = f64::from(r.width) * f64::from(r.height);
    Ok(samples.result() as f64 / pixels.max(1.0))
}
