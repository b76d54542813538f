//! F12 / P: the 3D view's rectangle of the window's back buffer (the frame,
//! before the panel is drawn over it), Shift+F12 the whole window with the
//! panel, saved as gloss-screenshot-N.png in the current directory.

use anyhow::{Context as _, Result};
use glow::HasContext;
use std::path::PathBuf;

/// Read the rectangle `[x, y, width, height]` (GL pixels, y up) of the
/// default framebuffer's back buffer and write it to the first free
/// gloss-screenshot-N.png; returns the path.
pub(super) fn save(gl: &glow::Context, [x, y, width, height]: [i32; 4]) -> Result<PathBuf> {
    let (width, height) = (width.max(1) as u32, height.max(1) as u32);
    let mut raw = vec![0u8; width as usize * height as usize * 4];
    unsafe {
        gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        gl.read_buffer(glow::BACK);
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 1);
        gl.read_pixels(
            x,
            y,
            width as i32,
            height as i32,
            glow::RGBA,
            glow::UNSIGNED_BYTE,
            glow::PixelPackData::Slice(Some(&mut raw)),
        );
        gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
    }
    let img = image::RgbaImage::from_raw(width, height, raw).context("screenshot size")?;
    let mut img = image::imageops::flip_vertical(&img);
    for p in img.pixels_mut() {
        p.0[3] = 255;
    }
    let dir = std::env::current_dir().context("no current directory for the screenshot")?;
    let path = (1..)
        .map(|n| dir.join(format!("gloss-screenshot-{n}.png")))
        .find(|p| !p.exists())
        .expect("some number is free");
    img.save(&path)
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(path)
}
