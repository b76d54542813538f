//! Instancing (LearnOpenGL, 4.advanced_opengl "Instancing": instanced
//! arrays and the asteroid field; beyond the notes). Many copies of one mesh,
//! each with its own model matrix, in one draw call. The lesson's steps:
//!
//! 1. Compute every rock's model matrix on the CPU, once
//!    (`crate::scene::instancing::Instancing::models`).
//! 2. Put them in a vertex buffer: glGenBuffers, glBindBuffer(GL_ARRAY_BUFFER),
//!    glBufferData(count x sizeof(mat4), GL_STATIC_DRAW).
//! 3. With the rock's VAO bound, a mat4 attribute is four vec4 attributes:
//!    for each column glEnableVertexAttribArray, glVertexAttribPointer(loc,
//!    4, GL_FLOAT, GL_FALSE, sizeof(mat4), column x sizeof(vec4)) and
//!    glVertexAttribDivisor(loc, 1): the attribute advances once per
//!    instance instead of once per vertex. Locations 5-8 here (the lesson's
//!    3-6 hold gloss meshes' tangents and colours).
//! 4. Draw: glDrawElementsInstanced(GL_TRIANGLES, indices, GL_UNSIGNED_INT,
//!    0, count).
//!
//! `render.instancing = false` draws the lesson's first version instead:
//! glUniformMatrix4fv(u_model) and glDrawElements for each rock, the same
//! image with one draw call and 64 bytes of uniforms per rock every frame
//! (`gloss bench --instancing` measures both).
//!
//! The rocks are opaque and drawn into the world target after the opaque
//! world of every path (its depth is there in each), before the sky fills
//! what is left. They are lit by Lambert from the scene's first directional
//! light (none: straight down) plus the ambient term: the lesson is about
//! the draw, not the light loop.
//!
//! GL state: depth test (GL_LESS) with writes, back-face culling; restores
//! no depth test, no culling.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::Gl;
use crate::gl::live::{self, Kind};
use crate::gl::mesh::Mesh;
use crate::gl::program::Program;
use crate::scene::instancing::Instancing;
use crate::scene::{LightKind, Scene, knobs};
use anyhow::Result;
use glam::{Mat4, Vec3};
use glow::HasContext;
use std::cell::{Cell, RefCell};
use std::time::Instant;

pub const INSTANCING: Technique = Technique {
    name: "instancing",
    notes: "LearnOpenGL, 4.advanced_opengl, Instancing: instanced arrays, the asteroid field (beyond the notes)",
    file: file!(),
    shaders: &[
        "vertex_geometry/instancing.vert",
        "vertex_geometry/instancing.frag",
    ],
    scene: "scenes/instancing.toml",
    docs: "docs/vertex_geometry/instancing.md",
    knobs: &[&knobs::INSTANCING],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The first attribute location of the instanced mat4 (four in a row).
pub const MODEL_LOCATION: u32 = 5;

thread_local! {
    static LAST_SUBMIT_MS: Cell<f64> = const { Cell::new(0.0) };
}

/// The CPU time the last instancing pass on this thread took to issue the
/// rocks' calls (from binding the VAO to the last draw returning, no
/// glFinish): what `gloss bench --instancing` reports as CPU time.
pub fn last_submit_ms() -> f64 {
    LAST_SUBMIT_MS.with(Cell::get)
}

/// The bytes the CPU sends for the rocks' transforms each frame: none when
/// instanced (the buffer was filled once), a mat4 uniform per rock otherwise.
pub fn bytes_per_frame(field: &Instancing, instanced: bool) -> usize {
    if instanced {
        0
    } else {
        field.count as usize * std::mem::size_of::<Mat4>()
    }
}

fn passes(scene: &Scene, _: &FrameLights) -> Vec<Pass> {
    let Some(field) = &scene.instancing else {
        return vec![];
    };
    let n = field.count;
    let draws = if scene.render.instancing {
        format!("{n} rocks in one glDrawElementsInstanced, model matrices in an instanced array")
    } else {
        format!("{n} rocks, one glUniformMatrix4fv + glDrawElements each")
    };
    vec![Pass::new("instancing", world_target(scene), draws, file!())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

/// The rock on the GPU with the field's instanced array in its VAO.
struct Field {
    of: Instancing,
    rock: Mesh,
    instances: glow::Buffer,
    models: Vec<Mat4>,
    gl: Gl,
}

impl Drop for Field {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_buffer(self.instances);
        }
        live::freed(Kind::Buffer);
    }
}

struct InstancingPass {
    instanced: Program,
    per_rock: Program,
    gl: Gl,
    /// Made on the first frame that draws the field, again when it changes.
    field: RefCell<Option<Field>>,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let stages = [
        (glow::VERTEX_SHADER, "vertex_geometry/instancing.vert"),
        (glow::FRAGMENT_SHADER, "vertex_geometry/instancing.frag"),
    ];
    Ok(Box::new(InstancingPass {
        instanced: p.build_with(&stages, &[("INSTANCED", "1".into())])?,
        per_rock: p.build(&stages)?,
        gl: p.gl.clone(),
        field: RefCell::new(None),
    }))
}

/// Steps 1-3: the rock, its model matrices and the instanced array.
fn make_field(gl: &Gl, of: &Instancing) -> Result<Field> {
    let rock = Mesh::upload(gl, &crate::geometry::rock())?;
    // 1. The model matrices.
    let models = of.models();
    let bytes: &[u8] = bytemuck_mat4(&models);
    unsafe {
        // 2. The instanced array's buffer.
        let instances = live::new_buffer(gl)?;
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(instances));
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytes, glow::STATIC_DRAW);
        // 3. A mat4 attribute: four vec4 columns, each advancing per instance.
        gl.bind_vertex_array(Some(rock.vao));
        let stride = std::mem::size_of::<Mat4>() as i32;
        for column in 0..4u32 {
            let loc = MODEL_LOCATION + column;
            gl.enable_vertex_attrib_array(loc);
            let offset = (column as usize * std::mem::size_of::<glam::Vec4>()) as i32;
            gl.vertex_attrib_pointer_f32(loc, 4, glow::FLOAT, false, stride, offset);
            gl.vertex_attrib_divisor(loc, 1);
        }
        gl.bind_vertex_array(None);
        gl.bind_buffer(glow::ARRAY_BUFFER, None);
        Ok(Field {
            of: of.clone(),
            rock,
            instances,
            models,
            gl: gl.clone(),
        })
    }
}

