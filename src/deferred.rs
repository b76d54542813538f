//! What the three deferred paths share (notes 01 §8.6.2 "Workflow"): the
//! G-buffer, the light accumulation target (which tests against the
//! G-buffer's depth) and the volume meshes; and the order of their passes.
//!
//! | path     | 1. fill G-buffer | 2. lighting                      | 3. final image |
//! |----------|------------------|----------------------------------|----------------|
//! | deferred | gbuffer.rs       | deferred_shading.rs (full screen) | composite      |
//! | volumes  | gbuffer.rs       | light_volumes.rs                 | composite      |
//! | prepass  | gbuffer.rs, thin | deferred_lighting.rs (volumes)   | deferred_lighting.rs combine |

use crate::deferred_lighting::DeferredLighting;
use crate::deferred_shading::{Composite, DeferredShading};
use crate::gbuffer::GBuffer;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Sources;
use crate::gl::texture::Texture;
use crate::light_volumes::{LightVolumes, VolumeMeshes};
use crate::renderer::{DrawList, FrameUniforms, PassTimer};
use crate::scene::{RenderPath, Scene};
use anyhow::{Result, bail};

pub struct Deferred {
    accumulation_format: u32,
    pub gbuffer: GBuffer,
    pub accumulation: Framebuffer,
    meshes: VolumeMeshes,
    lighting: Lighting,
}

/// The lighting and final passes of each deferred path.
enum Lighting {
    FullScreen(DeferredShading, Composite),
    Volumes(LightVolumes, Composite),
    PrePass(DeferredLighting),
}

impl Lighting {
    /// The light pre-pass fills a thin G-buffer and accumulates into two targets.
    fn thin(&self) -> bool {
        matches!(self, Lighting::PrePass(_))
    }
}

impl Deferred {
    pub fn new(
        gl: &Gl,
        sources: &Sources,
        defines: &[(&str, String)],
        scene: &Scene,
        width: i32,
        height: i32,
    ) -> Result<Deferred> {
        let lighting = match scene.render.path {
            RenderPath::Deferred => Lighting::FullScreen(
                DeferredShading::new(gl, sources, defines)?,
                Composite::new(gl, sources)?,
            ),
            RenderPath::Volumes => Lighting::Volumes(
                LightVolumes::new(gl, sources, defines)?,
                Composite::new(gl, sources)?,
            ),
            RenderPath::Prepass => Lighting::PrePass(DeferredLighting::new(gl, sources, defines)?),
            RenderPath::Forward => bail!("the forward path has no deferred passes"),
        };
        let thin = lighting.thin();
        let gbuffer = GBuffer::new(gl, sources, width, height, thin)?;
        let accumulation_format = scene.render.accumulation;
        let accumulation = make_accumulation(gl, &gbuffer, accumulation_format, thin)?;
        Ok(Deferred {
            accumulation_format,
            meshes: VolumeMeshes::new(gl)?,
            gbuffer,
            accumulation,
            lighting,
        })
    }

    pub fn resize(&mut self, gl: &Gl, width: i32, height: i32) -> Result<()> {
        let thin = self.lighting.thin();
        // The accumulation target refers to the G-buffer's depth: drop it first.
        self.accumulation = Framebuffer::new(gl, "placeholder", 1, 1, &[glow::RGBA8], None)?;
        self.gbuffer.fbo = GBuffer::make_fbo(gl, width, height, thin)?;
        self.accumulation = make_accumulation(gl, &self.gbuffer, self.accumulation_format, thin)?;
        Ok(())
    }

    pub fn render(
        &self,
        gl: &glow::Context,
        scene: &Scene,
        frame: &FrameUniforms,
        draws: &DrawList,
        output: &Framebuffer,
        timer: &mut PassTimer,
    ) {
        let (gbuffer, accumulation, meshes) = (&self.gbuffer, &self.accumulation, &self.meshes);
        gbuffer.draw(gl, &scene.render, frame, draws);
        timer.mark("gbuffer");
        // A frame with no lights runs no lighting pass; its target still reads as black.
        let lit = frame.light_count > 0;
        if !lit {
            clear_accumulation(gl, accumulation);
        }
        match &self.lighting {
            Lighting::FullScreen(shading, composite) => {
                if lit {
                    shading.lighting(gl, frame, gbuffer, accumulation, &meshes.fullscreen);
                    timer.mark("lighting");
                }
                composite.draw(
                    gl,
                    scene,
                    frame,
                    gbuffer,
                    accumulation,
                    output,
                    &meshes.fullscreen,
                );
                timer.mark("composite");
            }
            Lighting::Volumes(volumes, composite) => {
                if lit {
                    volumes.lighting(gl, scene, frame, gbuffer, accumulation, meshes);
                    timer.mark("lighting");
                }
                composite.draw(
                    gl,
                    scene,
                    frame,
                    gbuffer,
                    accumulation,
                    output,
                    &meshes.fullscreen,
                );
                timer.mark("composite");
            }
            Lighting::PrePass(prepass) => {
                if lit {
                    prepass.lighting(gl, scene, frame, gbuffer, accumulation, meshes);
                    timer.mark("light pre-pass");
                }
                prepass.combine(gl, scene, frame, draws, gbuffer, accumulation, output);
                timer.mark("combine");
            }
        }
    }
}

/// Clear the light accumulation target to black.
fn clear_accumulation(gl: &glow::Context, target: &Framebuffer) {
    use glow::HasContext;
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
        gl.clear_color(0.0, 0.0, 0.0, 0.0);
        gl.clear(glow::COLOR_BUFFER_BIT);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}

fn make_accumulation(gl: &Gl, gbuffer: &GBuffer, format: u32, two: bool) -> Result<Framebuffer> {
    let (w, h) = (gbuffer.fbo.width, gbuffer.fbo.height);
    let mut colors = vec![Texture::render_target(gl, w, h, format)?];
    if two {
        colors.push(Texture::render_target(gl, w, h, format)?);
    }
    Framebuffer::with_attachments(
        gl,
        "light_accumulation",
        colors,
        None,
        Some(gbuffer.depth()),
    )
}
