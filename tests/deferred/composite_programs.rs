//! The composite (techniques/deferred/composite.rs) and the G-buffer pass
//! (techniques/deferred/gbuffer.rs) build each of their programs the first
//! time a frame needs it, and keep it: a new renderer has none of them, the
//! first frame links exactly one of each, the frames after it none, and a
//! setting that changes the output's format (the hardware sRGB encode off:
//! an RGBA8 output, the shader encodes) one more composite, once. Counted
//! by the GL programs alive (gloss::gl::live).

use crate::common;
use gloss::gl::live;
use gloss::gl::program::Sources;
use gloss::renderer::{Output, Renderer};
use gloss::scene::Scene;

fn programs() -> i64 {
    let counts = live::counts();
    (counts.iter().find(|(name, _)| *name == "programs"))
        .unwrap()
        .1
}

#[test]
fn the_composite_builds_a_program_when_a_frame_first_needs_it() {
    let ctx = common::context(common::backend());
    let mut scene: Scene = common::scene("deferred-shading.toml");
    scene.render.size = (32, 18);
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &scene,
        &Sources::Embedded,
        32,
        18,
        Output::Srgb8,
    )
    .unwrap();
    let made = programs();
    r.render(&scene.camera).unwrap();
    assert_eq!(
        programs(),
        made + 2,
        "the first frame links one G-buffer program and one composite"
    );
    r.render(&scene.camera).unwrap();
    assert_eq!(programs(), made + 2, "the second frame links none");
    let mut shader_encodes = scene.render.clone();
    shader_encodes.hardware_srgb = false;
    r.set_render_settings(shader_encodes).unwrap();
    r.render(&scene.camera).unwrap();
    assert_eq!(programs(), made + 3, "a new output format: one more");
    r.set_render_settings(scene.render.clone()).unwrap();
    r.render(&scene.camera).unwrap();
    r.render(&scene.camera).unwrap();
    assert_eq!(programs(), made + 3, "and back: none");
    ctx.debug
        .check(&ctx.gl, "the composite's programs")
        .unwrap();
}
