//! Render targets: the plan describes them (`TargetDesc`), `Targets`
//! allocates exactly those, at the frame's size, and passes find them by
//! name. A target may attach another target's depth-stencil texture (the
//! light accumulation target tests its volumes against the G-buffer's depth),
//! so targets are made in the plan's order.

use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::mip_target::MipTarget;
use crate::gl::texture::{Texture, level_size, max_level};
use anyhow::{Result, anyhow};
use glow::HasContext;

/// The final image: the window shows it, `gloss render` writes it.
pub const OUTPUT: &str = "output";
/// Where lighting passes add up light (HDR, black clear).
pub const LIGHT_ACCUMULATION: &str = "light_accumulation";
/// The lit scene, linear and unclamped, when a post chain follows.
pub const HDR: &str = "hdr";
/// The HDR target's colour format: half floats hold light up to 65504 with
/// 11 significant bits (0.05 % steps), which 8 bits (and 256 lights adding
/// up past 1.0) cannot; 32-bit floats would double the bandwidth of every
/// post pass for precision no display shows.
pub const HDR_FORMAT: u32 = glow::RGBA16F;

/// A target's depth attachment.
#[derive(Clone, Debug, PartialEq)]
pub enum Depth {
    None,
    /// Its own depth-stencil texture of this format.
    Own(u32),
    /// The depth-stencil texture of the named (earlier) target.
    SharedWith(&'static str),
}

/// A render target as the plan names it.
#[derive(Clone, Debug, PartialEq)]
pub struct TargetDesc {
    pub name: &'static str,
    /// Samples per pixel: 1, or more for a multisampled target (MSAA,
    /// src/frame/multisample.rs), clamped to what the GL allows when made.
    pub samples: u32,
    /// (attachment name, GL internal format), GL_COLOR_ATTACHMENT0 first.
    pub colors: Vec<(&'static str, u32)>,
    pub depth: Depth,
    /// Its colour textures take turns at GL_COLOR_ATTACHMENT0 (the post
    /// chain's ping-pong framebuffer, src/frame/post.rs): only the first is
    /// attached when it is made.
    pub ping_pong: bool,
    /// A texture with mip levels `first..=last` of the frame size, one
    /// framebuffer per level (src/gl/mip_target.rs; bloom's four blurs,
    /// notes 03). Levels the frame is too small for are left out: a 3x2
    /// frame has level 1 only, a 1x1 frame none (then there is no target).
    /// None: one level, the frame size.
    pub mips: Option<(u32, u32)>,
    /// 1: the frame size; k: 1/k of it each way, rounded up (the far
    /// field, tiled_shading's low-resolution pass). Not with `mips`.
    pub downscale: u32,
}

impl TargetDesc {
    /// The final image: 8-bit colour holding encoded values, and depth
    /// (none when a post chain draws it: the world's depth is the HDR
    /// target's). `format` is RGBA8, or SRGB8_ALPHA8 when the chain's gamma
    /// pass leaves the encoding to GL_FRAMEBUFFER_SRGB.
    pub fn output(format: u32, depth: bool) -> TargetDesc {
        TargetDesc {
            name: OUTPUT,
            samples: 1,
            colors: vec![("color", format)],
            depth: if depth {
                Depth::Own(glow::DEPTH24_STENCIL8)
            } else {
                Depth::None
            },
            ping_pong: false,
            mips: None,
            downscale: 1,
        }
    }

    /// The bytes its textures take at `width` x `height`: every colour
    /// texture (both of a ping-pong pair), its own depth-stencil (a shared
    /// one is counted where it is owned), every sample, and for a mip target
    /// levels 0..=last (all are allocated; the levels below `first` are
    /// never drawn). What the GL is asked for: a driver may pad it.
    pub fn bytes(&self, width: u32, height: u32) -> u64 {
        let pixels: u64 = match self.mips {
            Some((_, last)) => (0..=last)
                .map(|l| {
                    let (w, h) = level_size(width as i32, height as i32, l);
                    w as u64 * h as u64
                })
                .sum(),
            None => {
                let (w, h) = scaled_size(width as i32, height as i32, self.downscale);
                w as u64 * h as u64
            }
        };
        let colors: u64 = self.colors.iter().map(|&(_, f)| bytes_per_pixel(f)).sum();
        let depth = match self.depth {
            Depth::Own(f) => bytes_per_pixel(f),
            Depth::None | Depth::SharedWith(_) => 0,
        };
        pixels * (colors + depth) * u64::from(self.samples.max(1))
    }

    /// The bytes of each of its textures at `width` x `height` (a mip
    /// target's chain is one texture): what one allocation asks for.
    pub fn single_textures(&self, width: u32, height: u32) -> Vec<u64> {
        let whole = self.bytes(width, height);
        let per_pixel: u64 = (self.colors.iter().map(|&(_, f)| bytes_per_pixel(f)))
            .chain(match self.depth {
                Depth::Own(f) => Some(bytes_per_pixel(f)),
                _ => None,
            })
            .sum();
        if per_pixel == 0 {
            return Vec::new();
        }
        let colors = self.colors.iter().map(|&(_, f)| bytes_per_pixel(f));
        let depth = match self.depth {
            Depth::Own(f) => Some(bytes_per_pixel(f)),
            _ => None,
        };
        colors.chain(depth).map(|b| whole / per_pixel * b).collect()
    }

