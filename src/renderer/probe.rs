//! The pixel probe: for one pixel of the frame just drawn, every value its
//! render targets hold (the G-buffer's normal, albedo, specular and
//! microfacet triple, the light accumulation, the AO, the output), its
//! depth and the view-space and world position that depth rebuilds, its
//! stencil, for each casting light the shadow-map lookup a lighting shader
//! made there (probe_shadow.rs), and on the light-volume and tiled paths the
//! lights that reach it. `gloss probe SCENE X Y` prints it; the demo shows
//! it beside a magnifier of the pixels around.
//!
//! Everything is read back with glReadPixels, one pixel at a time, from the
//! framebuffer that holds it: glReadBuffer(GL_COLOR_ATTACHMENTi) for a
//! colour, GL_DEPTH_COMPONENT and GL_STENCIL_INDEX for the depth-stencil
//! attachment. The read buffer is put back to attachment 0 and the read
//! framebuffer to 0 afterwards. Pixel coordinates are the image's: (0, 0)
//! is the top-left pixel, y grows downwards (GL's rows grow upwards).

use super::Renderer;
use super::probe_read::{read_color, read_depths, read_resolved, read_stencil, read_texture};
use super::probe_shadow::{ShadowProbe, probe_shadows};
pub use super::probe_tiles::TileLists;
use crate::frame::gbuffer::{NORMAL, OCTAHEDRAL};
use crate::frame::targets::Depth;
use crate::gl::framebuffer::Framebuffer;
use crate::scene::{Camera, LightKind};
use anyhow::{Result, bail};
use glam::{Vec3, Vec4};
use glow::HasContext;

/// The magnifier's reach: (2 R + 1)^2 pixels around the probed one.
pub const MAGNIFIER_RADIUS: i32 = 7;

/// Why a multisampled attachment is not read: one whose format a resolve
/// into a float or byte texture cannot take (an integer format).
const NOT_READ_MSAA: &str = "multisampled, in a format the probe's one-pixel resolve does not take; its resolved image is read with the target it resolves into";

/// One colour attachment's value at the pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetValue {
    /// "gbuffer.normal_shininess", as `gloss plan` names it.
    pub name: String,
    pub format: u32,
    /// As glReadPixels(GL_RGBA, GL_FLOAT) gives it: an sRGB attachment
    /// decoded to linear, an 8-bit one divided by 255.
    pub value: [f32; 4],
    /// How many channels the format has (1 for R16F, the AO).
    pub channels: usize,
}

