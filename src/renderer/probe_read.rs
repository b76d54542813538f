//! The pixel probe's reads (src/renderer/probe.rs): one pixel of a colour
//! attachment, a texture, a multisampled attachment resolved, the stencil,
//! a square of depths; each puts the read framebuffer and read buffer back.

use crate::gl::framebuffer::Framebuffer;
use crate::gl::texture::{Texture, bytemuck_f32};
use glow::HasContext;

/// Colour attachment `index` of framebuffer `fb` at (`x`, `y`) from the
/// top left, as RGBA floats.
pub(super) fn read_color(
    gl: &glow::Context,
    fb: &Framebuffer,
    index: u32,
    x: u32,
    y: u32,
) -> [f32; 4] {
    let mut v = [0f32; 4];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.id));
        gl.read_buffer(glow::COLOR_ATTACHMENT0 + index);
        gl.read_pixels(
            x as i32,
            fb.height - 1 - y as i32,
            1,
            1,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(bytemuck_f32(&mut v))),
        );
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    v
}

/// Texture `t` (of a framebuffer `height` rows high) at (`x`, `y`) from
/// the top left, as RGBA floats, through a framebuffer made for the read:
/// a ping-pong target's framebuffer has only one of its two textures
/// attached at a time.
pub(super) fn read_texture(
    gl: &glow::Context,
    t: &Texture,
    height: i32,
    x: u32,
    y: u32,
) -> [f32; 4] {
    let mut v = [0f32; 4];
    unsafe {
        let Ok(fb) = gl.create_framebuffer() else {
            return [f32::NAN; 4];
        };
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb));
        let color = glow::COLOR_ATTACHMENT0;
        gl.framebuffer_texture_2d(
            glow::READ_FRAMEBUFFER,
            color,
            glow::TEXTURE_2D,
            Some(t.id),
            0,
        );
        gl.read_buffer(color);
        gl.read_pixels(
            x as i32,
            height - 1 - y as i32,
            1,
            1,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(bytemuck_f32(&mut v))),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        gl.delete_framebuffer(fb);
    }
    v
}

/// Colour attachment `index` (of internal format `format`) of the
/// multisampled framebuffer `fb` at (`x`, `y`) from the top left, resolved:
/// glBlitFramebuffer of that one pixel into a 1 x 1 texture of the same
/// format (a resolve needs equal formats and rectangles), read back. None
/// for a format this does not make (integer formats).
pub(super) fn read_resolved(
    gl: &glow::Context,
    fb: &Framebuffer,
    index: u32,
    format: u32,
    x: u32,
    y: u32,
) -> Option<[f32; 4]> {
    let kind = match format {
        glow::RGBA16F | glow::RGBA32F | glow::R16F | glow::R32F | glow::RG16F => glow::FLOAT,
        glow::RGBA8 | glow::SRGB8_ALPHA8 | glow::R8 => glow::UNSIGNED_BYTE,
        _ => return None,
    };
    let mut v = [0f32; 4];
    let (sx, sy) = (x as i32, fb.height - 1 - y as i32);
    unsafe {
        let texture = gl.create_texture().ok()?;
        let Ok(resolved) = gl.create_framebuffer() else {
            gl.delete_texture(texture);
            return None;
        };
        gl.bind_texture(glow::TEXTURE_2D, Some(texture));
        let empty = glow::PixelUnpackData::Slice(None);
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            format as i32,
            1,
            1,
            0,
            glow::RGBA,
            kind,
            empty,
        );
        gl.bind_texture(glow::TEXTURE_2D, None);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, Some(resolved));
        let color = glow::COLOR_ATTACHMENT0;
        gl.framebuffer_texture_2d(
            glow::DRAW_FRAMEBUFFER,
            color,
            glow::TEXTURE_2D,
            Some(texture),
            0,
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.id));
        gl.read_buffer(color + index);
        let bit = glow::COLOR_BUFFER_BIT;
        gl.blit_framebuffer(sx, sy, sx + 1, sy + 1, 0, 0, 1, 1, bit, glow::NEAREST);
        gl.read_buffer(color);
        gl.bind_framebuffer(glow::DRAW_FRAMEBUFFER, None);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(resolved));
        gl.read_pixels(
            0,
            0,
            1,
            1,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(bytemuck_f32(&mut v))),
        );
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        gl.delete_framebuffer(resolved);
        gl.delete_texture(texture);
    }
    Some(v)
}

/// The stencil value of `fb` at (`x`, `y`) from the top left.
pub(super) fn read_stencil(gl: &glow::Context, fb: &Framebuffer, x: u32, y: u32) -> u8 {
    let mut v = [0u8; 1];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.id));
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            x as i32,
            fb.height - 1 - y as i32,
            1,
            1,
            glow::STENCIL_INDEX,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut v)),
        );
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    v[0]
}

/// The depths of `fb` in the square of reach `r` around (`x`, `y`) from
/// the top left, clamped to the frame: (2 r + 1)^2 values, top row first.
pub(super) fn read_depths(
    gl: &glow::Context,
    fb: &Framebuffer,
    x: u32,
    y: u32,
    r: i32,
) -> Vec<f32> {
    let side = (2 * r + 1) as usize;
    let mut out = Vec::with_capacity(side * side);
    let (w, h) = (fb.width, fb.height);
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb.id));
        for dy in -r..=r {
            for dx in -r..=r {
                let gx = (x as i32 + dx).clamp(0, w - 1);
                let gy = (h - 1 - (y as i32 + dy)).clamp(0, h - 1);
                let mut v = [0f32; 1];
                gl.read_pixels(
                    gx,
                    gy,
                    1,
                    1,
                    glow::DEPTH_COMPONENT,
                    glow::FLOAT,
                    glow::PixelPackData::Slice(Some(bytemuck_f32(&mut v))),
                );
                out.push(v[0]);
            }
        }
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
    }
    out
}
