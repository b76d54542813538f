//! A render target with mip levels: one texture, levels `first..=last`,
//! and one framebuffer per level with that level as GL_COLOR_ATTACHMENT0
//! (glFramebufferTexture2D's `level`). Notes 03's bloom writes its four
//! blurs into mip levels 1-4 of one texture ("tempbuffer2 (mipmaps)").
//!
//! A pass draws into one level and may read another texture, never a level
//! of the texture it draws into: GL 3.3 §4.4.3 makes that a feedback loop
//! unless the base and max levels shut the drawn level out, and the
//! checker in src/gl/debug.rs compares whole textures. The bloom reads its
//! levels from one texture and draws into the other's.

use super::Gl;
use super::framebuffer::status_name;
use super::texture::{Texture, level_size};
use anyhow::{Result, anyhow, bail};
use glow::HasContext;

/// One level and the framebuffer that draws into it.
pub struct Level {
    pub level: u32,
    pub framebuffer: glow::Framebuffer,
    pub width: i32,
    pub height: i32,
}

/// A texture with levels `first..=last`, each with its framebuffer.
pub struct MipTarget {
    gl: Gl,
    pub name: &'static str,
    pub texture: Texture,
    /// `first..=last`, in order.
    pub levels: Vec<Level>,
}

impl MipTarget {
    /// Make the texture (levels `first..=last` of `width` x `height`) and a
    /// complete framebuffer per level; a failure names the target and level.
    pub fn new(
        gl: &Gl,
        name: &'static str,
        width: i32,
        height: i32,
        format: u32,
        first: u32,
        last: u32,
    ) -> Result<MipTarget> {
        let texture = Texture::render_target_levels(gl, width, height, format, first, last)
            .map_err(|e| anyhow!("target {name}: {e}"))?;
        let mut target = MipTarget {
            gl: gl.clone(),
            name,
            texture,
            levels: Vec::new(),
        };
        for level in first..=last {
            let (w, h) = level_size(width, height, level);
            unsafe {
                let fb = gl
                    .create_framebuffer()
                    .map_err(|e| anyhow!("glGenFramebuffers: {e}"))?;
                super::live::made(super::live::Kind::Framebuffer);
                target.levels.push(Level {
                    level,
                    framebuffer: fb,
                    width: w,
                    height: h,
                });
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
                gl.framebuffer_texture_2d(
                    glow::FRAMEBUFFER,
                    glow::COLOR_ATTACHMENT0,
                    glow::TEXTURE_2D,
                    Some(target.texture.id),
                    level as i32,
                );
                gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
                let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
                gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                if status != glow::FRAMEBUFFER_COMPLETE {
                    bail!(
                        "framebuffer '{name}' level {level} is incomplete: {}",
                        status_name(status)
                    );
                }
            }
        }
        Ok(target)
    }

    /// Level `level`, if the target has it.
    pub fn level(&self, level: u32) -> Option<&Level> {
        self.levels.iter().find(|l| l.level == level)
    }

    /// The first level (GL_TEXTURE_BASE_LEVEL): a shader's lod 0.
    pub fn first(&self) -> u32 {
        self.levels.first().map_or(0, |l| l.level)
    }

    /// The last level the target has.
    pub fn last(&self) -> u32 {
        self.levels.last().map_or(0, |l| l.level)
    }
}

impl Drop for MipTarget {
    fn drop(&mut self) {
        for l in &self.levels {
            unsafe {
                self.gl.delete_framebuffer(l.framebuffer);
                super::live::freed(super::live::Kind::Framebuffer);
            }
        }
    }
}
