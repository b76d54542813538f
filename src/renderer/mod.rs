//! The renderer: uploads a scene's meshes, textures and lights, allocates
//! the targets its frame plan names, builds the programs of the techniques
//! the plan uses, and each frame runs the plan's passes in order, one line
//! each. What a pass does lives in its technique's file (src/techniques/).

mod output;
mod passes;
mod probe;
mod probe_pcf;
mod probe_read;
mod probe_shadow;
mod probe_text;
mod probe_tiles;
mod programs;

use output::target_descs;
pub use output::{Output, stencil_color, stencil_image};
pub use probe::{MAGNIFIER_RADIUS, Probe, TargetValue, TileLists};
pub use {probe_pcf::Filtered, probe_shadow::FACES, probe_shadow::ShadowProbe};

use crate::frame::draw_list::DrawList;
use crate::frame::light_halves::LightTextures;
use crate::frame::lights::{FrameLights, LIGHT_STRIDE, MAX_LIGHTS, check_lights_fit, max_lights};
use crate::frame::plan::{FramePlan, Pass};
use crate::frame::post::world_image;
use crate::frame::shadows::ShadowMaps;
use crate::frame::targets::{OUTPUT, Targets};
use crate::frame::timing::{PassTimer, PassTimes, timer_queries_trustworthy};
use crate::frame::uniforms::FrameUniforms;
use crate::frame::variant::LightingVariant;
use crate::frame::{Frame, RunPasses, meshes::FrameMeshes, views::View};
use crate::gl::program::Sources;
use crate::gl::texture_buffer::max_texels;
use crate::gl::{Gl, Headless, buffer::Buffer, debug::DebugLog, framebuffer::Framebuffer};
use crate::lighting;
use crate::scene::{Camera, RenderSettings, Scene};
use crate::techniques;
use anyhow::Result;
use glow::HasContext;
use std::collections::HashMap;

pub struct Renderer {
    gl: Gl,
    debug: DebugLog,
    pub scene: Scene,
    pub plan: FramePlan,
    lights: FrameLights,
    pub width: i32,
    pub height: i32,
    pub output_kind: Output,
    targets: Targets,
    draws: DrawList,
    lights_ubo: Buffer,
    /// Every light, for the passes that read more than the block holds (tiled, far field).
    lights_texture: LightTextures,
    meshes: FrameMeshes,
    /// The casting lights' depth maps (none when no light casts).
    shadows: ShadowMaps,
    /// Where shader text comes from, and the light limit, for programs built later.
    sources: Sources,
    max_lights: usize,
    /// The programs of each registered technique the plan uses, by registry index.
    techniques: Vec<Option<Box<dyn RunPasses>>>,
    /// The lighting variant the specialised techniques are built for, which those are, and
    /// their instances for other variants (a settings change and back builds nothing again).
    variant: LightingVariant,
    specialised: Vec<bool>,
    variant_cache: HashMap<(usize, LightingVariant), Box<dyn RunPasses>>,
    /// The slim G-buffer's specular colour as this GL reads it (frame/gbuffer_slim.rs).
    gbuffer_specular: glam::Vec3,
    /// Measure each pass with glFinish + the CPU clock.
    pub timing: bool,
    /// With `timing`, also GL_TIMESTAMP queries: on where the driver's timer
    /// queries are trustworthy (not on llvmpipe).
    pub gpu_timers: bool,
    pub last_times: PassTimes,
    /// Whether each pass is a KHR_debug group (passes.rs).
    debug_groups: bool,
}

impl Renderer {
    pub fn new(
        gl: &Gl,
        debug: &DebugLog,
        scene: &Scene,
        sources: &Sources,
        width: i32,
        height: i32,
    ) -> Result<Renderer> {
        Self::with_output(gl, debug, scene, sources, width, height, Output::Srgb8)
    }

