//! Deferred lighting, the light pre-pass (notes 02 "Deferred lighting is like
//! deferred shading, but computes specular and diffuse shading separately,
//! then combines those in a final pass").
//!
//! 1. A thin G-buffer: normal + shininess and depth only (gbuffer.rs).
//! 2. The light pre-pass: per light, its volume (light_volumes.rs: the same
//!    steps, state and meshes), accumulating *diffuse* light and *specular*
//!    light into two HDR targets; then the area lights' diffuse and
//!    specular light, if the scene has area lights
//!    (ltc_area_lights_deferred.rs), added to the same targets.
//! 3. The combine pass: the scene drawn again (the same vertex shader,
//!    gl_Position invariant) with glDepthFunc(GL_LEQUAL) against the
//!    G-buffer's depth, copied into the output with glBlitFramebuffer, and no
//!    depth writes; each fragment reads its light and applies its own
//!    material at full precision: kd (ambient + D) + ks S.
//!
//! The combine's program is specialised like the G-buffer's (gbuffer.rs):
//! built with the scene's `MaterialVariant` defines, and an object whose
//! material tests no alpha drawn with the program built with
//! `NO_ALPHA_TEST` (`render.specialize = false`: the general program, the
//! alpha test for every object). `gloss plan` names the programs.
//!
//! GL state: step 2 as light_volumes.rs; step 3 sets GL_LEQUAL, depth writes
//! off, back-face culling, glFrontFace per object, and restores them.

use crate::frame::draw_list::DrawList;
use crate::frame::environment::Environment;
use crate::frame::gbuffer;
use crate::frame::image_based_lighting;
use crate::frame::lights::FrameLights;
use crate::frame::material_variant::alpha_programs;
use crate::frame::plan::Pass;
use crate::frame::plan_programs::PlanProgram;
use crate::frame::post::world_target;
use crate::frame::shadows;
use crate::frame::targets::{Depth, LIGHT_ACCUMULATION, TargetDesc};
use crate::frame::technique::LaterPrograms;
use crate::frame::uniforms::{LIGHTS_BINDING, unit};
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, Programs, RunPasses, Runs, Technique};
use crate::gl::program::Program;
use crate::scene::knobs;
use crate::scene::texturing::Interpolation;
use crate::scene::{RenderPath, Scene};
use crate::techniques::deferred::deferred_lighting_combine::{
    COMBINE_STAGES, CombineNeeds, combine_needs,
};
use crate::techniques::deferred::light_volumes::{draw_bounded_volumes, volume_pass};
use crate::techniques::deferred::ltc_area_lights_deferred::{LightPrepass, prepass_pass};
use anyhow::Result;
use glow::HasContext;
use std::cell::OnceCell;
use std::collections::BTreeSet;

pub const DEFERRED_LIGHTING: Technique = Technique {
    name: "deferred_lighting",
    notes: "notes 02, Deferred lighting",
    file: file!(),
    shaders: &[
        "deferred/light_volumes.vert",
        "deferred/deferred_lighting.frag",
        "deferred/gbuffer.vert",
        "deferred/deferred_lighting_combine.frag",
    ],
    scene: "scenes/light-prepass.toml",
    docs: "docs/deferred/deferred_lighting.md",
    knobs: &[
        &knobs::CUTOFF,
        &knobs::ACCUMULATION,
        &knobs::AMBIENT,
        &knobs::BACKGROUND,
    ],
    passes,
    targets,
    create,
    order: None,
    runs: Runs::PerView,
};

/// The steps of this technique's passes.
const LIGHT_PREPASS: u32 = 0;
const COMBINE: u32 = 1;
const AREA_LIGHTS: u32 = 2;

fn passes(scene: &Scene, lights: &FrameLights) -> Vec<Pass> {
    if scene.render.path != RenderPath::Prepass {
        return vec![];
    }
    let mut v = Vec::new();
    if !lights.is_empty() {
        let draws = format!(
            "{} light volumes, diffuse and specular apart, additive",
            lights.len()
        );
        let variant = LightingVariant::of(scene, lights).describe();
        v.push(
            Pass::new("light pre-pass", LIGHT_ACCUMULATION, draws, file!())
                .step(LIGHT_PREPASS)
                .with_variant(variant),
        );
    }
    v.extend(prepass_pass(scene).map(|p| p.step(AREA_LIGHTS)));
    let draws = format!(
        "{} objects again, GL_LEQUAL against the G-buffer's depth (blitted): material x light, {}",
        scene.opaque_objects(),
        if scene.post.is_empty() {
            "sRGB encode"
        } else {
            "linear"
        }
    );
    // One program for the objects that test no alpha, one for those that
    // do, as the G-buffer's.
    let programs = (alpha_programs(scene).into_iter())
        .map(|a| {
            let role = if a { "combine, alpha test" } else { "combine" };
            PlanProgram::new(role, CombineNeeds::of(scene, a).defines())
        })
        .collect();
    v.push(
        Pass::new("combine", world_target(scene), draws, file!())
            .step(COMBINE)
            .with_programs(programs),
    );
    v
}