    /// Every attachment as "name:FORMAT", depth last.
    pub fn attachments(&self) -> Vec<String> {
        let mut v: Vec<String> = self
            .colors
            .iter()
            .map(|(n, f)| format!("{n}:{}", format_name(*f)))
            .collect();
        match self.depth {
            Depth::None => {}
            Depth::Own(f @ (glow::DEPTH24_STENCIL8 | glow::DEPTH32F_STENCIL8)) => {
                v.push(format!("depth_stencil:{}", format_name(f)))
            }
            Depth::Own(f) => v.push(format!("depth:{}", format_name(f))),
            Depth::SharedWith(t) => v.push(format!("depth_stencil:{t}'s")),
        }
        if let Some((first, last)) = self.mips {
            v.push(format!("mip levels {first}..={last}, one framebuffer each"));
        }
        if self.samples > 1 {
            v.push(format!("{} samples", self.samples));
        }
        if self.downscale > 1 {
            v.push(format!("1/{} of the frame each way", self.downscale));
        }
        v
    }
}

/// `width` x `height` divided by `k` each way, rounded up (at least 1x1).
pub fn scaled_size(width: i32, height: i32, k: u32) -> (i32, i32) {
    let k = k.max(1) as i32;
    (((width + k - 1) / k).max(1), ((height + k - 1) / k).max(1))
}

/// The bytes a pixel of an internal format gloss uses takes.
pub fn bytes_per_pixel(format: u32) -> u64 {
    match format {
        glow::RGBA16F => 8,
        glow::RGBA32F => 16,
        glow::DEPTH32F_STENCIL8 => 8,
        // The ambient occlusion (techniques/deferred/ambient_light.rs).
        glow::R16F => 2,
        // RGBA8, SRGB8_ALPHA8, DEPTH24_STENCIL8, DEPTH_COMPONENT24 (padded
        // to 32 bits), DEPTH_COMPONENT32F.
        _ => 4,
    }
}

/// "1.46 MiB", "900 KiB", "12 bytes".
pub fn size_name(bytes: u64) -> String {
    match bytes {
        b if b >= 1 << 20 => format!("{:.2} MiB", b as f64 / f64::from(1 << 20)),
        b if b >= 1 << 10 => format!("{:.0} KiB", b as f64 / 1024.0),
        b => format!("{b} bytes"),
    }
}

/// The GL name of an internal format gloss uses.
pub fn format_name(format: u32) -> &'static str {
    match format {
        glow::RGBA8 => "RGBA8",
        glow::SRGB8_ALPHA8 => "SRGB8_ALPHA8",
        glow::RGBA16F => "RGBA16F",
        glow::RGBA32F => "RGBA32F",
        glow::R16F => "R16F",
        glow::R32F => "R32F",
        glow::DEPTH32F_STENCIL8 => "DEPTH32F_STENCIL8",
        glow::DEPTH24_STENCIL8 => "DEPTH24_STENCIL8",
        glow::DEPTH_COMPONENT24 => "DEPTH_COMPONENT24",
        glow::DEPTH_COMPONENT32F => "DEPTH_COMPONENT32F",
        _ => "(unnamed format)",
    }
}

/// How many samples target `d` gets: its own count, clamped to what this
/// GL allows for colour and depth textures (GL_MAX_SAMPLES,
/// GL_MAX_COLOR_TEXTURE_SAMPLES, GL_MAX_DEPTH_TEXTURE_SAMPLES), with a
/// message on stderr when it is clamped.
fn allowed_samples(gl: &Gl, d: &TargetDesc) -> Result<i32> {
    if d.samples <= 1 {
        return Ok(1);
    }
    let mut max = i32::MAX;
    for p in [
        glow::MAX_SAMPLES,
        glow::MAX_COLOR_TEXTURE_SAMPLES,
        glow::MAX_DEPTH_TEXTURE_SAMPLES,
    ] {
        max = max.min(unsafe { gl.get_parameter_i32(p) });
    }
    if max < 2 {
        anyhow::bail!(
            "target {}: {} samples asked, but this GL has no multisampled textures (GL_MAX_SAMPLES = {max}): set render.msaa = 1",
            d.name,
            d.samples
        );
    }
    if d.samples as i32 > max {
        eprintln!(
            "gloss: render.msaa = {}, but this GL allows at most {max} samples per pixel (GL_MAX_SAMPLES): using {max}",
            d.samples
        );
        return Ok(max);
    }
    Ok(d.samples as i32)
}

/// The allocated targets of one plan.
pub struct Targets {
    targets: Vec<Framebuffer>,
    /// The targets with mip levels.
    mips: Vec<MipTarget>,
}

impl Targets {
    /// Allocate every target of `descs`, `width` x `height`, in order.
    pub fn new(gl: &Gl, descs: &[TargetDesc], width: i32, height: i32) -> Result<Targets> {
        let mut targets: Vec<Framebuffer> = Vec::with_capacity(descs.len());
        let mut mips = Vec::new();
        for d in descs {
            if let Some((first, last)) = d.mips {
                let last = last.min(max_level(width, height));
                if first <= last {
                    let format = d.colors.first().map_or(glow::RGBA16F, |c| c.1);
                    mips.push(MipTarget::new(
                        gl, d.name, width, height, format, first, last,
                    )?);
                }
                continue;
            }
            let samples = allowed_samples(gl, d)?;
            let (width, height) = scaled_size(width, height, d.downscale);
            let texture = |format| match samples {
                1 => Texture::render_target(gl, width, height, format),
                n => Texture::render_target_multisample(gl, width, height, format, n),
            };
            let mut colors = Vec::with_capacity(d.colors.len());
            for &(_, format) in &d.colors {
                colors.push(texture(format)?);
            }
            let (own, shared) = match d.depth {
                Depth::None => (None, None),
                Depth::Own(format) => (Some(texture(format)?), None),
                Depth::SharedWith(other) => {
                    let fb = targets.iter().find(|t| t.name == other).ok_or_else(|| {
                        anyhow!("target {} shares the depth of {other}, which comes later or not at all", d.name)
                    })?;
                    let depth = fb.depth_stencil.as_ref().ok_or_else(|| {
                        anyhow!(
                            "target {} shares the depth of {other}, which has none",
                            d.name
                        )
                    })?;
                    (None, Some(depth))
                }
            };
            let fb = if d.ping_pong {
                Framebuffer::ping_pong(gl, d.name, colors)?
            } else {
                Framebuffer::with_attachments(gl, d.name, colors, own, shared)?
            };
            targets.push(fb);
        }
        Ok(Targets { targets, mips })
    }

