//! Reading the finished frame back: as an 8-bit sRGB image (PNG order) or
//! as linear floats (for error measurements).

use super::Renderer;
use crate::frame::multisample;
use crate::frame::plan::FramePlan;
use crate::frame::targets::{OUTPUT, TargetDesc};
use crate::lighting;

/// How the final image is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// RGBA8 holding sRGB-encoded colour: what PNGs and the window show.
    Srgb8,
    /// RGBA32F holding linear colour: for error measurements.
    Linear32F,
}

impl Output {
    /// The output target's colour format.
    pub fn format(self) -> u32 {
        match self {
            Output::Srgb8 => glow::RGBA8,
            Output::Linear32F => glow::RGBA32F,
        }
    }
}

/// The stencil inspector's picture: value 0 black, each other value its own
/// colour (hues a golden angle apart, so neighbouring values differ), top row
/// first as `Renderer::read_stencil` gives them.
pub fn stencil_image(values: &[u8], width: u32, height: u32) -> image::RgbaImage {
    image::RgbaImage::from_fn(width, height, |x, y| {
        let v = values[(y * width + x) as usize];
        image::Rgba(stencil_color(v))
    })
}

/// The colour of stencil value `v` in the inspector.
pub fn stencil_color(v: u8) -> [u8; 4] {
    if v == 0 {
        return [0, 0, 0, 255];
    }
    let hue = (f32::from(v) * 137.508).rem_euclid(360.0) / 60.0;
    let x = 1.0 - (hue.rem_euclid(2.0) - 1.0).abs();
    let (r, g, b) = match hue as u32 {
        0 => (1.0, x, 0.0),
        1 => (x, 1.0, 0.0),
        2 => (0.0, 1.0, x),
        3 => (0.0, x, 1.0),
        4 => (x, 0.0, 1.0),
        _ => (1.0, 0.0, x),
    };
    let c = |c: f32| (55.0 + 200.0 * c) as u8;
    [c(r), c(g), c(b), 255]
}

impl Renderer {
    /// The output as an sRGB PNG-ready image (top row first).
    pub fn read_image(&self) -> image::RgbaImage {
        match self.output_kind {
            Output::Srgb8 => self.output().read_rgba8_top_down(0),
            Output::Linear32F => {
                let f = self.output().read_rgba_f32(0);
                let (w, h) = (self.width as u32, self.height as u32);
                let px = |c: f32| (lighting::srgb_encode(c) * 255.0).round() as u8;
                image::RgbaImage::from_fn(w, h, |x, y| {
                    let i = (((h - 1 - y) * w + x) * 4) as usize;
                    image::Rgba([px(f[i]), px(f[i + 1]), px(f[i + 2]), 255])
                })
            }
        }
    }

    /// The finished frame's window depth, 0..1, bottom row first (what
    /// glReadPixels gives): the shadow tests find each pixel's surface
    /// point from it. A deferred frame whose world image has no depth
    /// buffer (nothing after the composite needs one) gives the G-buffer's,
    /// which the composite would have copied.
    pub fn read_depth(&self) -> Vec<f32> {
        match self.depth_source() {
            Some(fb) => fb.read_depth_f32(),
            None => vec![1.0; (self.width * self.height) as usize],
        }
    }

    /// Where the frame's depth is: the world image's depth buffer, else
    /// the G-buffer's; None when neither exists (a frame with nothing).
    pub(super) fn depth_source(&self) -> Option<&crate::gl::framebuffer::Framebuffer> {
        let has = |fb: &crate::gl::framebuffer::Framebuffer| {
            fb.depth_stencil.is_some() || fb.shared_depth.is_some()
        };
        let world = self.world();
        if has(world) {
            return Some(world);
        }
        self.targets
            .find(crate::frame::gbuffer::NAME)
            .filter(|g| has(g))
    }

    /// The output's stencil buffer, one value per pixel, top row first
    /// (the stencil inspector; mirrors mark their regions there).
    /// A world image without a depth-stencil buffer (a deferred frame with
    /// no pass after the composite) has marked nothing: all 0.
    pub fn read_stencil(&self) -> Vec<u8> {
        let world = self.world();
        if world.depth_stencil.is_none() && world.shared_depth.is_none() {
            return vec![0; (self.width * self.height) as usize];
        }
        world.read_stencil_top_down()
    }

    /// Render a frame and return the output's stencil buffer as it was
    /// right after pass number `pass` (1-based, as `gloss plan` numbers
    /// them).
    pub fn stencil_after(
        &mut self,
        camera: &crate::scene::Camera,
        pass: usize,
    ) -> anyhow::Result<Vec<u8>> {
        let count = self.plan.passes.len();
        if pass == 0 || pass > count {
            anyhow::bail!(
                "--after {pass}: the frame has passes 1 to {count} (gloss plan lists them)"
            );
        }
        let (gl, fb) = (self.gl.clone(), self.world().id);
        let (w, h) = (self.width, self.height);
        let world = self.world();
        if world.depth_stencil.is_none() && world.shared_depth.is_none() {
            // No stencil buffer in this frame's world image: nothing marked.
            return Ok(vec![0; (w * h) as usize]);
        }
        let (mut n, mut stencil) = (0, Vec::new());
        self.render_inspected(camera, &mut |_| {
            n += 1;
            if n == pass {
                stencil = crate::gl::framebuffer::read_stencil_top_down(&gl, fb, w, h);
            }
        })?;
        Ok(stencil)
    }

