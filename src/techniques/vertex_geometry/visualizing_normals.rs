//! Visualizing normal vectors (LearnOpenGL, 4.advanced_opengl "Geometry
//! Shader", the section of that name; beyond the notes, whose geometry
//! shader makes particles' quads, notes 01 §3.2). A debug view: after the
//! world is drawn, every opaque object is drawn again by a program whose
//! geometry shader takes each triangle and emits, for each of its three
//! vertices, a line from the vertex along its normal:
//!
//! 1. The vertex shader passes the vertex's world position and its normal,
//!    transformed by the normal matrix (notes 01 §8.1.1) and normalised.
//! 2. The geometry shader (`layout(triangles) in; layout(line_strip,
//!    max_vertices = 6) out;`) emits p and p + length x n for each vertex,
//!    then EndPrimitive: three lines a triangle.
//! 3. The fragment shader writes one flat colour.
//!
//! The lesson offsets in view space with its projection after; gloss works
//! in world space (the length is in world units, the same as the scene's)
//! and projects in the geometry shader. `render.normal_length` sets it.
//! `glsl/vertex_geometry/visualizing_normals.geom` writes each end's world
//! position to `g_world`, which the tests capture by transform feedback and
//! compare with the mesh on the CPU.
//!
//! GL state: depth test (GL_LEQUAL, no writes: the lines start on the
//! surfaces); restores no depth test, depth writes on, GL_LESS.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::{Scene, knobs};
use anyhow::Result;
use glam::Vec3;
use glow::HasContext;

pub const VISUALIZING_NORMALS: Technique = Technique {
    name: "visualizing_normals",
    notes: "LearnOpenGL, 4.advanced_opengl, Geometry Shader: Visualizing normal vectors (beyond the notes; notes 01 §3.2 has the geometry shader)",
    file: file!(),
    shaders: &[
        "vertex_geometry/visualizing_normals.vert",
        "vertex_geometry/visualizing_normals.geom",
        "vertex_geometry/visualizing_normals.frag",
    ],
    scene: "scenes/normals.toml",
    docs: "docs/vertex_geometry/visualizing_normals.md",
    knobs: &[&knobs::SHOW_NORMALS, &knobs::NORMAL_LENGTH],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The lines' colour (linear RGB).
pub const NORMAL_COLOR: Vec3 = Vec3::new(1.0, 1.0, 0.0);

/// The program's stages, for the tests that capture its lines.
pub const STAGES: [(u32, &str); 3] = [
    (
        glow::VERTEX_SHADER,
        "vertex_geometry/visualizing_normals.vert",
    ),
    (
        glow::GEOMETRY_SHADER,
        "vertex_geometry/visualizing_normals.geom",
    ),
    (
        glow::FRAGMENT_SHADER,
        "vertex_geometry/visualizing_normals.frag",
    ),
];

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let n = scene.opaque_objects();
    if !scene.render.show_normals || n == 0 {
        return vec![];
    }
    let draws = format!(
        "{n} objects, a geometry shader emits one line per vertex, {} long",
        scene.render.normal_length
    );
    vec![Pass::new("normals", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct VisualizingNormals {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(VisualizingNormals {
        program: p.build(&STAGES)?,
    }))
}

impl RunPasses for VisualizingNormals {
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, p, u) = (f.gl, &self.program, f.uniforms);
        let target = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LEQUAL);
            gl.depth_mask(false);
            // A reflected view: only inside its mirror's stencil region.
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            p.use_program();
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_f32("u_length", f.scene.render.normal_length);
            p.set_vec3("u_color", NORMAL_COLOR);
            p.set_bool("u_output_srgb", u.output_srgb);
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                p.set_mat4("u_model", &d.model);
                p.set_mat3("u_normal_matrix", &d.normal_matrix);
                f.draws.mesh(d).draw();
            }
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