/// What the probe found at one pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct Probe {
    /// The pixel, from the top left.
    pub x: u32,
    pub y: u32,
    /// The frame's size.
    pub size: (u32, u32),
    pub targets: Vec<TargetValue>,
    /// Window depth (0..1) of the frame's depth buffer; 1.0: nothing drawn.
    pub depth: Option<f32>,
    /// The point that depth rebuilds, in the camera's view space and in
    /// the world (None where nothing was drawn).
    pub view_position: Option<Vec3>,
    pub world_position: Option<Vec3>,
    /// The surface normal (world) and where it came from.
    pub normal: Option<(Vec3, &'static str)>,
    /// Each depth-stencil target's stencil value: (target, value).
    pub stencil: Vec<(String, u8)>,
    pub shadows: Vec<ShadowProbe>,
    /// On the light-volume and tiled paths: the lights that reach the
    /// point (within their radius, inside a spot light's cone; on the tiled
    /// path only those its cluster lists or every pixel shades).
    pub reached: Option<Vec<usize>>,
    /// On the tiled path: the pixel's cluster and its lists (probe_tiles.rs).
    pub tile: Option<TileLists>,
    /// The frame's targets not read at the pixel, each with why.
    pub not_read: Vec<(String, &'static str)>,
    /// The output's pixels around it, (2 R + 1) rows of (2 R + 1), top row
    /// first, as stored (sRGB-encoded bytes); outside the frame black.
    pub magnifier: Vec<[u8; 4]>,
}

impl Renderer {
    /// Probe pixel (`x`, `y`) (from the top left) of the frame last drawn
    /// with `camera`.
    pub fn probe(&self, camera: &Camera, x: u32, y: u32) -> Result<Probe> {
        let (w, h) = (self.width as u32, self.height as u32);
        if x >= w || y >= h {
            bail!(
                "pixel ({x}, {y}) is outside the {w}x{h} frame: x runs 0 to {}, y 0 to {} (from the top left)",
                w - 1,
                h - 1
            );
        }
        let gl = &self.gl;
        let mut targets = Vec::new();
        let mut stencil = Vec::new();
        let mut normal = None;
        let mut not_read = Vec::new();
        for desc in &self.plan.targets {
            // A multisampled target is read resolved, a ping-pong target's
            // two textures each through a framebuffer of its own; a mip
            // target's other levels are the inspector's (level 0 is read).
            let Some(fb) = self.targets.find(desc.name) else {
                continue;
            };
            let (tx, ty) = scaled(x, y, (w, h), (fb.width as u32, fb.height as u32));
            if desc.samples > 1 {
                // glReadPixels reads no multisampled framebuffer: each
                // attachment's pixel resolved (the mean of its samples) by
                // a one-pixel glBlitFramebuffer, then read.
                for (i, &(attachment, format)) in desc.colors.iter().enumerate() {
                    let name = format!("{}.{attachment}", desc.name);
                    match read_resolved(gl, fb, i as u32, format, tx, ty) {
                        Some(value) => targets.push(TargetValue {
                            name: format!(
                                "{name} (resolved: the mean of its {} samples)",
                                desc.samples
                            ),
                            format,
                            value,
                            channels: channels(format),
                        }),
                        None => not_read.push((name, NOT_READ_MSAA)),
                    }
                }
                continue;
            }
            if desc.ping_pong {
                // Both textures, each through a framebuffer of its own: step
                // s of the chain writes texture s % 2 (src/frame/post.rs).
                for (i, &(attachment, format)) in desc.colors.iter().enumerate() {
                    let value = read_texture(gl, &fb.colors[i], fb.height, tx, ty);
                    targets.push(TargetValue {
                        name: format!("{}.{attachment}", desc.name),
                        format,
                        value,
                        channels: channels(format),
                    });
                }
                continue;
            }
            for (i, &(attachment, format)) in desc.colors.iter().enumerate() {
                let value = read_color(gl, fb, i as u32, tx, ty);
                if (attachment, format) == NORMAL && normal.is_none() {
                    let n = Vec3::new(value[0], value[1], value[2]);
                    let source = "the G-buffer's normal_shininess.xyz";
                    normal = (n.length() > 0.5).then(|| (n.normalize(), source));
                }
                if (attachment, format) == OCTAHEDRAL && normal.is_none() {
                    let b = |c: f32| (c * 255.0).round() as u8;
                    let n =
                        crate::math::octahedral::unpack([b(value[0]), b(value[1]), b(value[2])]);
                    let source = "the G-buffer's normal_octahedral.rgb, decoded";
                    normal = Some((n, source));
                }
                targets.push(TargetValue {
                    name: format!("{}.{attachment}", desc.name),
                    format,
                    value,
                    channels: channels(format),
                });
            }
            if let Depth::Own(format) = desc.depth
                && format == glow::DEPTH24_STENCIL8
            {
                stencil.push((desc.name.to_string(), read_stencil(gl, fb, tx, ty)));
            }
        }
        let source = self.depth_source();
        let depth = source.map(|fb| read_depths(gl, fb, x, y, 0)[0]);
        let aspect = w as f32 / h as f32;
        let rebuild = Rebuild {
            camera,
            aspect,
            size: (w, h),
        };
        let view_position = depth.filter(|&d| d < 1.0).map(|d| rebuild.view(x, y, d));
        let world_position = view_position.map(|v| camera.view().inverse().transform_point3(v));
        if normal.is_none()
            && let (Some(fb), Some(p)) = (source, world_position)
        {
            normal = rebuild.normal_from_depth(gl, fb, x, y, p);
        }
        let tile = self.tile_lists(x, y, view_position);
        let shadows = match world_position {
            Some(p) => probe_shadows(self, p, normal.map_or(Vec3::ZERO, |n| n.0)),
            None => Vec::new(),
        };
        Ok(Probe {
            x,
            y,
            size: (w, h),
            targets,
            depth,
            view_position,
            world_position,
            normal,
            stencil,
            shadows,
            reached: self.reached(world_position, tile.as_ref()),
            tile,
            not_read,
            magnifier: self.magnifier(x, y),
        })
    }

    /// The lights that reach `p` on a path that picks lights per pixel
    /// (light volumes, stencil light volumes, tiled shading): the test each
    /// of those shaders makes; on the tiled path, of the lights its
    /// cluster's lists hold (`tile`).
    fn reached(&self, p: Option<Vec3>, tile: Option<&TileLists>) -> Option<Vec<usize>> {
        let per_pixel = (self.plan.passes.iter()).any(|pass| {
            let t = crate::techniques::ALL.get(pass.technique).map(|t| t.name);
            matches!(
                t,
                Some("light_volumes" | "stencil_light_volumes" | "tiled_shading")
            )
        });
        if !per_pixel {
            return None;
        }
        let Some(p) = p else {
            return Some(Vec::new());
        };
        let lights = self.scene.lights.iter().zip(&self.lights.lights);
        let shaded = |i: usize| {
            tile.is_none_or(|t| {
                t.listed.contains(&i) || t.global.contains(&i) || t.casters.contains(&i)
            })
        };
        let reach = lights.enumerate().filter(|&(i, _)| shaded(i));
        let reach = reach.filter(|(_, (l, f))| {
            let Some(r) = f.radius else { return true };
            let d = p - l.position;
            let inside = d.length() <= r;
            let cone = l.kind != LightKind::Spot
                || d.normalize_or_zero().dot(l.direction.normalize_or_zero())
                    >= l.outer_angle.to_radians().cos();
            inside && cone
        });
        Some(reach.map(|(i, _)| i).collect())
    }

    /// The output's pixels around (`x`, `y`), top row first.
    fn magnifier(&self, x: u32, y: u32) -> Vec<[u8; 4]> {
        let r = MAGNIFIER_RADIUS;
        let side = (2 * r + 1) as usize;
        let mut out = vec![[0u8; 4]; side * side];
        let (w, h) = (self.width, self.height);
        let (cx, cy) = (x as i32, h - 1 - y as i32);
        // The part of the square inside the frame, in GL rows.
        let (x0, x1) = ((cx - r).max(0), (cx + r).min(w - 1));
        let (y0, y1) = ((cy - r).max(0), (cy + r).min(h - 1));
        let (rw, rh) = (x1 - x0 + 1, y1 - y0 + 1);
        let mut raw = vec![0u8; (rw * rh * 4) as usize];
        let gl = &self.gl;
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.output().id));
            gl.read_buffer(glow::COLOR_ATTACHMENT0);
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            gl.read_pixels(
                x0,
                y0,
                rw,
                rh,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut raw)),
            );
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        }
        for gy in y0..=y1 {
            for gx in x0..=x1 {
                let i = (((gy - y0) * rw + (gx - x0)) * 4) as usize;
                // Row 0 of the square is its top: GL row cy + r.
                let (row, col) = ((cy + r - gy) as usize, (gx - cx + r) as usize);
                out[row * side + col] = [raw[i], raw[i + 1], raw[i + 2], 255];
            }
        }
        out
    }
}

