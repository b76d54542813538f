//! Light volumes (notes 04 "Light Volumes"; notes 01 §8.6.1).
//!
//! Deferred shading still shades every pixel for every light, although the
//! attenuation makes most lights negligible at most pixels. Rasterisation is
//! the conditional: draw, per light, a mesh that encloses the region the light
//! reaches, and shade only the pixels it covers.
//!
//! 1. The radius: where the attenuated light falls to `cutoff` (5/256) of the
//!    light's brightest channel (src/attenuation.rs; stable for small Kq).
//! 2. A point light draws a sphere scaled to that radius; a spot light a cone
//!    turned to its direction and scaled to its range and outer angle; a
//!    directional light (or one whose attenuation never reaches the cutoff)
//!    the full-screen triangle with an identity MVP.
//! 3. uv = gl_FragCoord.xy / textureSize (glsl/gbuffer_read.glsl).
//! 4. glCullFace(GL_FRONT): draw the back faces, so the volume still lights
//!    when the camera is inside it.
//! 5. glDepthMask(GL_FALSE); glEnable(GL_BLEND); glBlendFunc(GL_ONE, GL_ONE)
//!    on a black clear, into an RGBA16F target so many lights do not saturate.
//! 6. Only surfaces inside the volume are shaded: the back faces are depth
//!    tested with GL_GEQUAL against the scene's depth (the surface is in front
//!    of the back face), and the shader discards what lies beyond the radius
//!    (surfaces in front of the volume). GL_DEPTH_CLAMP keeps back faces that
//!    reach past the far plane.
//!
//! Option (`render.stencil_volumes`): the two-sided stencil test. Per light,
//! first draw the volume's both faces into the stencil only (back faces behind
//! the surface increment, front faces behind the surface decrement), so the
//! stencil is non-zero exactly where the surface is inside the volume; then
//! shade where stencil != 0, zeroing it for the next light.

use crate::gbuffer::GBuffer;
use crate::geometry;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::renderer::FrameUniforms;
use crate::scene::{Light, LightKind, Scene};
use anyhow::Result;
use glam::{Mat4, Quat, Vec3};
use glow::HasContext;

/// The meshes every light-volume pass draws.
pub struct VolumeMeshes {
    /// Encloses the unit sphere (every face plane at distance >= 1).
    pub sphere: Mesh,
    /// Encloses the cone of half-angle 45°, apex at the origin, axis -Z, height 1.
    pub cone: Mesh,
    pub fullscreen: Mesh,
}

impl VolumeMeshes {
    pub fn new(gl: &Gl) -> Result<VolumeMeshes> {
        Ok(VolumeMeshes {
            sphere: Mesh::upload(gl, &geometry::light_volume_sphere())?,
            cone: Mesh::upload(gl, &geometry::cone(32))?,
            fullscreen: Mesh::upload(gl, &geometry::fullscreen_triangle())?,
        })
    }
}

/// Which mesh a light draws and its model matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Volume {
    Sphere(Mat4),
    Cone(Mat4),
    FullScreen,
}

/// The light's volume at `cutoff`.
pub fn volume_for(light: &Light, cutoff: f32) -> Volume {
    match (light.kind, light.volume_radius(cutoff)) {
        (LightKind::Point, Some(r)) => Volume::Sphere(
            Mat4::from_translation(light.position) * Mat4::from_scale(Vec3::splat(r)),
        ),
        (LightKind::Spot, Some(r)) => {
            // The unit cone has half-angle 45° (radius 1 at height 1): scale
            // its width by tan(outer) and its length by the range, then turn
            // -Z onto the light's direction.
            let w = r * light.outer_angle.to_radians().tan();
            let turn = Quat::from_rotation_arc(Vec3::NEG_Z, light.direction);
            Volume::Cone(Mat4::from_scale_rotation_translation(
                Vec3::new(w, w, r),
                turn,
                light.position,
            ))
        }
        _ => Volume::FullScreen,
    }
}

