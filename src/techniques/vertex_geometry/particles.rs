//! Generation with the geometry shader (notes 01 §3.2, "Generation (Geometry
//! Shader)"): "a basic graphical particle system in which points are sent
//! to the GPU pipeline and are converted into quads by the geometry shader.
//! This saves (~75%) CPU time copying primitives to the GPU."
//!
//! Each frame the particles alive at the scene's time are computed on the
//! CPU (src/frame/particles.rs) and sent to the GPU, in one of two forms
//! (`[particles] expand`):
//!
//! - `"geometry_shader"`: one point a particle (16 bytes); the geometry
//!   shader (glsl/vertex_geometry/particles.geom) emits a camera-facing quad,
//!   a triangle strip of 4 vertices, for each;
//! - `"cpu"`: the quads built on the CPU, two triangles a particle (144
//!   bytes), drawn by a plain vertex shader. The same image: the
//!   comparison the notes' claim is about.
//!
//! The buffer is rewritten every frame through a mapped pointer or with
//! glBufferSubData (`stream`, src/gl/stream.rs). `gloss bench --particles`
//! measures bytes, CPU time and frame time for every combination.
//!
//! GL state: additive (glBlendFunc(GL_ONE, GL_ONE), depth test on, depth
//! writes off), or alpha-tested discs (depth writes on, no blending);
//! restores no blending, depth writes on, no depth test.

use crate::frame::lights::FrameLights;
use crate::frame::particles::{self, Particle};
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::gl::stream::{StreamBuffer, Upload};
use crate::scene::Scene;
use crate::scene::particles::{ParticleBlend, Particles};
use anyhow::Result;
use glow::HasContext;
use std::cell::{Cell, RefCell};

pub const PARTICLES: Technique = Technique {
    name: "particles",
    notes: "notes 01 §3.2, Generation (Geometry Shader)",
    file: file!(),
    shaders: &[
        "vertex_geometry/particles.vert",
        "vertex_geometry/particles.geom",
        "vertex_geometry/particles.frag",
        "vertex_geometry/particles_quads.vert",
    ],
    scene: "scenes/particles.toml",
    docs: "docs/vertex_geometry/particles.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let Some(p) = &scene.particles else {
        return vec![];
    };
    let living = particles::alive_range(p, scene.animation.time);
    let n = (living.end - living.start) as usize;
    let (form, bytes) = if p.geometry_shader {
        (
            "points made quads by the geometry shader",
            particles::POINT_BYTES,
        )
    } else {
        ("quads built on the CPU", particles::QUAD_BYTES)
    };
    let draws = format!(
        "{n} particles, {form}, {} KiB streamed by {} ({})",
        n * bytes / 1024,
        if p.map {
            "glMapBufferRange"
        } else {
            "glBufferSubData"
        },
        match p.blend {
            ParticleBlend::Additive => "additive",
            ParticleBlend::AlphaTest => "alpha test",
        }
    );
    vec![Pass::new("particles", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ParticlePass {
    points: Program,
    quads: Program,
    point_buffer: StreamBuffer,
    quad_buffer: StreamBuffer,
    /// The bytes of the last frame, reused.
    bytes: RefCell<Vec<u8>>,
    /// Whether a refused map was already reported.
    map_refused: Cell<bool>,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let points = p.build(&[
        (glow::VERTEX_SHADER, "vertex_geometry/particles.vert"),
        (glow::GEOMETRY_SHADER, "vertex_geometry/particles.geom"),
        (glow::FRAGMENT_SHADER, "vertex_geometry/particles.frag"),
    ])?;
    let quads = p.build(&[
        (glow::VERTEX_SHADER, "vertex_geometry/particles_quads.vert"),
        (glow::FRAGMENT_SHADER, "vertex_geometry/particles.frag"),
    ])?;
    Ok(Box::new(ParticlePass {
        points,
        quads,
        point_buffer: StreamBuffer::new(p.gl, &[(0, 4, 0)], 16)?,
        quad_buffer: StreamBuffer::new(p.gl, &[(0, 3, 0), (1, 2, 12), (2, 1, 20)], 24)?,
        bytes: RefCell::new(Vec::new()),
        map_refused: Cell::new(false),
    }))
}

/// Fill `out` with what the GPU gets for `alive` in `p`'s form.
pub fn pack(p: &Particles, alive: &[Particle], view: &glam::Mat4, out: &mut Vec<u8>) {
    if p.geometry_shader {
        particles::pack_points(alive, out);
    } else {
        particles::pack_quads(alive, view, p.size, out);
    }
}

impl RunPasses for ParticlePass {
    fn run(&self, _: &Pass, f: &Frame) {
        let Some(ps) = &f.scene.particles else {
            return;
        };
        let (gl, u) = (f.gl, f.uniforms);
        let view = u.view * f.view.reflection;
        let alive = particles::alive(ps, f.scene.animation.time);
        let mut bytes = self.bytes.borrow_mut();
        pack(ps, &alive, &view, &mut bytes);
        let (buffer, program, mode, count) = if ps.geometry_shader {
            (&self.point_buffer, &self.points, glow::POINTS, alive.len())
        } else {
            (
                &self.quad_buffer,
                &self.quads,
                glow::TRIANGLES,
                alive.len() * 6,
            )
        };
        // Notes 01 §1.3: through a mapped pointer, or glBufferSubData; a
        // refused map is written the second way and said, once.
        if buffer.write(&bytes, ps.map) == Upload::MapRefused && !self.map_refused.replace(true) {
            eprintln!(
                "gloss: warning: particles: glMapBufferRange refused the {}-byte buffer; written with glBufferSubData instead (particles.map = true has no effect on this GL)",
                bytes.len()
            );
        }
        let target = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            match ps.blend {
                ParticleBlend::Additive => {
                    gl.depth_mask(false);
                    gl.enable(glow::BLEND);
                    gl.blend_func(glow::ONE, glow::ONE);
                }
                ParticleBlend::AlphaTest => gl.depth_mask(true),
            }
            program.use_program();
            program.set_mat4("u_view_projection", &(u.projection * view));
            program.set_mat4("u_view", &view);
            program.set_f32("u_size", ps.size);
            program.set_vec3("u_color", ps.color);
            program.set_bool("u_alpha_test", ps.blend == ParticleBlend::AlphaTest);
            program.set_bool("u_output_srgb", u.output_srgb);
            buffer.draw(mode, count as i32);

            gl.use_program(None);
            gl.disable(glow::BLEND);
            gl.depth_mask(true);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
