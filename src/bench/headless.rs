//! The renderer a bench measures: on the headless context, with the shaders
//! built into the binary, at the size asked (the scene's, or `--size`).

use crate::gl::Headless;
use crate::gl::program::Sources;
use crate::renderer::Renderer;
use crate::scene::Scene;
use anyhow::Result;

pub fn renderer(ctx: &Headless, scene: &Scene, (w, h): (u32, u32)) -> Result<Renderer> {
    Renderer::new(
        &ctx.gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
    )
}
