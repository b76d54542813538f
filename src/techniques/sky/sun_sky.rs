//! The sun-sky pass (notes 03, "Sun Sky": "adds the sun-sky effect using
//! the Preetham model"; "Implementation": the skybox drawn with z = w and
//! glDepthFunc(GL_LEQUAL)).
//!
//! After the world's opaque passes, one full-screen triangle whose vertex
//! shader sets z = w, so that every fragment lands on the far plane (depth
//! 1). The depth test, GL_LEQUAL, passes only where nothing nearer was
//! drawn: the sky fills the background and costs nothing behind objects.
//! Each fragment evaluates the Preetham sky (glsl/common/preetham.glsl,
//! whose coefficients `Sky::uniforms` computes once on the CPU) in the
//! direction of its pixel's ray, taken from the view's inverse
//! view-projection (a planar mirror's reflection included, so mirrors
//! reflect the sky). Depth writes are off: the sky is at infinity.
//!
//! GL state: depth test on, GL_LEQUAL, depth writes off (and a mirror
//! view's stencil test); restores no depth test, GL_LESS, depth writes on,
//! no stencil test.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::sky::SUN_ANGULAR_RADIUS;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glam::Vec3;
use glow::HasContext;

pub const SUN_SKY: Technique = Technique {
    name: "sun_sky",
    notes: "notes 03, Sun Sky; Implementation (z = w, GL_LEQUAL)",
    file: file!(),
    shaders: &["sky/sun_sky.vert", "sky/sun_sky.frag"],
    scene: "scenes/sun-sky.toml",
    docs: "docs/sky/sun_sky.md",
    // Image-based lighting lights with this sky: its switch is shown here.
    knobs: &[&knobs::IBL],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    // A [skybox] draws the background instead (skybox.rs).
    let (Some(sky), None) = (&scene.sky, &scene.skybox) else {
        return vec![];
    };
    let disc = if sky.sun_disc > 0.0 {
        format!(" and the sun's disc (irradiance {})", sky.sun_disc)
    } else {
        String::new()
    };
    let draws = format!(
        "1 full-screen triangle at z = w, GL_LEQUAL, depth writes off: the Preetham sky (turbidity {}){disc} where nothing was drawn",
        sky.turbidity
    );
    vec![Pass::new("sun-sky", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct SunSky {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(SunSky {
        program: p.build(&[
            (glow::VERTEX_SHADER, "sky/sun_sky.vert"),
            (glow::FRAGMENT_SHADER, "sky/sun_sky.frag"),
        ])?,
    }))
}

impl RunPasses for SunSky {
    fn run(&self, _: &Pass, f: &Frame) {
        let Some(sky) = &f.scene.sky else { return };
        let (gl, p, u) = (f.gl, &self.program, f.uniforms);
        let output = f.targets.get(world_target(f.scene));
        let uniforms = sky.model().uniforms();
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

            p.use_program();
            let view_projection = u.view_projection * f.view.reflection;
            p.set_mat4("u_inverse_view_projection", &view_projection.inverse());
            for (i, c) in uniforms.perez.iter().enumerate() {
                p.set_vec3(&format!("u_perez[{i}]"), Vec3::from(*c));
            }
            p.set_vec3("u_zenith", Vec3::from(uniforms.zenith));
            p.set_vec3("u_sun", Vec3::from(uniforms.sun));
            p.set_f32("u_sky_intensity", sky.intensity);
            // The sun's own disc, which the bloom spreads (0: none).
            p.set_vec3("u_sun_disc", sky.sun_disc_radiance());
            p.set_vec3("u_sun_direction", sky.sun);
            p.set_f32("u_sun_cos_radius", SUN_ANGULAR_RADIUS.cos() as f32);
            p.set_bool("u_output_srgb", u.output_srgb);
            f.meshes.fullscreen.draw();

            // Restore the state this pass changed.
            gl.use_program(None);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
