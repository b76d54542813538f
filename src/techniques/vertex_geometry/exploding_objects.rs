//! Exploding objects (LearnOpenGL, 4.advanced_opengl "Geometry Shader", the
//! section of that name; beyond the notes, whose geometry shader makes
//! particles' quads, notes 01 §3.2). The opaque world drawn as forward's
//! Phong pass draws it, with a geometry shader between the vertex and the
//! fragment shader that moves every triangle along its face normal:
//!
//! 1. The vertex shader passes each vertex on in world space (position,
//!    normal, uv, colour, tangent: what forward.vert computes).
//! 2. The geometry shader (`layout(triangles) in; layout(triangle_strip,
//!    max_vertices = 3) out;`) takes the face normal
//!    N = normalize((p1 - p0) x (p2 - p0)) (the lesson's GetNormal) and
//!    emits the three vertices moved by N x magnitude x (sin(t) + 1) / 2
//!    (its explode), t the scene's time, projected.
//! 3. The fragment shader is forward's (lighting/forward.frag): the pieces
//!    are lit where they have flown to, with their own vertex normals.
//!
//! The lesson works on gl_Position (clip space); gloss works in world space,
//! so the magnitude is in the scene's units and the normal is the face's
//! true outward normal. `render.explode` switches it, `render.explode_magnitude`
//! sets the magnitude; the forward pass skips the objects this pass draws
//! (`RenderSettings::explodes`). Shadow maps see the objects whole.
//!
//! GL state: as forward's pass without its clear: depth test
//! (render.depth_func) and writes, culling per material, glFrontFace per
//! object, the stencil test and GL_CLIP_DISTANCE0 for a reflected view, the
//! scene's clip planes; restores GL_LESS, no depth test, no culling, GL_CCW,
//! no stencil test, no clip distance, unit 0 active with nothing bound.

use crate::frame::draw_list::DrawList;
use crate::frame::environment::Environment;
use crate::frame::forward_pass;
use crate::frame::image_based_lighting;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::texturing::Interpolation;
use crate::scene::{Parallax, Scene, knobs};
use anyhow::Result;
use glow::HasContext;

pub const EXPLODING_OBJECTS: Technique = Technique {
    name: "exploding_objects",
    notes: "LearnOpenGL, 4.advanced_opengl, Geometry Shader: Exploding objects (beyond the notes; notes 01 §3.2 has the geometry shader)",
    file: file!(),
    shaders: &[
        "vertex_geometry/exploding_objects.vert",
        "vertex_geometry/exploding_objects.geom",
        "lighting/forward.frag",
    ],
    scene: "scenes/explode.toml",
    docs: "docs/vertex_geometry/exploding_objects.md",
    knobs: &[&knobs::EXPLODE, &knobs::EXPLODE_MAGNITUDE],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The program's stages, for the tests that capture its triangles.
pub const STAGES: [(u32, &str); 3] = [
    (
        glow::VERTEX_SHADER,
        "vertex_geometry/exploding_objects.vert",
    ),
    (
        glow::GEOMETRY_SHADER,
        "vertex_geometry/exploding_objects.geom",
    ),
    (glow::FRAGMENT_SHADER, "lighting/forward.frag"),
];

/// The distance a triangle moves along its face normal at time `t`
/// (seconds): the lesson's magnitude x (sin(t) + 1) / 2.
pub fn offset(magnitude: f32, t: f32) -> f32 {
    magnitude * (t.sin() + 1.0) / 2.0
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    let n = scene.opaque_objects();
    if !scene.render.explodes() || n == 0 {
        return vec![];
    }
    let r = &scene.render;
    let draws = format!(
        "{n} objects x {} lights (Phong), every triangle moved {:.3} along its face normal (magnitude {} at t = {:.2} s)",
        scene.lights.len(),
        offset(r.explode_magnitude, scene.animation.time),
        r.explode_magnitude,
        scene.animation.time
    );
    let pass = Pass::new("explode", world_target(scene), draws, file!());
    vec![pass.with_variant(LightingVariant::of(scene, lights).describe())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ExplodingObjects {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build_variant(&STAGES)?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    Ok(Box::new(ExplodingObjects { program }))
}

impl RunPasses for ExplodingObjects {
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, settings, u, p) = (f.gl, &f.scene.render, f.uniforms, &self.program);
        let target = f.targets.get(world_target(f.scene));
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(settings.depth_func.gl());
            gl.depth_mask(true);
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if settings.wireframe {
                gl.polygon_mode(glow::FRONT_AND_BACK, glow::LINE);
            }
            forward_pass::enable_clip_distances(f);

            // shader.use() with forward's uniforms, for its fragment shader;
            // then the lesson's uniform: time (and gloss's magnitude).
            forward_pass::use_with_frame_uniforms(f, p);
            p.set_i32("u_light_map", unit::LIGHT_MAP as i32);
            p.set_f32("u_time", f.scene.animation.time);
            p.set_f32("u_magnitude", settings.explode_magnitude);
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            f.draws.environment.bind(gl, p);
            image_based_lighting::bind(gl, p, f.draws.environment.ibl.as_ref());
            let affine = settings.interpolation == Interpolation::Affine;
            p.set_bool("u_affine", affine);
            f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            let mut depth_func = settings.depth_func;
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                // Height-mapped objects: the parallax pass draws them (on
                // this path with Phong shading, whenever render.parallax is on).
                if d.height_map.is_some() && settings.parallax != Parallax::Off {
                    continue;
                }
                match d.cull.gl() {
                    Some(face) => {
                        gl.enable(glow::CULL_FACE);
                        gl.cull_face(face);
                    }
                    None => gl.disable(glow::CULL_FACE),
                }
                let func = d.depth_func.unwrap_or(settings.depth_func);
                if func != depth_func {
                    gl.depth_func(func.gl());
                    depth_func = func;
                }
                gl.front_face(f.view.front_face(d.mirrored));
                f.draws.bind_textures(gl, p, d, settings);
                f.draws.set_object_uniforms(p, d);
                f.draws.mesh(d).draw();
            }

            // Restore the state this pass changed.
            gl.polygon_mode(glow::FRONT_AND_BACK, glow::FILL);
            forward_pass::disable_clip_distances(f);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.front_face(glow::CCW);
            DrawList::unbind_textures(gl);
            Environment::unbind(gl);
            image_based_lighting::unbind(gl, f.draws.environment.ibl.as_ref());
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.active_texture(glow::TEXTURE0);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, None);
            f.shadows.unbind(gl);
            gl.use_program(None);
            gl.cull_face(glow::BACK);
            gl.disable(glow::CULL_FACE);
            gl.disable(glow::DEPTH_TEST);
            gl.depth_func(glow::LESS);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