    /// The output as linear RGBA floats, bottom row first (Linear32F output only
    /// gives the unquantised values).
    pub fn read_linear(&self) -> Vec<f32> {
        let f = self.output().read_rgba_f32(0);
        match self.output_kind {
            Output::Linear32F => f,
            Output::Srgb8 => f
                .chunks(4)
                .flat_map(|p| {
                    [
                        lighting::srgb_decode(p[0]),
                        lighting::srgb_decode(p[1]),
                        lighting::srgb_decode(p[2]),
                        p[3],
                    ]
                })
                .collect(),
        }
    }
}

impl Renderer {
    /// Attachment `name` of a render target at the end of the frame (`gloss
    /// render --target`): "gbuffer.albedo", or "hdr" for a target's first
    /// colour attachment, as `gloss plan` names them. Made visible as an
    /// 8-bit picture, top row first: a normal as (n + 1) / 2; light (a float
    /// attachment other than the data ones) sRGB-encoded and clamped to 1;
    /// data (gAlpha, gConvert, the AO) and 8-bit attachments as stored, one
    /// channel as grey.
    pub fn read_target(&self, name: &str) -> anyhow::Result<image::RgbaImage> {
        let (target, attachment) = match name.split_once('.') {
            Some((t, a)) => (t, Some(a)),
            None => (name, None),
        };
        let all: Vec<&str> = self.plan.targets.iter().map(|t| t.name).collect();
        let Some(desc) = self.plan.targets.iter().find(|t| t.name == target) else {
            anyhow::bail!(
                "--target {name}: this frame has no target {target:?}; it has {}",
                all.join(", ")
            );
        };
        let attachments: Vec<&str> = desc.colors.iter().map(|c| c.0).collect();
        let index = match attachment {
            None if !attachments.is_empty() => 0,
            None => anyhow::bail!("--target {name}: {target} has no colour attachment"),
            Some(a) => attachments.iter().position(|x| *x == a).ok_or_else(|| {
                anyhow::anyhow!(
                    "--target {name}: {target} has the attachments {}",
                    attachments.join(", ")
                )
            })?,
        };
        let Some(fb) = self.targets.find(target) else {
            anyhow::bail!(
                "--target {name}: {target} keeps its images in mip levels (the bloom's): \
                 name one, such as {target}.1 (the demo's inspector draws it)"
            );
        };
        let (attachment, format) = desc.colors[index];
        let data = fb.read_rgba_f32(index as u32);
        let (w, h) = (fb.width as u32, fb.height as u32);
        let normal = attachment.starts_with("normal");
        let stored = ["alpha", "convert", "ao"].contains(&attachment);
        let float = !stored
            && matches!(
                format,
                glow::RGBA16F | glow::RGBA32F | glow::R16F | glow::R32F | glow::RG16F
            );
        let grey = matches!(format, glow::R16F | glow::R32F | glow::R8);
        Ok(image::RgbaImage::from_fn(w, h, |x, y| {
            let i = (((h - 1 - y) * w + x) * 4) as usize;
            let mut c = [data[i], data[i + 1], data[i + 2]];
            if grey {
                c = [c[0]; 3];
            }
            let c = c.map(|v| {
                let v = if normal {
                    v * 0.5 + 0.5
                } else if float {
                    lighting::srgb_encode(v)
                } else {
                    v
                };
                (v.clamp(0.0, 1.0) * 255.0).round() as u8
            });
            image::Rgba([c[0], c[1], c[2], 255])
        }))
    }
}

/// The plan's targets, with the output's colour format as `output` asks
/// (and its multisampled twin's, which is resolved into it).
pub(super) fn target_descs(plan: &FramePlan, output: Output) -> Vec<TargetDesc> {
    let mut descs = plan.targets.clone();
    let twin = multisample::twins_output(&plan.targets);
    for d in &mut descs {
        // The plan says RGBA8 or SRGB8_ALPHA8; error measurements want RGBA32F.
        if d.name == OUTPUT && output == Output::Linear32F {
            d.colors[0].1 = output.format();
        }
    }
    let format = (descs.iter().find(|d| d.name == OUTPUT)).map(|d| d.colors[0].1);
    for d in &mut descs {
        if let (true, Some(format)) = (d.name == multisample::MSAA && twin, format) {
            d.colors[0].1 = format;
        }
    }
    descs
}

/// The plan's render targets for `output`, once the frame budget
/// (src/frame/budget.rs) has checked every texture against this GL's
/// limits and the memory budget, and the light maps' bake against its work
/// limit: before any of it is made.
pub(super) fn checked_targets(
    gl: &crate::gl::Gl,
    scene: &crate::scene::Scene,
    plan: &crate::frame::plan::FramePlan,
    output: Output,
    (width, height): (i32, i32),
) -> anyhow::Result<Vec<crate::frame::targets::TargetDesc>> {
    let descs = target_descs(plan, output);
    let limits = crate::frame::budget::GlLimits::query(gl);
    crate::frame::budget::check(scene, &descs, width as u32, height as u32, Some(&limits))?;
    Ok(descs)
}
