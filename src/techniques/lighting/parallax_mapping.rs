//! Parallax mapping (LearnOpenGL, 5.advanced_lighting, "Parallax Mapping":
//! 5.1 parallax mapping, 5.2 steep parallax mapping, 5.3 parallax occlusion
//! mapping), with self-shadowing (Tatarchuk 2006, "Dynamic parallax
//! occlusion mapping with approximate soft shadows").
//!
//! A height map says how far below the polygon the surface lies at each
//! texel. The fragment shader (glsl/lighting/parallax_mapping.frag) takes
//! the view direction into tangent space and follows it into the relief:
//!
//! ```text
//! 1. parallax:  uv - V.xy / V.z * depth(uv) * height_scale   (one shift)
//! 2. steep:     step the ray down n layers until it is below depth(uv)
//! 3. occlusion: the hit between the last two layers, interpolated
//! 4. shadows:   from the hit, step toward each light; blocked where the
//!               relief rises above that ray
//! ```
//!
//! then shades as forward's Phong pass does, with the diffuse texture, the
//! normal map and the specular map read at the uv the ray hit. LearnOpenGL's
//! lesson binds the diffuse map, the normal map and the depth map and draws
//! its quad; this pass does the same per object, for the opaque objects whose
//! material has a height map (forward's pass skips them), after the forward
//! pass, into the same target, on the forward path with Phong shading.
//!
//! GL state: as forward's pass (it does not clear): glDepthFunc, depth
//! writes, culling per material, glFrontFace per object, the stencil test
//! and GL_CLIP_DISTANCE0 for a reflected view, the scene's clip planes;
//! restores GL_LESS, no depth test, no culling, GL_CCW, no stencil test, no
//! clip distance, unit 0 active with nothing bound.

use crate::frame::draw_list::DrawList;
use crate::frame::environment::Environment;
use crate::frame::forward_pass;
use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::TargetDesc;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::texturing::Interpolation;
use crate::scene::{Parallax, RenderPath, Scene, Shading};
use anyhow::Result;
use glow::HasContext;

pub const PARALLAX_MAPPING: Technique = Technique {
    name: "parallax_mapping",
    notes: "LearnOpenGL 5.advanced_lighting, Parallax Mapping; Tatarchuk 2006",
    file: file!(),
    shaders: &["lighting/forward.vert", "lighting/parallax_mapping.frag"],
    scene: "scenes/parallax.toml",
    docs: "docs/lighting/parallax_mapping.md",
    knobs: &[
        &knobs::PARALLAX,
        &knobs::PARALLAX_LAYERS,
        &knobs::PARALLAX_SHADOWS,
        &knobs::PARALLAX_UV,
        &knobs::NORMAL_MAPPING,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// Whether the parallax pass draws the objects whose material has a height
/// map (the forward pass then skips them): the forward path, Phong shading,
/// `render.parallax` not off.
pub fn draws_relief(scene: &Scene) -> bool {
    let r = &scene.render;
    r.path == RenderPath::Forward && r.shading == Shading::Phong && r.parallax != Parallax::Off
}

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    let relief = (scene.objects.iter())
        .filter(|o| o.mirror.is_none())
        .map(|o| &scene.materials[o.material])
        .filter(|m| m.height_map.is_some() && !m.is_transparent())
        .count();
    if relief == 0 || !draws_relief(scene) {
        return vec![];
    }
    let r = &scene.render;
    let method = match r.parallax {
        Parallax::Plain => "one offset".to_string(),
        Parallax::Steep => format!("steep, {} layers", r.parallax_layers),
        _ => format!("occlusion, {} layers", r.parallax_layers),
    };
    let shadows = if r.parallax_shadows {
        ", relief shadows"
    } else {
        ""
    };
    let draws = format!(
        "{relief} objects with a height map x {} lights ({method}{shadows})",
        scene.lights.len()
    );
    let pass = Pass::new("parallax", world_target(scene), draws, file!());
    vec![pass.with_variant(LightingVariant::of(scene, lights).describe())]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

struct ParallaxMapping {
    program: Program,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    let program = p.build_variant(&[
        (glow::VERTEX_SHADER, "lighting/forward.vert"),
        (glow::FRAGMENT_SHADER, "lighting/parallax_mapping.frag"),
    ])?;
    program.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&program);
    Ok(Box::new(ParallaxMapping { program }))
}

impl RunPasses for ParallaxMapping {
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
            forward_pass::enable_clip_distances(f);

            // shader.use(); the forward pass's uniforms, then the lesson's:
            // heightScale, and the method.
            forward_pass::use_with_frame_uniforms(f, p);
            p.set_i32("u_height_map", unit::HEIGHT_MAP as i32);
            let method = match settings.parallax {
                Parallax::Plain => 1,
                Parallax::Steep => 2,
                _ => 3,
            };
            p.set_i32("u_parallax", method);
            p.set_i32("u_layers", settings.parallax_layers as i32);
            p.set_bool("u_self_shadow", settings.parallax_shadows);
            p.set_bool("u_show_uv", settings.parallax_uv);
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            f.draws.environment.bind(gl, p);
            let affine = settings.interpolation == Interpolation::Affine;
            p.set_bool("u_affine", affine);
            f.view.set_uniforms(p, u.eye, &f.scene.clip_planes);
            gl.bind_buffer_base(glow::UNIFORM_BUFFER, LIGHTS_BINDING, Some(u.lights_ubo));
            f.shadows.bind(gl);
            let mut depth_func = settings.depth_func;
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                let Some(height_map) = d.height_map else {
                    continue;
                };
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
                // glActiveTexture; glBindTexture: the depth map beside the
                // diffuse and normal maps, read with the material's sampler.
                gl.active_texture(glow::TEXTURE0 + unit::HEIGHT_MAP);
                gl.bind_texture(glow::TEXTURE_2D, Some(f.draws.textures[height_map].id));
                gl.bind_sampler(unit::HEIGHT_MAP, f.draws.sampler(d, settings));
                f.draws.bind_textures(gl, p, d, settings);
                p.set_f32("u_height_scale", d.height_scale);
                f.draws.set_object_uniforms(p, d);
                f.draws.mesh(d).draw();
            }

            // Restore the state this pass changed.
            forward_pass::disable_clip_distances(f);
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            gl.front_face(glow::CCW);
            gl.active_texture(glow::TEXTURE0 + unit::HEIGHT_MAP);
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.bind_sampler(unit::HEIGHT_MAP, None);
            DrawList::unbind_textures(gl);
            Environment::unbind(gl);
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
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