    pub fn with_output(
        gl: &Gl,
        debug: &DebugLog,
        scene: &Scene,
        sources: &Sources,
        width: i32,
        height: i32,
        output_kind: Output,
    ) -> Result<Renderer> {
        let max_block = unsafe { gl.get_parameter_i32(glow::MAX_UNIFORM_BLOCK_SIZE) };
        let max_lights = max_lights(max_block);
        check_lights_fit(
            scene,
            max_lights,
            &format!(
                "GL_MAX_UNIFORM_BLOCK_SIZE = {max_block} bytes on this GL, {LIGHT_STRIDE} a light, at most {MAX_LIGHTS}"
            ),
            max_texels(gl),
        )?;
        crate::frame::gbuffer::check_units(gl, scene)?;
        crate::frame::image_based_lighting::check_units(gl, scene)?;
        crate::frame::ltc_area_lights::check_units(gl, scene)?;
        let clip = unsafe { gl.get_parameter_i32(glow::MAX_CLIP_DISTANCES) } as usize;
        if scene.clip_planes.len() + 1 > clip {
            anyhow::bail!(
                "{}: {} clip planes, but this GL has GL_MAX_CLIP_DISTANCES = {clip}, one of them the mirrors'",
                scene.path.display(),
                scene.clip_planes.len()
            );
        }
        let lights = FrameLights::new(scene);
        let plan = FramePlan::new(scene, &lights, techniques::ALL);
        let descs = output::checked_targets(gl, scene, &plan, output_kind, (width, height))?;
        let targets = Targets::new(gl, &descs, width, height)?;
        let lights_ubo = Buffer::new(
            gl,
            glow::UNIFORM_BUFFER,
            max_lights * LIGHT_STRIDE,
            glow::DYNAMIC_DRAW,
        )?;
        let lights_texture = LightTextures::new(gl)?;
        let mut techniques = Vec::new();
        techniques.resize_with(techniques::ALL.len(), || None);
        let mut r = Renderer {
            gl: gl.clone(),
            debug: debug.clone(),
            scene: scene.clone(),
            plan,
            lights,
            width,
            height,
            output_kind,
            targets,
            draws: DrawList::new(gl, scene)?,
            lights_ubo,
            lights_texture,
            meshes: FrameMeshes::new(gl)?,
            shadows: ShadowMaps::new(gl, scene, max_lights)?,
            sources: sources.clone(),
            max_lights,
            techniques,
            variant: LightingVariant::GENERAL,
            specialised: vec![false; techniques::ALL.len()],
            variant_cache: HashMap::new(),
            gbuffer_specular: crate::frame::gbuffer_slim::uniform_value(gl, scene)?,
            timing: false,
            gpu_timers: timer_queries_trustworthy(&unsafe {
                gl.get_parameter_string(glow::RENDERER)
            }),
            last_times: PassTimes::default(),
            debug_groups: passes::has_debug_groups(gl),
        };
        let variant = LightingVariant::of(scene, &r.lights);
        r.build_planned_techniques(variant)?;
        r.upload_lights()?;
        debug.check(gl, "renderer set-up")?;
        Ok(r)
    }

    /// Take new render settings (the demo's panel); see `set_scene_values`.
    pub fn set_render_settings(&mut self, settings: RenderSettings) -> Result<()> {
        let mut scene = self.scene.clone();
        scene.render = settings;
        self.set_scene_values(&scene)
    }

