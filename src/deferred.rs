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
use anyhow::Result;

pub struct Deferred {
    path: RenderPath,
    accumulation_format: u32,
    pub gbuffer: GBuffer,
    pub accumulation: Framebuffer,
    meshes: VolumeMeshes,
    shading: Option<DeferredShading>,
    volumes: Option<LightVolumes>,
    prepass: Option<DeferredLighting>,
    composite: Option<Composite>,
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
        let path = scene.render.path;
        let thin = path == RenderPath::Prepass;
        let gbuffer = GBuffer::new(gl, sources, width, height, thin)?;
        let accumulation_format = scene.render.accumulation;
        let accumulation = make_accumulation(gl, &gbuffer, accumulation_format, thin)?;
        Ok(Deferred {
            path,
            accumulation_format,
            meshes: VolumeMeshes::new(gl)?,
            shading: match path {
                RenderPath::Deferred => Some(DeferredShading::new(gl, sources, defines)?),
                _ => None,
            },
            volumes: match path {
                RenderPath::Volumes => Some(LightVolumes::new(gl, sources, defines)?),
                _ => None,
            },
            prepass: match path {
                RenderPath::Prepass => Some(DeferredLighting::new(gl, sources, defines)?),
                _ => None,
            },
            composite: match path {
                RenderPath::Deferred | RenderPath::Volumes => Some(Composite::new(gl, sources)?),
                _ => None,
            },
            gbuffer,
            accumulation,
        })
    }

    pub fn resize(&mut self, gl: &Gl, width: i32, height: i32) -> Result<()> {
        let thin = self.path == RenderPath::Prepass;
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
        self.gbuffer.draw(gl, &scene.render, frame, draws);
        timer.mark("gbuffer");
        let has_lights = frame.light_count > 0;
        match self.path {
            RenderPath::Deferred | RenderPath::Volumes => {
                if let (true, Some(s)) = (has_lights, &self.shading) {
                    s.lighting(
                        gl,
                        frame,
                        &self.gbuffer,
                        &self.accumulation,
                        &self.meshes.fullscreen,
                    );
                    timer.mark("lighting");
                } else if let (true, Some(v)) = (has_lights, &self.volumes) {
                    v.lighting(
                        gl,
                        scene,
                        frame,
                        &self.gbuffer,
                        &self.accumulation,
                        &self.meshes,
                    );
                    timer.mark("lighting");
                } else {
                    clear_accumulation(gl, &self.accumulation);
                }
                let c = self
                    .composite
                    .as_ref()
                    .expect("composite exists for this path");
                c.draw(
                    gl,
                    scene,
                    frame,
                    &self.gbuffer,
                    &self.accumulation,
                    output,
                    &self.meshes.fullscreen,
                );
                timer.mark("composite");
            }
            RenderPath::Prepass => {
                let p = self.prepass.as_ref().expect("prepass programs exist");
                if has_lights {
                    p.lighting(
                        gl,
                        scene,
                        frame,
                        &self.gbuffer,
                        &self.accumulation,
                        &self.meshes,
                    );
                    timer.mark("light pre-pass");
                } else {
                    clear_accumulation(gl, &self.accumulation);
                }
                p.combine(
                    gl,
                    scene,
                    frame,
                    draws,
                    &self.gbuffer,
                    &self.accumulation,
                    output,
                );
                timer.mark("combine");
            }
            RenderPath::Forward => unreachable!("the forward path has no deferred resources"),
        }
    }
}

/// With no lights the lighting pass is skipped; its target still reads as black.
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
