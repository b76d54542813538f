//! Forward rendering (notes 04, "Forward rendering"; notes 01 §8.2 "Lighting
//! Models" and §8.3 "Phong Reflection Model").
//!
//! ```text
//! for every object in the scene
//!     for every fragment of that object
//!         for every light: calculate shading
//! ```
//!
//! Three shading modes from notes 01 §8.2: flat (one colour per triangle,
//! lit in a geometry shader), Gouraud (lit per vertex) and Phong (lit per
//! fragment). This is the reference every deferred path is compared against.
//!
//! For a reflected view (notes 05, stencil/mirror.rs) the same pass draws
//! the world reflected: without clearing, inside the mirror's stencil
//! region, with a clip plane and the winding flipped (src/frame/views.rs).
//!
//! GL state: sets glDepthFunc(render.depth_func, or the material's
//! depth_func per object where it differs), depth writes, back-face
//! culling, glFrontFace per object, and for a reflected view the stencil
//! test and GL_CLIP_DISTANCE0; restores GL_LESS, no depth test, no culling,
//! GL_CCW, no stencil test, no clip distance.

use crate::frame::draw_list::DrawList;
use crate::frame::environment::Environment;
use crate::frame::forward_pass;
use crate::frame::image_based_lighting;
use crate::frame::lights::FrameLights;
use crate::frame::ltc_area_lights;
use crate::frame::plan::Pass;
use crate::frame::plan_programs::PlanProgram;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::texturing::Interpolation;
use crate::scene::{RenderPath, Scene, Shading};
use anyhow::Result;
use glow::HasContext;

