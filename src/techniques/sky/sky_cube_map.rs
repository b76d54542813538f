//! The sky rendered into a cube map (notes 03, Implementation: the skybox
//! cube map that the skybox pass draws and mirrors reflect; Sun Sky: the
//! Preetham model). A scene whose `[skybox]` has no faces, or whose
//! reflective materials mirror its `[sky]`, gets an RGBA16F cube map
//! (src/frame/environment.rs); this pass draws the sky into it once, when
//! the scene loads, and again only when the sky changes.
//!
//! For each of the six faces: bind the face's framebuffer, one full-screen
//! triangle whose fragment shader evaluates the sky (glsl/common/preetham.glsl)
//! along the direction through its texel (GL's face table, the twin of
//! src/math/cube_map.rs); then glGenerateMipmap for the chain.
//!
//! GL state: the viewport (the face's size; the passes after it set their
//! own); no depth test, no blending (the defaults). Restores the default
//! framebuffer and no program.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::Scene;
use crate::scene::skybox::Environment;
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;

pub const SKY_CUBE_MAP: Technique = Technique {
    name: "sky_cube_map",
    notes: "notes 03, Implementation (the skybox cube map); Sun Sky",
    file: file!(),
    shaders: &["common/fullscreen.vert", "sky/sky_cube_map.frag"],
    scene: "scenes/environment-reflection.toml",
    docs: "docs/sky/skybox.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::BeforeViews,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let (Some(Environment::Sky { size }), Some(sky)) = (scene.environment(), &scene.sky) else {
        return vec![];
    };
    let draws = format!(
        "6 faces x 1 full-screen triangle: the Preetham sky (turbidity {}) into a {size}x{size} RGBA16F cube map, then its mip chain; when the scene loads or the sky changes",
        sky.turbidity
    );
    vec![Pass::new("sky cube map", "environment", draws, file!()).without_depth()]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct SkyCubeMap {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(SkyCubeMap {
        program: p.build(&[
            (glow::VERTEX_SHADER, "common/fullscreen.vert"),
            (glow::FRAGMENT_SHADER, "sky/sky_cube_map.frag"),
        ])?,
    }))
}

impl RunPasses for SkyCubeMap {
    fn run(&self, _: &Pass, f: &Frame) {
        let environment = &f.draws.environment;
        // Drawn already for this sky: nothing to do.
        let Some((cube, sky)) = environment.sky_to_draw(f.scene) else {
            return;
        };
        let (gl, p) = (f.gl, &self.program);
        let uniforms = sky.model().uniforms();
        unsafe {
            p.use_program();
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            for (i, c) in uniforms.perez.iter().enumerate() {
                p.set_vec3(&format!("u_perez[{i}]"), Vec3::from(*c));
            }
            p.set_vec3("u_zenith", Vec3::from(uniforms.zenith));
            p.set_vec3("u_sun", Vec3::from(uniforms.sun));
            p.set_f32("u_sky_intensity", sky.intensity);
            p.set_f32("u_size", cube.size as f32);
            gl.viewport(0, 0, cube.size, cube.size);
            // 1. Each face: the sky along the direction through each texel.
            for (face, fb) in cube.faces.iter().enumerate() {
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(*fb));
                p.set_i32("u_face", face as i32);
                f.meshes.fullscreen.draw();
            }
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.use_program(None);
        }
        // 2. The mip chain, for the passes that minify it.
        cube.generate_mipmap();
        *environment.drawn_for.borrow_mut() = Some(sky);
    }
}