    /// The target named `name`, if the plan has it.
    pub fn find(&self, name: &str) -> Option<&Framebuffer> {
        self.targets.iter().find(|t| t.name == name)
    }

    /// The target named `name`; the plan guarantees that a pass's targets exist.
    pub fn get(&self, name: &str) -> &Framebuffer {
        self.find(name)
            .unwrap_or_else(|| panic!("the frame plan has no target named {name}"))
    }

    /// The target with mip levels named `name`, if the plan has it and the
    /// frame has at least its first level.
    pub fn mip(&self, name: &str) -> Option<&MipTarget> {
        self.mips.iter().find(|t| t.name == name)
    }

    /// Free every target (the ones sharing a depth texture first).
    pub fn clear(&mut self) {
        while self.targets.pop().is_some() {}
        self.mips.clear();
    }
}

impl Drop for Targets {
    fn drop(&mut self) {
        self.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn target(colors: Vec<(&'static str, u32)>, depth: Depth) -> TargetDesc {
        TargetDesc {
            name: "t",
            samples: 1,
            colors,
            depth,
            ping_pong: false,
            mips: None,
            downscale: 1,
        }
    }

    #[test]
    fn a_targets_bytes_are_its_textures() {
        // The G-buffer: RGBA16F + two SRGB8_ALPHA8 + DEPTH24_STENCIL8, 20
        // bytes a pixel.
        let g = target(
            vec![
                ("normal_shininess", glow::RGBA16F),
                ("albedo", glow::SRGB8_ALPHA8),
                ("specular", glow::SRGB8_ALPHA8),
            ],
            Depth::Own(glow::DEPTH24_STENCIL8),
        );
        assert_eq!(g.bytes(320, 240), 20 * 320 * 240);
        // A shared depth is counted once, where it is owned.
        let shared = TargetDesc {
            depth: Depth::SharedWith("gbuffer"),
            ..target(vec![("light", glow::RGBA16F)], Depth::None)
        };
        assert_eq!(shared.bytes(320, 240), 8 * 320 * 240);
        // Four samples take four times the bytes.
        let msaa = TargetDesc {
            samples: 4,
            ..target(vec![("color", glow::RGBA8)], Depth::None)
        };
        assert_eq!(msaa.bytes(10, 10), 4 * 4 * 100);
        // Mip levels 1..=2 of 10x6: levels 0, 1 and 2 are allocated
        // (10x6, 5x3, 2x1).
        let mips = TargetDesc {
            mips: Some((1, 2)),
            downscale: 1,
            ..target(vec![("color", glow::RGBA16F)], Depth::None)
        };
        assert_eq!(mips.bytes(10, 6), 8 * (60 + 15 + 2));
        assert_eq!(size_name(1536000), "1.46 MiB");
        assert_eq!(size_name(2048), "2 KiB");
        assert_eq!(size_name(12), "12 bytes");
    }
}
