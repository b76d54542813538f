//! The scene's billboards on the GPU (notes 05, "Billboards"): the sprites
//! side by side in one RGBA texture (a sprite sheet: sprite i covers u in
//! [i/n, (i+1)/n]), and a vertex array whose attributes are per instance
//! (glVertexAttribDivisor 1): one instance per billboard, four vertices
//! each, the corners made from gl_VertexID in glsl/billboards/billboards.vert.
//! The billboards technique writes the instances in the order it draws them.

use crate::gl::Gl;
use crate::gl::buffer::Buffer;
use crate::gl::live::{self, Kind};
use crate::gl::texture::{Sampling, Texture, load_rgba8};
use crate::scene::{Billboard, BillboardKind, Scene};
use anyhow::{Result, anyhow, bail};
use glow::HasContext;

/// Floats per instance: centre xyz, size (width, height), sprite, cylindrical.
pub const INSTANCE_FLOATS: usize = 7;

/// Mipmapped, clamped: a sprite's transparent border keeps its neighbours apart.
const SHEET_SAMPLING: Sampling = Sampling {
    wrap: glow::CLAMP_TO_EDGE,
    min_filter: glow::LINEAR_MIPMAP_LINEAR,
    mag_filter: glow::LINEAR,
};

/// The billboards' sprite sheet and instance attributes (nothing when the
/// scene has no billboards).
pub struct BillboardDraws {
    pub gpu: Option<BillboardGpu>,
}

pub struct BillboardGpu {
    gl: Gl,
    /// Every sprite, resized to the first one's size, left to right.
    pub sheet: Texture,
    pub sprite_count: usize,
    /// `count` instances of INSTANCE_FLOATS floats (GL_ARRAY_BUFFER, rewritten each frame).
    pub instances: Buffer,
    /// Locations 0-3 read `instances`, one value per instance.
    pub vao: glow::VertexArray,
    pub count: usize,
}

impl BillboardDraws {
    pub fn new(gl: &Gl, scene: &Scene) -> Result<BillboardDraws> {
        if scene.billboards.is_empty() {
            return Ok(BillboardDraws { gpu: None });
        }
        let sheet = sprite_sheet(gl, scene)?;
        let count = scene.billboards.len();
        let stride = (INSTANCE_FLOATS * 4) as i32;
        let instances = Buffer::new(
            gl,
            glow::ARRAY_BUFFER,
            count * INSTANCE_FLOATS * 4,
            glow::DYNAMIC_DRAW,
        )?;
        let vao = unsafe {
            let vao = live::new_vertex_array(gl)?;
            gl.bind_vertex_array(Some(vao));
            gl.bind_buffer(glow::ARRAY_BUFFER, Some(instances.id));
            // location, components, byte offset
            for (loc, n, off) in [(0u32, 3, 0), (1, 2, 12), (2, 1, 20), (3, 1, 24)] {
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, n, glow::FLOAT, false, stride, off);
                gl.vertex_attrib_divisor(loc, 1);
            }
            gl.bind_vertex_array(None);
            gl.bind_buffer(glow::ARRAY_BUFFER, None);
            vao
        };
        Ok(BillboardDraws {
            gpu: Some(BillboardGpu {
                gl: gl.clone(),
                sheet,
                sprite_count: scene.sprites.len(),
                instances,
                vao,
                count,
            }),
        })
    }
}

/// The instance attributes of `billboards` in `order` (indices into it).
pub fn instance_data(billboards: &[Billboard], order: &[usize]) -> Vec<f32> {
    let mut v = Vec::with_capacity(order.len() * INSTANCE_FLOATS);
    for &i in order {
        let b = &billboards[i];
        let cylindrical = b.kind == BillboardKind::Cylindrical;
        v.extend_from_slice(&[
            b.center.x,
            b.center.y,
            b.center.z,
            b.size.x,
            b.size.y,
            b.sprite as f32,
            if cylindrical { 1.0 } else { 0.0 },
        ]);
    }
    v
}

/// Every sprite of `scene`, resized to the first one's size, side by side in
/// one sRGB texture with its alpha (mipmapped).
fn sprite_sheet(gl: &Gl, scene: &Scene) -> Result<Texture> {
    let images = load_sprites(scene)?;
    let (w, h) = images[0].dimensions();
    let n = images.len() as u32;
    let max = unsafe { gl.get_parameter_i32(glow::MAX_TEXTURE_SIZE) } as u32;
    if w.saturating_mul(n) > max {
        bail!(
            "billboard sprites: {n} sprites {w} pixels wide make a sheet wider than this GL's GL_MAX_TEXTURE_SIZE ({max}); use smaller sprites"
        );
    }
    let mut sheet = image::RgbaImage::new(w * n, h);
    for (i, img) in images.iter().enumerate() {
        let img = if img.dimensions() == (w, h) {
            img.clone()
        } else {
            image::imageops::resize(img, w, h, image::imageops::FilterType::Triangle)
        };
        image::imageops::replace(&mut sheet, &img, (i as u32 * w) as i64, 0);
    }
    Texture::from_rgba8(gl, w * n, h, sheet.as_raw(), true, SHEET_SAMPLING)
}

/// Every sprite of `scene`, decoded (`gloss plan` loads them the same way).
pub fn load_sprites(scene: &Scene) -> Result<Vec<image::RgbaImage>> {
    let mut images = Vec::with_capacity(scene.sprites.len());
    for p in &scene.sprites {
        let img = load_rgba8(p).map_err(|e| anyhow!("billboard sprite: {e:#}"))?;
        images.push(img);
    }
    Ok(images)
}

impl Drop for BillboardGpu {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_vertex_array(self.vao);
            live::freed(Kind::VertexArray);
        }
    }
}
