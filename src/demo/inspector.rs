//! The pass inspector: any attachment of the frame plan's render targets,
//! drawn over the window so that it can be seen (normals as colours, depth
//! linearised, light with an exposure), by a full-screen pass with
//! glsl/demo/inspect.frag. The list of views comes from the plan, so a
//! technique's targets appear here as soon as it declares them; each
//! casting light's shadow map is listed too (src/demo/shadow_views.rs).

use super::shadow_views::ShadowView;
use super::volume_views::VolumeView;
use crate::frame::plan::FramePlan;
use crate::frame::targets::{Depth, Targets, format_name};
use crate::geometry;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mesh::Mesh;
use crate::gl::program::{Program, Sources};
use crate::scene::{Camera, Projection};
use anyhow::Result;
use glam::Mat4;
use glow::HasContext;

/// How an attachment is made visible (glsl/demo/inspect.frag's u_mode).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mode {
    /// Colour as stored; `encode`: linear colour, sRGB-encode it.
    Color {
        encode: bool,
    },
    Normal,
    Shininess,
    /// HDR light, scaled by the exposure.
    Light,
    Depth,
    /// A count, as a heat map from 0 to `scale`.
    Count {
        scale: f32,
    },
}

/// One view the inspector offers.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    pub target: &'static str,
    pub attachment: &'static str,
    /// None: the depth-stencil attachment.
    pub color_index: Option<usize>,
    pub format: u32,
    pub mode: Mode,
    /// A view of the light volumes instead of an attachment.
    pub volumes: Option<VolumeView>,
    /// The difference image of "compare with reference" instead of an attachment.
    pub difference: bool,
    /// The stencil values of the depth-stencil attachment (read back: GL 3.3
    /// cannot sample stencil), each value its own colour.
    pub stencil: bool,
    /// A casting light's shadow map instead of an attachment.
    pub shadow: Option<ShadowView>,
}

impl View {
    /// Whether two views show the same thing. A shadow map stays its
    /// light's map when its resolution changes.
    pub fn same_as(&self, other: &View) -> bool {
        let key = |v: &View| {
            let shadow = v.shadow.map(|s| s.light);
            (
                v.target,
                v.attachment,
                v.color_index,
                v.volumes,
                v.difference,
                v.stencil,
                shadow,
            )
        };
        key(self) == key(other)
    }

    /// "gbuffer.normal_shininess (RGBA16F)" and what the view shows.
    pub fn label(&self) -> String {
        if let Some(v) = self.volumes {
            return v.label().to_string();
        }
        if let Some(s) = &self.shadow {
            return s.label();
        }
        if self.difference {
            return "difference to the forward reference, x8".to_string();
        }
        if self.stencil {
            return format!(
                "{}.stencil ({}): each value its own colour, 0 black",
                self.target,
                format_name(self.format)
            );
        }
        let shows = match self.mode {
            Mode::Color { .. } => "colour",
            Mode::Normal => "normal x 0.5 + 0.5",
            Mode::Shininess => "shininess / 256",
            Mode::Light => "light x exposure",
            Mode::Depth => "depth, linearised",
            Mode::Count { .. } => "count, as a heat map",
        };
        format!(
            "{}.{} ({}): {shows}",
            self.target,
            self.attachment,
            format_name(self.format)
        )
    }
}

/// Every view of a frame: the shadow map of each casting light (`shadows`:
/// drawn first in the frame), the plan's targets in the plan's order; then,
/// when some light has a volume, the three views of the volumes.
pub fn views(plan: &FramePlan, has_volumes: bool, shadows: &[ShadowView]) -> Vec<View> {
    let mut v: Vec<View> = (shadows.iter())
        .map(|s| View {
            target: "shadow map",
            attachment: "depth",
            color_index: None,
            format: crate::gl::depth_map::FORMAT,
            mode: Mode::Depth,
            volumes: None,
            difference: false,
            stencil: false,
            shadow: Some(*s),
        })
        .collect();
    for t in &plan.targets {
        // A multisampled target (MSAA) cannot be sampled as a sampler2D: its
        // resolved image is the world's target, shown with it.
        if t.samples > 1 {
            continue;
        }
        for (i, &(name, format)) in t.colors.iter().enumerate() {
            let color = |mode| View {
                target: t.name,
                attachment: name,
                color_index: Some(i),
                format,
                mode,
                volumes: None,
                difference: false,
                stencil: false,
                shadow: None,
            };
            match name {
                "normal_shininess" => {
                    v.push(color(Mode::Normal));
                    v.push(View {
                        attachment: "shininess",
                        ..color(Mode::Shininess)
                    });
                }
                _ if matches!(format, glow::RGBA16F | glow::RGBA32F) => v.push(color(Mode::Light)),
                _ => v.push(color(Mode::Color {
                    encode: format == glow::SRGB8_ALPHA8,
                })),
            }
        }
        if let Depth::Own(format) = t.depth {
            v.push(View {
                target: t.name,
                attachment: "depth",
                color_index: None,
                format,
                mode: Mode::Depth,
                volumes: None,
                difference: false,
                stencil: false,
                shadow: None,
            });
            // The output's stencil: where mirrors mark their regions.
            if format == glow::DEPTH24_STENCIL8 && t.name == crate::frame::targets::OUTPUT {
                v.push(View {
                    target: t.name,
                    attachment: "stencil",
                    color_index: None,
                    format,
                    mode: Mode::Color { encode: false },
                    volumes: None,
                    difference: false,
                    stencil: true,
                    shadow: None,
                });
            }
        }
    }
    if has_volumes {
        for which in [
            VolumeView::Wireframe,
            VolumeView::Debug,
            VolumeView::Overdraw,
        ] {
            v.push(View {
                target: "light volumes",
                attachment: which.label(),
                color_index: None,
                format: 0,
                mode: Mode::Color { encode: false },
                volumes: Some(which),
                difference: false,
                stencil: false,
                shadow: None,
            });
        }
    }
    v
}

