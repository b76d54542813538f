//! Framebuffer objects with several colour attachments (MRT) and a depth-stencil texture.

use super::Gl;
use super::texture::Texture;
// Kept here for the readers that import it from the framebuffer (it lives
// with the texture, below the framebuffer: src/gl/texture.rs).
pub use super::texture::bytemuck_f32;
use anyhow::{Result, anyhow, bail};
use glow::HasContext;

/// One FBO. It owns its attachment textures so a pass can sample them later
/// (the G-buffer) or read them back (tests).
pub struct Framebuffer {
    gl: Gl,
    pub id: glow::Framebuffer,
    pub width: i32,
    pub height: i32,
    pub colors: Vec<Texture>,
    pub depth_stencil: Option<Texture>,
    /// A depth-stencil texture owned by another framebuffer and attached here
    /// too (the light accumulation target tests against the G-buffer's depth).
    pub shared_depth: Option<glow::Texture>,
    pub name: &'static str,
}

impl Framebuffer {
    /// Make an FBO with one texture per entry of `color_formats` bound to
    /// GL_COLOR_ATTACHMENT0.., an optional depth-stencil texture, and
    /// glDrawBuffers for all colour attachments. Completeness is checked and a
    /// failure names the status.
    pub fn new(
        gl: &Gl,
        name: &'static str,
        width: i32,
        height: i32,
        color_formats: &[u32],
        depth_stencil_format: Option<u32>,
    ) -> Result<Framebuffer> {
        let mut colors = Vec::new();
        for &f in color_formats {
            colors.push(Texture::render_target(gl, width, height, f)?);
        }
        let depth_stencil = match depth_stencil_format {
            Some(f) => Some(Texture::render_target(gl, width, height, f)?),
            None => None,
        };
        Self::with_attachments(gl, name, colors, depth_stencil, None)
    }