    /// Take `scene`'s render settings, lights, materials and object
    /// transforms (the demo's panel edits them; its objects must be this
    /// renderer's, in the same order): the lights' derived values, the plan
    /// and, where they changed, the targets are made again, and the programs
    /// of techniques the new plan adds are built. Meshes and textures stay
    /// uploaded. On an error the renderer keeps what it had.
    pub fn set_scene_values(&mut self, scene: &Scene) -> Result<()> {
        check_lights_fit(
            scene,
            self.max_lights,
            "this GL's GL_MAX_UNIFORM_BLOCK_SIZE",
            max_texels(&self.gl),
        )?;
        let old = std::mem::replace(&mut self.scene, scene.clone());
        let lights = FrameLights::new(&self.scene);
        let plan = FramePlan::new(&self.scene, &lights, techniques::ALL);
        let targets_changed = plan.targets != self.plan.targets;
        let old_plan = std::mem::replace(&mut self.plan, plan);
        let old_variant = self.variant;
        if let Err(e) = self.build_planned_techniques(LightingVariant::of(&self.scene, &lights)) {
            self.scene = old;
            self.plan = old_plan;
            // The old variant's instances come back from the cache.
            self.build_planned_techniques(old_variant)?;
            return Err(e);
        }
        if targets_changed {
            self.targets.clear();
            self.targets = Targets::new(
                &self.gl,
                &target_descs(&self.plan, self.output_kind),
                self.width,
                self.height,
            )?;
        }
        self.shadows.take_casters(&self.gl, &self.scene)?;
        self.gbuffer_specular = crate::frame::gbuffer_slim::uniform_value(&self.gl, &self.scene)?;
        self.lights = lights;
        self.upload_lights()?;
        self.draws.update_values(&self.scene);
        // render.ibl may add the sky's cube map and image-based lighting's maps, or drop them.
        let environment = &self.draws.environment;
        if environment.source != self.scene.environment()
            || environment.ibl.is_some() != crate::frame::image_based_lighting::wanted(&self.scene)
        {
            crate::frame::image_based_lighting::check_units(&self.gl, &self.scene)?;
            self.draws.environment =
                crate::frame::environment::Environment::new(&self.gl, &self.scene)?;
        }
        self.debug.check(&self.gl, "changing the scene's values")
    }

    /// The render targets of the current plan (the demo's pass inspector).
    pub fn targets(&self) -> &Targets {
        &self.targets
    }

    /// Each light's radius and volume (the demo's light-volume views).
    pub fn lights(&self) -> &FrameLights {
        &self.lights
    }

    /// The shadow maps (the demo's shadow-map inspector, the tests).
    pub fn shadows(&self) -> &ShadowMaps {
        &self.shadows
    }

    /// The scene's objects on the GPU (the tests read the skinned vertices back).
    pub fn draws(&self) -> &DrawList {
        &self.draws
    }

    /// The full-screen triangle and the volume meshes.
    pub fn meshes(&self) -> &FrameMeshes {
        &self.meshes
    }

    /// Write the scene's lights into the uniform buffer (as many as it holds) and all of them
    /// into the buffer texture, floats or halves (tiled shading and the far field read it: a
    /// tiled frame may hold more lights than the block). Once per change of the scene's values.
    fn upload_lights(&mut self) -> Result<()> {
        let bytes = self.lights.pack(&self.scene);
        let n = bytes.len().min(self.max_lights * LIGHT_STRIDE);
        if n > 0 {
            self.lights_ubo.write(&bytes[..n]);
        }
        self.lights_texture.write(&self.scene, &bytes)
    }

    /// Reallocate the targets at a new size (nothing happens for the same
    /// size, or for 0 x 0, a minimised window).
    pub fn resize(&mut self, width: i32, height: i32) -> Result<()> {
        if width < 1 || height < 1 || (width, height) == (self.width, self.height) {
            return Ok(());
        }
        self.targets.clear();
        self.targets = Targets::new(
            &self.gl,
            &target_descs(&self.plan, self.output_kind),
            width,
            height,
        )?;
        self.width = width;
        self.height = height;
        Ok(())
    }

    /// The finished frame (colour attachment 0).
    pub fn output(&self) -> &Framebuffer {
        self.targets.get(OUTPUT)
    }

    /// The world image: the output, or the HDR target a post chain reads
    /// (its depth and stencil are the frame's; with MSAA, resolved into it).
    pub fn world(&self) -> &Framebuffer {
        self.targets.get(world_image(&self.scene))
    }