pub const FORWARD: Technique = Technique {
    name: "forward",
    notes: "notes 04, Forward rendering; notes 01 §8.2-8.3",
    file: file!(),
    shaders: &[
        "lighting/forward.vert",
        "lighting/forward.frag",
        "lighting/forward_gouraud.vert",
        "lighting/forward_gouraud.frag",
        "lighting/forward_flat.vert",
        "lighting/forward_flat.geom",
        "lighting/forward_flat.frag",
    ],
    scene: "scenes/shading-phong.toml",
    docs: "docs/lighting/forward.md",
    knobs: &[
        &knobs::SHADING,
        &knobs::WIREFRAME,
        // Texture mapping (notes 01 §5): every geometry pass reads these.
        &knobs::TEXTURE_FILTER,
        &knobs::INTERPOLATION,
        &knobs::MIP_COLORS,
        // Bump mapping (notes 01 §8.4), forward and into the G-buffer.
        &knobs::NORMAL_MAPPING,
        // Static lighting (notes 01 §8.2).
        &knobs::LIGHT_MAPS,
        &knobs::DEPTH_FUNC,
        &knobs::AMBIENT,
        &knobs::BACKGROUND,
        // MSAA is for the forward path (fragment_tests/msaa.rs): offered here.
        &knobs::MSAA,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if scene.render.path != RenderPath::Forward {
        return vec![];
    }
    let mode = match scene.render.shading {
        Shading::Phong => "Phong shading, per fragment",
        Shading::Gouraud => "Gouraud shading, per vertex",
        Shading::Flat => "flat shading, per triangle in a geometry shader",
    };
    let draws = format!(
        "{} objects x {} lights ({mode})",
        scene.opaque_objects(),
        scene.lights.len()
    );
    let pass = Pass::new("forward", world_target(scene), draws, file!());
    // Every shading mode's program is specialised to the frame (src/frame/variant.rs).
    // Its program is the shading mode's, built with the variant's defines.
    let variant = LightingVariant::of(scene, lights);
    let role = match scene.render.shading {
        Shading::Phong => "Phong",
        Shading::Gouraud => "Gouraud",
        Shading::Flat => "flat",
    };
    vec![
        pass.with_variant(variant.describe())
            .with_programs(vec![PlanProgram::new(role, variant.defines())]),
    ]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct Forward {
    phong: Program,
    gouraud: Program,
    flat: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let phong = p.build_variant(&[
        (glow::VERTEX_SHADER, "lighting/forward.vert"),
        (glow::FRAGMENT_SHADER, "lighting/forward.frag"),
    ])?;
    let gouraud = p.build_variant(&[
        (glow::VERTEX_SHADER, "lighting/forward_gouraud.vert"),
        (glow::FRAGMENT_SHADER, "lighting/forward_gouraud.frag"),
    ])?;
    let flat = p.build_variant(&[
        (glow::VERTEX_SHADER, "lighting/forward_flat.vert"),
        (glow::GEOMETRY_SHADER, "lighting/forward_flat.geom"),
        (glow::FRAGMENT_SHADER, "lighting/forward_flat.frag"),
    ])?;
    for program in [&phong, &gouraud, &flat] {
        program.bind_uniform_block("Lights", LIGHTS_BINDING);
        shadows::setup_program(program);
    }
    Ok(Box::new(Forward {
        phong,
        gouraud,
        flat,
    }))
}

impl RunPasses for Forward {
    /// The forward pass: clear, depth test, back-face culling, one draw per object.
    fn run(&self, _: &Pass, f: &Frame) {
        let (gl, settings, u) = (f.gl, &f.scene.render, f.uniforms);
        let target = f.targets.get(world_target(f.scene));
        let p = match settings.shading {
            Shading::Phong => &self.phong,
            Shading::Gouraud => &self.gouraud,
            Shading::Flat => &self.flat,
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
            let (x, y, w, h) = f.view.rect(target.width, target.height);
            gl.viewport(x, y, w, h);
            let bg = u.clear_color;
            gl.clear_color(bg.x, bg.y, bg.z, 1.0);
            gl.enable(glow::DEPTH_TEST);
            gl.depth_func(settings.depth_func.gl());
            gl.depth_mask(true);
            // A view drawn into a mirror (stencil/mirror.rs) keeps the image.
            if f.view.clears {
                // A split view clears only its own rectangle: glClear obeys
                // the scissor test (notes 01 §4.2, a scissor box per viewport).
                gl.enable(glow::SCISSOR_TEST);
                gl.scissor(x, y, w, h);
                // The skybox drawn first (sky/sky_first.rs) is the background.
                let colour = if f.scene.sky_first() {
                    0
                } else {
                    glow::COLOR_BUFFER_BIT
                };
                gl.clear(colour | glow::DEPTH_BUFFER_BIT);
                gl.disable(glow::SCISSOR_TEST);
            }
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
            // A reflected view: only inside its mirror's stencil region, and
            // only what lies in front of the mirror (notes 05).
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            // Edges only (notes 01 §3.3-3.4: what the clipper makes of each triangle).
            if f.scene.render.wireframe {
                gl.polygon_mode(glow::FRONT_AND_BACK, glow::LINE);
            }
            // A reflected view's plane (GL_CLIP_DISTANCE0), and the scene's
            // clip planes (notes 01 §3.3), GL_CLIP_DISTANCE1 on.
            forward_pass::enable_clip_distances(f);

            // The program, the camera, the lights, the material's units.
            forward_pass::use_with_frame_uniforms(f, p);
            p.set_i32("u_light_map", unit::LIGHT_MAP as i32);
            // The environment reflective materials mirror (notes 03,
            // Implementation), filtered across the cube map's faces.
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            f.draws.environment.bind(gl, p);
            // Image-based lighting's maps, the ambient term with render.ibl.
            image_based_lighting::bind(gl, p, f.draws.environment.ibl.as_ref());
            // The area lights and their LTC tables (lighting/ltc_area_lights.rs).
            ltc_area_lights::bind(gl, p, f.scene, f.draws.ltc.as_ref());
            // Texture coordinates and vertex colours perspective-correct or
            // affine (notes 01 §4.1, §5.1).
            let affine = f.scene.render.interpolation == Interpolation::Affine;
            p.set_bool("u_affine", affine);
            f.view.set_uniforms(p, f.uniforms.eye, &f.scene.clip_planes);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            let mut depth_func = settings.depth_func;
            // Transparent objects are drawn later, sorted (blending/transparency.rs);
            // mirrors by the mirror technique (stencil/mirror.rs).
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                // Height-mapped objects: the parallax pass draws them
                // (lighting/parallax_mapping.rs).
                if d.height_map.is_some() && super::parallax_mapping::draws_relief(f.scene) {
                    continue;
                }
                // render.explode: the exploding-objects pass draws them
                // (vertex_geometry/exploding_objects.rs).
                if settings.explodes() {
                    continue;
                }
                // The material's face culling (notes 01 §3.4): back faces
                // (the default), front faces, both, or none.
                match d.cull.gl() {
                    Some(face) => {
                        gl.enable(glow::CULL_FACE);
                        gl.cull_face(face);
                    }
                    None => gl.disable(glow::CULL_FACE),
                }
                // A material may test depth its own way (notes 05, "Depth Test and Operation").
                let func = d.depth_func.unwrap_or(settings.depth_func);
                if func != depth_func {
                    gl.depth_func(func.gl());
                    depth_func = func;
                }
                // A mirroring model matrix, or a reflected view, turns
                // counter-clockwise triangles clockwise.
                gl.front_face(f.view.front_face(d.mirrored));
                // Its texture and normal map, with the sampler that says how
                // to read them (notes 01 §5: wrap rules, filter; §8.4).
                f.draws.bind_textures(gl, p, d, &f.scene.render);
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
            ltc_area_lights::unbind(gl, f.draws.ltc.as_ref());
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