fn targets(scene: &Scene, lights: &FrameLights) -> Vec<TargetDesc> {
    // The area lights' pass makes it when no light does.
    let area_lights = prepass_pass(scene).is_some();
    if scene.render.path != RenderPath::Prepass || (lights.is_empty() && !area_lights) {
        return vec![];
    }
    let format = scene.render.accumulation.gl();
    vec![TargetDesc {
        name: LIGHT_ACCUMULATION,
        samples: 1,
        colors: vec![("diffuse_light", format), ("specular_light", format)],
        depth: Depth::Own(gbuffer::depth_format(scene)),
        ping_pong: false,
        mips: None,
        downscale: 1,
    }]
}

struct DeferredLighting {
    light: Program,
    build: LaterPrograms,
    /// The combine's programs, by [`CombineNeeds::index`], each built the first
    /// frame that needs it.
    combine: [OnceCell<Program>; 128],
    /// The area lights' diffuse and specular light (after step 2).
    area_lights: LightPrepass,
}

fn create(p: &Programs) -> Result<Box<dyn RunPasses>> {
    // The per-light program is specialised to the frame (src/frame/variant.rs).
    let light = p.build_variant(&[
        (glow::VERTEX_SHADER, "deferred/light_volumes.vert"),
        (glow::FRAGMENT_SHADER, "deferred/deferred_lighting.frag"),
    ])?;
    light.bind_uniform_block("Lights", LIGHTS_BINDING);
    shadows::setup_program(&light);
    Ok(Box::new(DeferredLighting {
        light,
        build: p.later(),
        combine: std::array::from_fn(|_| OnceCell::new()),
        area_lights: LightPrepass::create(p)?,
    }))
}

impl RunPasses for DeferredLighting {
    /// The combine programs the objects' alpha tests need.
    fn prepare(&self, pass: &Pass, f: &Frame) -> Result<()> {
        if pass.step != COMBINE {
            return Ok(());
        }
        let tests: BTreeSet<i32> = f.draws.items.iter().map(|d| d.alpha_test).collect();
        for t in tests {
            self.combine_program(combine_needs(f.scene, t))?;
        }
        Ok(())
    }

    fn run(&self, pass: &Pass, f: &Frame) {
        match pass.step {
            LIGHT_PREPASS => self.light_prepass(f),
            COMBINE => self.combine(f),
            AREA_LIGHTS => self.area_lights.run(f),
            other => unreachable!("deferred lighting has no step {other}"),
        }
    }
}

impl DeferredLighting {
    /// Step 2: diffuse and specular light, per light volume, additive: the
    /// light-volume pass with this technique's shader.
    fn light_prepass(&self, f: &Frame) {
        volume_pass(f, &self.light, draw_bounded_volumes);
    }

    /// The combine program for `needs`, built now if no frame has needed
    /// it yet.
    fn combine_program(&self, needs: CombineNeeds) -> Result<&Program> {
        let i = needs.index();
        if let Some(p) = self.combine[i].get() {
            return Ok(p);
        }
        let program = self.build.build_with(&COMBINE_STAGES, &needs.defines())?;
        if needs.tints {
            program.bind_uniform_block("Cascades", shadows::CASCADES_BINDING);
        }
        Ok(self.combine[i].get_or_init(|| program))
    }