    /// The camera's uniforms, for `view`: a reflected view draws the world
    /// through `VP * R` and lights it with the eye reflected back, `R^-1 *
    /// eye` (src/frame/views.rs says why).
    ///
    /// A split view has its own camera (or the frame's) and the aspect of
    /// its own rectangle.
    pub fn frame_uniforms(&self, camera: &Camera, for_view: &View) -> FrameUniforms {
        let camera = for_view.camera.as_ref().unwrap_or(camera);
        let (x, y, w, h) = for_view.rect(self.width, self.height);
        let view = camera.view();
        let projection = camera.projection(w as f32 / h as f32);
        let r = for_view.reflection;
        let vp = projection * view * r;
        let encoded = self.output_kind == Output::Srgb8;
        // A post chain gets the world's light linear, and encodes at its end.
        let srgb = encoded && self.scene.post.is_empty();
        let bg = self.scene.render.background;
        FrameUniforms {
            view,
            projection,
            view_projection: vp,
            inverse_view_projection: vp.inverse(),
            eye: r.inverse().transform_point3(camera.eye),
            near: camera.near,
            far: camera.far,
            light_count: self.scene.lights.len().min(self.max_lights) as i32,
            lights_ubo: self.lights_ubo.id,
            lights_texture: self.lights_texture.texture(self.variant.light_halves),
            output_srgb: srgb,
            output_encoded: encoded,
            viewport: [x, y, w, h],
            shininess_table: crate::frame::gbuffer::shininess_uniform(&self.scene),
            gbuffer_specular: self.gbuffer_specular,
            clear_color: if srgb {
                bg.map(lighting::srgb_encode)
            } else {
                bg
            },
        }
    }

    /// Run the frame plan with the given camera into `output()`.
    pub fn render(&mut self, camera: &Camera) -> Result<()> {
        self.render_inspected(camera, &mut |_| {})
    }

    /// `render`, calling `after_pass` after each pass (tests inspect the GL state there).
    pub fn render_inspected(
        &mut self,
        camera: &Camera,
        after_pass: &mut dyn FnMut(&Pass),
    ) -> Result<()> {
        let uniforms: Vec<FrameUniforms> = (self.plan.views.iter())
            .map(|v| self.frame_uniforms(camera, v))
            .collect();
        let aspect = self.width as f32 / self.height as f32;
        (self.shadows).update(&self.scene, &self.draws, camera, aspect);
        let mut timer = PassTimer::new(&self.gl, self.timing, self.gpu_timers);
        for (i, pass) in self.plan.passes.iter().enumerate() {
            let frame = Frame {
                gl: &self.gl,
                scene: &self.scene,
                uniforms: &uniforms[pass.view],
                view: &self.plan.views[pass.view],
                draws: &self.draws,
                lights: &self.lights,
                targets: &self.targets,
                meshes: &self.meshes,
                shadows: &self.shadows,
            };
            let technique = self.techniques[pass.technique].as_deref();
            let technique = technique.expect("built for its pass");
            let (title, groups) = (self.plan.title(i), self.debug_groups);
            passes::run_pass(i + 1, pass, &title, technique, &frame, groups)?;
            timer.mark(pass.name, title);
            after_pass(pass);
        }
        self.last_times = timer.finish();
        self.last_times.culling =
            (self.scene.render.frustum_culling).then(|| self.draws.last_cull.get());
        let shadow = self.draws.shadow_cull.get();
        self.last_times.shadow_culling = (shadow.objects > 0).then_some(shadow);
        self.debug.check(&self.gl, "the frame")?;
        Ok(())
    }
}

/// Build a renderer for `scene` at its own size on a headless context and
/// draw one frame from the scene's camera: what `gloss render` and the image
/// tests do.
pub fn render_scene(ctx: &Headless, scene: &Scene, output: Output) -> Result<Renderer> {
    let (w, h) = scene.render.size;
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
        output,
    )?;
    r.render(&scene.camera)?;
    Ok(r)
}
