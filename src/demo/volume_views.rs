//! The light volumes made visible (notes 04): as wireframes in each light's
//! colour over the final image; as notes 04's debug view, each volume solid
//! red over the G-buffer's albedo; and as the overdraw count, how many
//! volumes cover each pixel (back faces counted with additive blending into
//! a float target, then shown as a heat map).

use super::inspector::{Inspector, Mode};
use crate::frame::lights::Volume;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::{Program, Sources};
use crate::renderer::Renderer;
use crate::scene::Camera;
use anyhow::Result;
use glam::{Mat4, Vec4};
use glow::HasContext;

pub use super::inspect_views::VolumeView;

pub struct VolumeViews {
    program: Program,
    /// The overdraw count (RGBA16F), the renderer's size.
    count: Option<Framebuffer>,
    /// The stencil light volumes' marks (stencil_marks.rs).
    pub(super) mark_fb: Option<Framebuffer>,
}

impl VolumeViews {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<VolumeViews> {
        Ok(VolumeViews {
            program: Program::new(
                gl,
                sources,
                &[
                    (glow::VERTEX_SHADER, "deferred/light_volumes.vert"),
                    (glow::FRAGMENT_SHADER, "demo/volume_debug.frag"),
                ],
                &[],
            )?,
            count: None,
            mark_fb: None,
        })
    }

    /// The overdraw count of the last Overdraw view (red: volumes per pixel).
    pub fn count(&self) -> Option<&Framebuffer> {
        self.count.as_ref()
    }

    /// Draw `view` of the renderer's last frame into `into`.
    pub fn draw(
        &mut self,
        gl: &Gl,
        view: VolumeView,
        renderer: &Renderer,
        camera: &Camera,
        inspector: &Inspector,
        into: &Framebuffer,
    ) -> Result<()> {
        let vp = renderer
            .frame_uniforms(camera, &crate::frame::views::View::camera())
            .view_projection;
        match view {
            VolumeView::Wireframe => {
                blit(gl, renderer.output(), into);
                unsafe {
                    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(into.id));
                    gl.viewport(0, 0, into.width, into.height);
                    gl.polygon_mode(glow::FRONT_AND_BACK, glow::LINE);
                }
                self.volumes(gl, renderer, vp, |l| {
                    let c = l.color / l.color.max_element().max(1e-6);
                    Vec4::new(c.x, c.y, c.z, 1.0)
                });
                unsafe {
                    gl.polygon_mode(glow::FRONT_AND_BACK, glow::FILL);
                    gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                }
            }
            VolumeView::Debug => {
                match renderer
                    .targets()
                    .find("gbuffer")
                    .and_then(|g| g.colors.get(1))
                {
                    Some(albedo) => inspector.draw_texture(
                        gl,
                        Some(albedo.id),
                        Mode::Color { encode: true },
                        camera,
                        1.0,
                        into,
                    ),
                    None => blit(gl, renderer.output(), into),
                }
                unsafe {
                    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(into.id));
                    gl.viewport(0, 0, into.width, into.height);
                    gl.enable(glow::BLEND);
                    gl.blend_func(glow::SRC_ALPHA, glow::ONE_MINUS_SRC_ALPHA);
                    gl.enable(glow::CULL_FACE);
                    gl.cull_face(glow::FRONT);
                }
                self.volumes(gl, renderer, vp, |_| Vec4::new(1.0, 0.0, 0.0, 0.35));
                unsafe {
                    gl.cull_face(glow::BACK);
                    gl.disable(glow::CULL_FACE);
                    gl.blend_func(glow::ONE, glow::ZERO);
                    gl.disable(glow::BLEND);
                    gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                }
            }
            VolumeView::Overdraw => {
                let size = (into.width, into.height);
                if self.count.as_ref().map(|f| (f.width, f.height)) != Some(size) {
                    self.count = None;
                    self.count = Some(Framebuffer::new(
                        gl,
                        "volume count",
                        size.0,
                        size.1,
                        &[glow::RGBA16F],
                        None,
                    )?);
                }
                let count = self.count.as_ref().expect("made above");
                unsafe {
                    gl.bind_framebuffer(glow::FRAMEBUFFER, Some(count.id));
                    gl.viewport(0, 0, count.width, count.height);
                    gl.clear_color(0.0, 0.0, 0.0, 0.0);
                    gl.clear(glow::COLOR_BUFFER_BIT);
                    gl.enable(glow::BLEND);
                    gl.blend_func(glow::ONE, glow::ONE);
                    // A convex volume's back faces cover each pixel once.
                    gl.enable(glow::CULL_FACE);
                    gl.cull_face(glow::FRONT);
                    gl.enable(glow::DEPTH_CLAMP);
                }
                let n = self.volumes(gl, renderer, vp, |_| Vec4::new(1.0, 0.0, 0.0, 0.0));
                unsafe {
                    gl.disable(glow::DEPTH_CLAMP);
                    gl.cull_face(glow::BACK);
                    gl.disable(glow::CULL_FACE);
                    gl.blend_func(glow::ONE, glow::ZERO);
                    gl.disable(glow::BLEND);
                    gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                }
                let scale = (n as f32).clamp(1.0, 32.0);
                inspector.draw_texture(
                    gl,
                    Some(count.colors[0].id),
                    Mode::Count { scale },
                    camera,
                    1.0,
                    into,
                );
            }
            VolumeView::Marks => {
                let (w, h) = (renderer.width as u32, renderer.height as u32);
                let values =
                    (self.marks(gl, renderer, vp)?).unwrap_or_else(|| vec![0; (w * h) as usize]);
                let img = crate::renderer::stencil_image(&values, w, h);
                let img = image::imageops::flip_vertical(&img);
                let texture = crate::gl::texture::Texture::from_rgba8(
                    gl,
                    w,
                    h,
                    img.as_raw(),
                    false,
                    crate::gl::texture::Sampling::NEAREST_CLAMP,
                )?;
                inspector.draw_texture(
                    gl,
                    Some(texture.id),
                    Mode::Color { encode: false },
                    camera,
                    1.0,
                    into,
                );
            }
        }
        Ok(())
    }

    /// Draw each bounded light's volume in `color(light)` into the bound
    /// framebuffer; returns how many were drawn.
    pub(super) fn volumes(
        &self,
        gl: &glow::Context,
        renderer: &Renderer,
        vp: Mat4,
        color: impl Fn(&crate::scene::Light) -> Vec4,
    ) -> usize {
        let p = &self.program;
        let meshes = renderer.meshes();
        p.use_program();
        let mut n = 0;
        for (light, f) in renderer.scene.lights.iter().zip(&renderer.lights().lights) {
            let (mesh, model) = match f.volume {
                Volume::Sphere(m) => (&meshes.volume_sphere, m),
                Volume::Cone(m) => (&meshes.volume_cone, m),
                Volume::FullScreen => continue,
            };
            p.set_vec4("u_color", color(light));
            p.set_mat4("u_mvp", &(vp * model));
            mesh.draw();
            n += 1;
        }
        unsafe { gl.use_program(None) };
        n
    }
}

/// Copy `from`'s colour to `into`, same size.
fn blit(gl: &glow::Context, from: &Framebuffer, into: &Framebuffer) {
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(from.id));
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(into.id));
        gl.blit_framebuffer(
            0,
            0,
            from.width,
            from.height,
            0,
            0,
            into.width,
            into.height,
            glow::COLOR_BUFFER_BIT,
            glow::NEAREST,
        );
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
    }
}