    /// Put the combine program for `needs` in use with the pass's uniforms
    /// and textures; None (and a warning) if it could not be built (built
    /// by `prepare`, which the renderer calls first).
    fn use_combine(&self, f: &Frame, needs: CombineNeeds, light: bool) -> Option<&Program> {
        let p = match self.combine_program(needs) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("warning: the light pre-pass's combine did not draw: {e:#}");
                return None;
            }
        };
        let (gl, u) = (f.gl, f.uniforms);
        unsafe {
            p.use_program();
            p.set_mat4("u_view_projection", &u.view_projection);
            p.set_vec3("u_ambient", f.scene.render.ambient);
            super::ambient_light::bind_result(f, p);
            p.set_bool("u_output_srgb", u.output_srgb);
            p.set_bool("u_has_light", light);
            p.set_i32("u_diffuse_texture", unit::DIFFUSE_TEXTURE as i32);
            p.set_i32("u_normal_map", unit::NORMAL_MAP as i32);
            p.set_i32("u_specular_map", unit::SPECULAR_MAP as i32);
            // Texture coordinates and vertex colours perspective-correct or
            // affine (notes 01 §4.1, §5.1).
            let affine = f.scene.render.interpolation == Interpolation::Affine;
            p.set_bool("u_affine", affine);
            p.set_i32("u_diffuse_light", unit::LIGHT as i32);
            p.set_i32("u_specular_light", unit::SPECULAR_LIGHT as i32);
            // The environment reflective materials mirror (notes 03,
            // Implementation), filtered across the cube map's faces.
            p.set_vec3("u_eye", u.eye);
            f.draws.environment.bind(gl, p);
            image_based_lighting::bind(gl, p, f.draws.environment.ibl.as_ref());
            f.view.set_uniforms(p, f.uniforms.eye, &f.scene.clip_planes);
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
        }
        Some(p)
    }

    /// Step 3: draw the scene again, combining light and material.
    fn combine(&self, f: &Frame) {
        let tints = shadows::cascade_tints(f.scene);
        let (gl, u) = (f.gl, f.uniforms);
        let gbuf = f.targets.get(gbuffer::NAME);
        let output = f.targets.get(world_target(f.scene));
        // A frame with no lights has no light pre-pass and no light to add.
        let light = f.targets.find(LIGHT_ACCUMULATION);
        // The view's rectangle (all of the output but for split views).
        let (x, y, w, h) = f.view.rect(output.width, output.height);
        unsafe {
            if f.view.clears {
                // The G-buffer's depth becomes the output's depth.
                gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(gbuf.id));
                gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(output.id));
                gl.blit_framebuffer(
                    x,
                    y,
                    x + w,
                    y + h,
                    x,
                    y,
                    x + w,
                    y + h,
                    glow::DEPTH_BUFFER_BIT,
                    glow::NEAREST,
                );
            }
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            gl.viewport(x, y, w, h);
            let bg = u.clear_color;
            gl.clear_color(bg.x, bg.y, bg.z, 1.0);
            gl.enable(glow::DEPTH_TEST);
            if f.view.clears {
                // Only this view's rectangle (glClear obeys the scissor test).
                gl.enable(glow::SCISSOR_TEST);
                gl.scissor(x, y, w, h);
                gl.clear(glow::COLOR_BUFFER_BIT);
                gl.disable(glow::SCISSOR_TEST);
                gl.depth_func(glow::LEQUAL);
                gl.depth_mask(false);
            } else {
                // A view drawn into a mirror (stencil/mirror.rs) keeps the
                // image and the depth outside its region: an ordinary depth
                // test there, against the depth the mirror cleared.
                gl.depth_func(f.scene.render.depth_func.gl());
                gl.depth_mask(true);
            }
            if let Some(region) = f.view.stencil {
                gl.enable(glow::STENCIL_TEST);
                gl.stencil_func(glow::EQUAL, region.into(), 0xff);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
            }
            if f.view.clips() {
                gl.enable(glow::CLIP_DISTANCE0);
            }
            // The scene's clip planes (notes 01 §3.3), GL_CLIP_DISTANCE1 on.
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.enable(glow::CLIP_DISTANCE1 + i);
            }
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);

            // The cascade colours: the cascades' ranges (shadow.cascade_colors).
            if tints {
                f.shadows.bind_cascade_block(gl, true);
            }
            gl.enable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            gl.active_texture(glow::TEXTURE0 + unit::LIGHT);
            gl.bind_texture(glow::TEXTURE_2D, light.map(|t| t.colors[0].id));
            gl.active_texture(glow::TEXTURE0 + unit::SPECULAR_LIGHT);
            gl.bind_texture(glow::TEXTURE_2D, light.map(|t| t.colors[1].id));
            gl.active_texture(glow::TEXTURE0 + unit::DIFFUSE_TEXTURE);
            // Transparent objects are drawn later, sorted (blending/transparency.rs);
            // mirrors by the mirror technique (stencil/mirror.rs).
            // The program in use, and what it was built for.
            let mut current: Option<(CombineNeeds, Option<&Program>)> = None;
            for i in f.opaque_order() {
                let d = &f.draws.items[i];
                // The program its alpha test needs, put in use when it changes.
                let want = combine_needs(f.scene, d.alpha_test);
                if current.map(|c| c.0) != Some(want) {
                    current = Some((want, self.use_combine(f, want, light.is_some())));
                }
                let Some((_, Some(p))) = current else {
                    continue;
                };
                // The material's face culling (notes 01 §3.4): back faces
                // (the default), front faces, both, or none.
                match d.cull.gl() {
                    Some(face) => {
                        gl.enable(glow::CULL_FACE);
                        gl.cull_face(face);
                    }
                    None => gl.disable(glow::CULL_FACE),
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

            gl.front_face(glow::CCW);
            gl.disable(glow::CLIP_DISTANCE0);
            for i in 0..f.scene.clip_planes.len() as u32 {
                gl.disable(glow::CLIP_DISTANCE1 + i);
            }
            gl.stencil_func(glow::ALWAYS, 0, 0xff);
            gl.disable(glow::STENCIL_TEST);
            DrawList::unbind_textures(gl);
            gl.bind_texture(glow::TEXTURE_2D, None);
            super::ambient_light::unbind_result(gl);
            Environment::unbind(gl);
            image_based_lighting::unbind(gl, f.draws.environment.ibl.as_ref());
            gl.disable(glow::TEXTURE_CUBE_MAP_SEAMLESS);
            for u in [unit::LIGHT, unit::SPECULAR_LIGHT] {
                gl.active_texture(glow::TEXTURE0 + u);
                gl.bind_texture(glow::TEXTURE_2D, None);
            }
            gl.active_texture(glow::TEXTURE0);
            if tints {
                f.shadows.bind_cascade_block(gl, false);
            }
            gl.use_program(None);
            gl.cull_face(glow::BACK);
            gl.disable(glow::CULL_FACE);
            gl.depth_mask(true);
            gl.depth_func(glow::LESS);
            gl.disable(glow::DEPTH_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