pub struct Inspector {
    program: Program,
    fullscreen: Mesh,
}

impl Inspector {
    pub fn new(gl: &Gl, sources: &Sources) -> Result<Inspector> {
        Ok(Inspector {
            program: Program::new(
                gl,
                sources,
                &[
                    (glow::VERTEX_SHADER, "common/fullscreen.vert"),
                    (glow::FRAGMENT_SHADER, "demo/inspect.frag"),
                ],
                &[],
            )?,
            fullscreen: Mesh::upload(gl, &geometry::fullscreen_triangle())?,
        })
    }

    /// Draw `view` (an attachment) into `into` (its own framebuffer, never
    /// one of the renderer's targets), full size.
    pub fn draw(
        &self,
        gl: &glow::Context,
        view: &View,
        targets: &Targets,
        camera: &Camera,
        exposure: f32,
        into: &Framebuffer,
    ) {
        let Some(fb) = targets.find(view.target) else {
            return;
        };
        let texture = match view.color_index {
            Some(i) => fb.colors.get(i).map(|t| t.id),
            None => fb.depth_stencil.as_ref().map(|t| t.id),
        };
        self.draw_texture(gl, texture, view.mode, camera, exposure, into);
    }

    /// Draw `texture` made visible by `mode` into `into`, full size.
    pub fn draw_texture(
        &self,
        gl: &glow::Context,
        texture: Option<glow::Texture>,
        mode: Mode,
        camera: &Camera,
        exposure: f32,
        into: &Framebuffer,
    ) {
        let p = &self.program;
        let (index, encode, scale) = match mode {
            Mode::Color { encode } => (0, encode, 1.0),
            Mode::Normal => (1, false, 1.0),
            Mode::Shininess => (2, false, 1.0),
            Mode::Light => (3, false, 1.0),
            Mode::Depth => (4, false, 1.0),
            Mode::Count { scale } => (5, false, scale),
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(into.id));
            gl.viewport(0, 0, into.width, into.height);
            gl.disable(glow::DEPTH_TEST);
            p.use_program();
            gl.active_texture(glow::TEXTURE0);
            gl.bind_texture(glow::TEXTURE_2D, texture);
            p.set_i32("u_texture", 0);
            p.set_i32("u_mode", index);
            p.set_bool("u_encode", encode);
            p.set_f32("u_exposure", exposure);
            p.set_f32("u_scale", scale);
            p.set_f32("u_near", camera.near);
            p.set_f32("u_far", camera.far);
            p.set_bool(
                "u_orthographic",
                matches!(camera.projection, Projection::Orthographic { .. }),
            );
            p.set_vec2(
                "u_viewport",
                glam::Vec2::new(into.width as f32, into.height as f32),
            );
            p.set_mat4("u_mvp", &Mat4::IDENTITY);
            self.fullscreen.draw();
            gl.bind_texture(glow::TEXTURE_2D, None);
            gl.use_program(None);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}

/// The inspected view, kept by what it shows rather than by its place in the
/// list: adding or removing a caster shifts every view after it. `index` is
/// the panel's choice and `kept` the view it showed last frame (None just
/// after a new choice). Returns the index to show, None when the view has
/// gone, and makes `kept` that view.
pub fn follow(index: Option<usize>, kept: &mut Option<View>, views: &[View]) -> Option<usize> {
    let found = match (index, kept.as_ref()) {
        (None, _) => None,
        (Some(i), Some(k)) if !views.get(i).is_some_and(|v| v.same_as(k)) => {
            views.iter().position(|v| v.same_as(k))
        }
        (Some(i), _) => (i < views.len()).then_some(i),
    };
    *kept = found.map(|i| views[i].clone());
    found
}