/// The matrices as the bytes glBufferData sends (column-major f32s).
fn bytemuck_mat4(m: &[Mat4]) -> &[u8] {
    // Mat4 is 16 f32s, column-major, with no padding.
    unsafe { std::slice::from_raw_parts(m.as_ptr() as *const u8, std::mem::size_of_val(m)) }
}

/// The light the rocks are lit by: the first directional light (towards
/// it, and its radiance), or white from straight above.
fn light(scene: &Scene) -> (Vec3, Vec3) {
    (scene.lights.iter())
        .find(|l| l.kind == LightKind::Directional)
        .map_or((Vec3::Y, Vec3::ONE), |l| (-l.direction, l.radiance()))
}

impl RunPasses for InstancingPass {
    fn run(&self, _: &Pass, f: &Frame) {
        let Some(of) = &f.scene.instancing else {
            return;
        };
        let mut field = self.field.borrow_mut();
        if field.as_ref().is_none_or(|x| &x.of != of) {
            *field = None;
            match make_field(&self.gl, of) {
                Ok(made) => *field = Some(made),
                Err(e) => {
                    eprintln!("gloss: warning: instancing: the rocks are not drawn: {e:#}");
                    return;
                }
            }
        }
        let field = field.as_ref().expect("made above");
        let (gl, u) = (f.gl, f.uniforms);
        let instanced = f.scene.render.instancing;
        let p = if instanced {
            &self.instanced
        } else {
            &self.per_rock
        };
        let target = f.targets.get(world_target(f.scene));
        let (to_light, radiance) = light(f.scene);
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.depth_mask(true);
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            gl.front_face(f.view.front_face(false));
            // A reflected view: only inside its mirror's stencil region.
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }
            p.use_program();
            f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_vec3("u_color", of.color);
            p.set_vec3("u_ambient", f.scene.render.ambient);
            p.set_vec3("u_to_light", to_light.normalize_or_zero());
            p.set_vec3("u_radiance", radiance);
            p.set_bool("u_output_srgb", u.output_srgb);
            let mesh = &field.rock;
            crate::gl::debug::check_feedback_before_draw(gl);
            let start = Instant::now();
            gl.bind_vertex_array(Some(mesh.vao));
            if instanced {
                // 4. Every rock in one call.
                gl.draw_elements_instanced(
                    glow::TRIANGLES,
                    mesh.index_count,
                    glow::UNSIGNED_INT,
                    0,
                    of.count as i32,
                );
            } else {
                // The lesson's first version: a uniform and a draw per rock.
                for m in &field.models {
                    p.set_mat4("u_model", m);
                    gl.draw_elements(glow::TRIANGLES, mesh.index_count, glow::UNSIGNED_INT, 0);
                }
            }
            gl.bind_vertex_array(None);
            LAST_SUBMIT_MS.with(|c| c.set(start.elapsed().as_secs_f64() * 1e3));

            gl.use_program(None);
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.front_face(glow::CCW);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