/// Draw every light's volume with program `p` (in use, G-buffer bound):
/// sets u_light_id and u_mvp per light. With `stencil`, marks the volume's
/// pixels in the stencil first (bounded lights only).
pub fn draw_volumes(
    gl: &glow::Context,
    p: &Program,
    scene: &Scene,
    frame: &FrameUniforms,
    meshes: &VolumeMeshes,
    stencil: bool,
) {
    for (i, light) in scene.lights.iter().enumerate() {
        p.set_i32("u_light_id", i as i32);
        let (mesh, mvp) = match volume_for(light, scene.render.cutoff) {
            Volume::Sphere(m) => (&meshes.sphere, frame.view_projection * m),
            Volume::Cone(m) => (&meshes.cone, frame.view_projection * m),
            Volume::FullScreen => {
                // "mvp is simple identity pass through"; no depth test, both faces.
                p.set_mat4("u_mvp", &Mat4::IDENTITY);
                unsafe {
                    gl.disable(glow::DEPTH_TEST);
                    gl.disable(glow::STENCIL_TEST);
                    gl.disable(glow::CULL_FACE);
                }
                meshes.fullscreen.draw();
                unsafe {
                    gl.enable(glow::CULL_FACE);
                    gl.enable(glow::DEPTH_TEST);
                    if stencil {
                        gl.enable(glow::STENCIL_TEST);
                    }
                }
                continue;
            }
        };
        p.set_mat4("u_mvp", &mvp);
        unsafe {
            if stencil {
                // Stencil marking: both faces, no colour, depth-fail counts.
                gl.color_mask(false, false, false, false);
                gl.disable(glow::CULL_FACE);
                gl.depth_func(glow::LESS);
                gl.stencil_func(glow::ALWAYS, 0, 0xFF);
                gl.stencil_op_separate(glow::BACK, glow::KEEP, glow::INCR_WRAP, glow::KEEP);
                gl.stencil_op_separate(glow::FRONT, glow::KEEP, glow::DECR_WRAP, glow::KEEP);
                mesh.draw();
                // Shading: where stencil != 0, resetting it to 0 as we go.
                gl.color_mask(true, true, true, true);
                gl.enable(glow::CULL_FACE);
                gl.disable(glow::DEPTH_TEST);
                gl.stencil_func(glow::NOTEQUAL, 0, 0xFF);
                gl.stencil_op(glow::KEEP, glow::KEEP, glow::ZERO);
                mesh.draw();
                gl.enable(glow::DEPTH_TEST);
                gl.depth_func(glow::GEQUAL);
            } else {
                mesh.draw();
            }
        }
    }
}

/// Set the state of notes 04 for drawing light volumes into `target`.
/// `restore_volume_state` undoes it.
pub fn begin_volume_state(gl: &glow::Context, target: &Framebuffer, stencil: bool) {
    unsafe {
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(target.id));
        gl.viewport(0, 0, target.width, target.height);
        gl.clear_color(0.0, 0.0, 0.0, 0.0);
        gl.clear(glow::COLOR_BUFFER_BIT);
        gl.enable(glow::CULL_FACE);
        gl.cull_face(glow::FRONT);
        gl.depth_mask(false);
        gl.enable(glow::BLEND);
        gl.blend_func(glow::ONE, glow::ONE);
        gl.enable(glow::DEPTH_TEST);
        gl.depth_func(glow::GEQUAL);
        gl.enable(glow::DEPTH_CLAMP);
        if stencil {
            gl.enable(glow::STENCIL_TEST);
            gl.clear_stencil(0);
            gl.clear(glow::STENCIL_BUFFER_BIT);
        }
    }
}

pub fn restore_volume_state(gl: &glow::Context) {
    unsafe {
        gl.disable(glow::STENCIL_TEST);
        gl.stencil_func(glow::ALWAYS, 0, 0xFF);
        gl.stencil_op(glow::KEEP, glow::KEEP, glow::KEEP);
        gl.disable(glow::DEPTH_CLAMP);
        gl.depth_func(glow::LESS);
        gl.disable(glow::DEPTH_TEST);
        gl.disable(glow::BLEND);
        gl.depth_mask(true);
        gl.cull_face(glow::BACK);
        gl.disable(glow::CULL_FACE);
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}

pub struct LightVolumes {
    program: Program,
}

impl LightVolumes {
    pub fn new(gl: &Gl, sources: &Sources, defines: &[(&str, String)]) -> Result<LightVolumes> {
        let program = Program::new(
            gl,
            sources,
            &[
                (glow::VERTEX_SHADER, "light_volumes.vert"),
                (glow::FRAGMENT_SHADER, "light_volumes.frag"),
            ],
            defines,
        )?;
        program.bind_uniform_block("Lights", 0);
        Ok(LightVolumes { program })
    }

    /// The lighting pass: one volume per light, additive, into `accumulation`
    /// (which shares the G-buffer's depth-stencil texture).
    pub fn lighting(
        &self,
        gl: &glow::Context,
        scene: &Scene,
        frame: &FrameUniforms,
        gbuffer: &GBuffer,
        accumulation: &Framebuffer,
        meshes: &VolumeMeshes,
    ) {
        volume_pass(
            gl,
            &self.program,
            scene,
            frame,
            gbuffer,
            accumulation,
            meshes,
        );
    }
}

/// A whole light-volume pass with program `p`: notes 04's state, the
/// G-buffer bound, every light's volume drawn, the state restored. The light
/// pre-pass (deferred_lighting.rs) runs the same pass with its own shader.
#[allow(clippy::too_many_arguments)]
pub fn volume_pass(
    gl: &glow::Context,
    p: &Program,
    scene: &Scene,
    frame: &FrameUniforms,
    gbuffer: &GBuffer,
    accumulation: &Framebuffer,
    meshes: &VolumeMeshes,
) {
    let stencil = scene.render.stencil_volumes;
    begin_volume_state(gl, accumulation, stencil);
    p.use_program();
    gbuffer.bind_for_lighting(gl, p, frame);
    unsafe { gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, Some(frame.lights_ubo)) };
    draw_volumes(gl, p, scene, frame, meshes, stencil);
    unsafe {
        gl.bind_buffer_base(glow::UNIFORM_BUFFER, 0, None);
        gl.use_program(None);
    }
    GBuffer::unbind_textures(gl, 4);
    restore_volume_state(gl);
}