    /// Wrap existing textures (e.g. share the G-buffer's depth with the lighting target).
    pub fn with_attachments(
        gl: &Gl,
        name: &'static str,
        colors: Vec<Texture>,
        depth_stencil: Option<Texture>,
        shared_depth: Option<&Texture>,
    ) -> Result<Framebuffer> {
        let (width, height) = colors
            .first()
            .or(depth_stencil.as_ref())
            .map(|t| (t.width, t.height))
            .ok_or_else(|| anyhow!("framebuffer {name} has no attachments"))?;
        unsafe {
            let id = gl
                .create_framebuffer()
                .map_err(|e| anyhow!("glGenFramebuffers: {e}"))?;
            super::live::made(super::live::Kind::Framebuffer);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(id));
            let mut draw = Vec::new();
            for (i, t) in colors.iter().enumerate() {
                let at = glow::COLOR_ATTACHMENT0 + i as u32;
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, at, t.target(), Some(t.id), 0);
                draw.push(at);
            }
            if let Some(d) = depth_stencil.as_ref().or(shared_depth) {
                let at = match d.internal_format {
                    glow::DEPTH24_STENCIL8 | glow::DEPTH32F_STENCIL8 => {
                        glow::DEPTH_STENCIL_ATTACHMENT
                    }
                    _ => glow::DEPTH_ATTACHMENT,
                };
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, at, d.target(), Some(d.id), 0);
            }
            if draw.is_empty() {
                gl.draw_buffer(glow::NONE);
                gl.read_buffer(glow::NONE);
            } else {
                gl.draw_buffers(&draw);
            }
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            let fb = Framebuffer {
                gl: gl.clone(),
                id,
                width,
                height,
                colors,
                depth_stencil,
                shared_depth: shared_depth.map(|t| t.id),
                name,
            };
            if status != glow::FRAMEBUFFER_COMPLETE {
                bail!(
                    "framebuffer '{name}' is incomplete: {}",
                    status_name(status)
                );
            }
            Ok(fb)
        }
    }

    /// An FBO that owns `textures` but attaches only the first, at
    /// GL_COLOR_ATTACHMENT0: the post chain's ping-pong pair, whose passes
    /// attach the one they draw into (src/frame/post.rs).
    pub fn ping_pong(gl: &Gl, name: &'static str, textures: Vec<Texture>) -> Result<Framebuffer> {
        let mut textures = textures.into_iter();
        let first = textures
            .next()
            .ok_or_else(|| anyhow!("framebuffer {name} has no attachments"))?;
        let mut fb = Self::with_attachments(gl, name, vec![first], None, None)?;
        fb.colors.extend(textures);
        Ok(fb)
    }

    /// Read colour attachment `index` as RGBA f32 (row 0 = bottom).
    pub fn read_rgba_f32(&self, index: u32) -> Vec<f32> {
        let n = (self.width * self.height * 4) as usize;
        let mut out = vec![0f32; n];
        unsafe {
            self.gl
                .bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.id));
            self.gl.read_buffer(glow::COLOR_ATTACHMENT0 + index);
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.read_pixels(
                0,
                0,
                self.width,
                self.height,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(bytemuck_f32(&mut out))),
            );
            self.gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        }
        out
    }

    /// Read the depth attachment as floats in 0..1 (row 0 = bottom).
    pub fn read_depth_f32(&self) -> Vec<f32> {
        let mut out = vec![0f32; (self.width * self.height) as usize];
        unsafe {
            self.gl
                .bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.id));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.read_pixels(
                0,
                0,
                self.width,
                self.height,
                glow::DEPTH_COMPONENT,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(bytemuck_f32(&mut out))),
            );
            self.gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        }
        out
    }

    /// Read the stencil buffer (GL_STENCIL_INDEX), one byte per pixel, row 0
    /// the top (PNG order).
    pub fn read_stencil_top_down(&self) -> Vec<u8> {
        read_stencil_top_down(&self.gl, self.id, self.width, self.height)
    }

    /// Read colour attachment `index` as RGBA8, flipped so row 0 is the top (PNG order).
    pub fn read_rgba8_top_down(&self, index: u32) -> image::RgbaImage {
        let (w, h) = (self.width as usize, self.height as usize);
        let mut raw = vec![0u8; w * h * 4];
        unsafe {
            self.gl
                .bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.id));
            self.gl.read_buffer(glow::COLOR_ATTACHMENT0 + index);
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
            self.gl.read_pixels(
                0,
                0,
                self.width,
                self.height,
                glow::RGBA,
                glow::UNSIGNED_BYTE,
                glow::PixelPackData::Slice(Some(&mut raw)),
            );
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        }
        let img = image::RgbaImage::from_raw(w as u32, h as u32, raw).expect("size matches");
        image::imageops::flip_vertical(&img)
    }
}

/// The name of a glCheckFramebufferStatus result.
pub fn status_name(status: u32) -> &'static str {
    match status {
        glow::FRAMEBUFFER_COMPLETE => "GL_FRAMEBUFFER_COMPLETE",
        glow::FRAMEBUFFER_UNDEFINED => "GL_FRAMEBUFFER_UNDEFINED",
        glow::FRAMEBUFFER_INCOMPLETE_ATTACHMENT => "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT",
        glow::FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT => {
            "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"
        }
        glow::FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER => "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER",
        glow::FRAMEBUFFER_INCOMPLETE_READ_BUFFER => "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER",
        glow::FRAMEBUFFER_UNSUPPORTED => "GL_FRAMEBUFFER_UNSUPPORTED",
        glow::FRAMEBUFFER_INCOMPLETE_MULTISAMPLE => "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE",
        glow::FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS => "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS",
        _ => "unknown framebuffer status",
    }
}

impl Drop for Framebuffer {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_framebuffer(self.id);
            super::live::freed(super::live::Kind::Framebuffer);
        }
    }
}

/// Read framebuffer `fb`'s stencil buffer (`width` x `height`), one byte per
/// pixel, row 0 the top.
pub fn read_stencil_top_down(
    gl: &glow::Context,
    fb: glow::Framebuffer,
    width: i32,
    height: i32,
) -> Vec<u8> {
    let mut raw = vec![0u8; (width.max(0) * height.max(0)) as usize];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb));
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            0,
            0,
            width,
            height,
            glow::STENCIL_INDEX,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut raw)),
        );
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    raw.chunks(width.max(1) as usize)
        .rev()
        .flatten()
        .copied()
        .collect()
}