/// (`x`, `y`) of a `full`-size frame in a target of `size` (a target at a
/// fraction of the frame, such as the far field's).
fn scaled(x: u32, y: u32, full: (u32, u32), size: (u32, u32)) -> (u32, u32) {
    let s = |v: u32, f: u32, t: u32| {
        ((u64::from(v) * u64::from(t) / u64::from(f.max(1))) as u32).min(t.max(1) - 1)
    };
    (s(x, full.0, size.0), s(y, full.1, size.1))
}

fn channels(format: u32) -> usize {
    match format {
        glow::R8 | glow::R16F | glow::R32F => 1,
        glow::RG8 | glow::RG16F | glow::RG32F => 2,
        glow::RGB8 | glow::RGB16F | glow::R11F_G11F_B10F => 3,
        _ => 4,
    }
}

/// Window depth back to the view space and world, for the frame's camera.
struct Rebuild<'a> {
    camera: &'a Camera,
    aspect: f32,
    size: (u32, u32),
}

impl Rebuild<'_> {
    /// The view-space point at pixel (`x`, `y`)'s centre and window depth
    /// `d`: normalised device coordinates (x, y from the pixel, z = 2 d - 1)
    /// through the inverse projection, then the divide by w.
    fn view(&self, x: u32, y: u32, d: f32) -> Vec3 {
        let (w, h) = (self.size.0 as f32, self.size.1 as f32);
        let ndc = Vec4::new(
            2.0 * (x as f32 + 0.5) / w - 1.0,
            1.0 - 2.0 * (y as f32 + 0.5) / h,
            2.0 * d - 1.0,
            1.0,
        );
        let v = self.camera.projection(self.aspect).inverse() * ndc;
        v.truncate() / v.w
    }

    fn world(&self, x: u32, y: u32, d: f32) -> Vec3 {
        (self.camera.view().inverse()).transform_point3(self.view(x, y, d))
    }

    /// Where no target holds a normal (the forward path): the cross product
    /// of the rebuilt points beside the pixel, the nearer of each pair
    /// (an edge's far side is another surface), turned to face the camera.
    fn normal_from_depth(
        &self,
        gl: &glow::Context,
        fb: &Framebuffer,
        x: u32,
        y: u32,
        p: Vec3,
    ) -> Option<(Vec3, &'static str)> {
        let d = read_depths(gl, fb, x, y, 1);
        let (w, h) = self.size;
        let at = |dx: i32, dy: i32| {
            let (nx, ny) = (x as i32 + dx, y as i32 + dy);
            let inside = nx >= 0 && ny >= 0 && (nx as u32) < w && (ny as u32) < h;
            let depth = d[((dy + 1) * 3 + dx + 1) as usize];
            (inside && depth < 1.0).then(|| self.world(nx as u32, ny as u32, depth))
        };
        let nearer = |a: Option<Vec3>, b: Option<Vec3>, sign: f32| match (a, b) {
            (Some(a), Some(b)) if (a - p).length() <= (b - p).length() => Some((a - p) * sign),
            (_, Some(b)) => Some(p - b),
            (Some(a), None) => Some((a - p) * sign),
            (None, None) => None,
        };
        // Right minus here, and here minus the pixel above.
        let dx = nearer(at(1, 0), at(-1, 0), 1.0)?;
        let dy = nearer(at(0, -1), at(0, 1), 1.0)?;
        let n = dx.cross(dy).try_normalize()?;
        let to_eye = self.camera.eye - p;
        let n = if n.dot(to_eye) < 0.0 { -n } else { n };
        Some((n, "rebuilt from the depth of the pixels beside it"))
    }
}
