//! The skybox pass (notes 03, Implementation: "a separate 'skybox pass' is
//! added to draw the skybox images. To optimize the performance, the depth
//! value z for a pixel is always set to w (which is 1) in the skybox vertex
//! shader such that the skybox pixel will not be drawn if there are
//! anything in front of it. The depth test is enabled and GL_LEQUAL is set
//! for depth function before the rendering.").
//!
//! After the world's opaque passes, one full-screen triangle at z = w: every
//! fragment lands on the far plane (depth 1) and GL_LEQUAL passes only where
//! nothing nearer was drawn. Each fragment samples the environment cube map
//! (src/frame/environment.rs: the `[skybox]` faces, or the `[sky]` rendered
//! into one by sky_cube_map.rs) along its pixel's view ray, taken from the
//! view's inverse view-projection (a planar mirror's reflection included).
//! With a `[skybox]` this pass draws the background and the per-pixel
//! sun-sky pass (sun_sky.rs) does not run. `render.sky_first` draws it
//! before the world instead (sky_first.rs), to measure what z = w saves.
//!
//! GL state: depth test on, GL_LEQUAL, depth writes off,
//! GL_TEXTURE_CUBE_MAP_SEAMLESS on, the cube map on unit::ENVIRONMENT (and
//! a mirror view's stencil test); restores no depth test, GL_LESS, depth
//! writes on, no seamless filtering, no cube map, no stencil test.

use crate::frame::environment::Environment;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::skybox::Environment as Source;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glow::HasContext;

pub const SKYBOX: Technique = Technique {
    name: "skybox",
    notes: "notes 03, Implementation (skybox pass, z = w, GL_LEQUAL)",
    file: file!(),
    shaders: &["sky/skybox.vert", "sky/skybox.frag"],
    scene: "scenes/skybox.toml",
    docs: "docs/sky/skybox.md",
    // And the switch of image-based lighting, which lights with the skybox.
    knobs: &[&knobs::SKY_FIRST, &knobs::IBL],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// What the skybox pass draws, in words (sky_first.rs says it too).
pub(super) fn describe(scene: &Scene) -> String {
    match &scene.skybox {
        Some(Source::Faces(_)) => "the skybox's six faces".into(),
        Some(Source::Sky { size }) => format!("the [sky] in a {size}x{size} cube map"),
        None => "nothing".into(),
    }
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    if scene.skybox.is_none() || scene.sky_first() {
        return vec![];
    }
    let draws = format!(
        "1 full-screen triangle at z = w, GL_LEQUAL, depth writes off: {} where nothing was drawn",
        describe(scene)
    );
    vec![Pass::new("skybox", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Skybox {
    program: Program,
}

/// The skybox's program (sky_first.rs draws with it too).
pub(super) fn program(p: &Programs) -> Result<Program> {
    p.build(&[
        (glow::VERTEX_SHADER, "sky/skybox.vert"),
        (glow::FRAGMENT_SHADER, "sky/skybox.frag"),
    ])
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Skybox {
        program: program(p)?,
    }))
}

/// One full-screen triangle at z = w sampling the cube map along each
/// pixel's view ray, into the bound target with the depth state as set.
pub(super) fn draw(p: &Program, f: &Frame) {
    let (gl, u) = (f.gl, f.uniforms);
    unsafe {
        gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
        p.use_program();
        let view_projection = u.view_projection * f.view.reflection;
        p.set_mat4("u_inverse_view_projection", &view_projection.inverse());
        p.set_bool("u_output_srgb", u.output_srgb);
        f.draws.environment.bind(gl, p);
        f.meshes.fullscreen.draw();
        Environment::unbind(gl);
        gl.use_program(None);
        gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
    }
}

impl RunPasses for Skybox {
    fn run(&self, _: &Pass, f: &Frame) {
        let gl = f.gl;
        let output = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            let (x, y, w, h) = f.view.rect(output.width, output.height);
            gl.viewport(x, y, w, h);
            // Only where nothing nearer than the far plane was drawn.
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LEQUAL);
            gl.depth_mask(false);
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            draw(&self.program, f);

            // Restore the state this pass changed.
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
