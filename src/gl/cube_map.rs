//! Cube maps (notes 03, Implementation: the skybox's six images): one
//! GL_TEXTURE_CUBE_MAP, from six PNG faces (sRGB, with a mip chain) or
//! empty at RGBA16F for a pass to render into (the Preetham sky,
//! src/techniques/sky/sky_cube_map.rs), one framebuffer per face.
//! src/math/cube_map.rs is its CPU twin: the face order, the face table and
//! the sampling the tests compare with.
//!
//! Faces are uploaded top row first and not flipped: GL's cube map faces
//! put t = 0 at the image's top (GL 3.3 §3.8.10), unlike 2D textures.
//! Filtering is trilinear, clamped to each face's edge; the passes that
//! sample a cube map enable GL_TEXTURE_CUBE_MAP_SEAMLESS themselves, so that
//! filtering crosses from face to face.

use super::Gl;
use super::image_file::load_rgba8;
use super::texture::max_level;
use crate::math::cube_map::FACES;
use anyhow::{Result, anyhow, bail};
use glow::{HasContext, PixelUnpackData};
use std::path::{Path, PathBuf};

/// One GL_TEXTURE_CUBE_MAP, square faces of `size` texels.
pub struct CubeMap {
    gl: Gl,
    pub id: glow::Texture,
    pub size: i32,
    pub internal_format: u32,
    /// One framebuffer per face's level 0 (`empty` only): what a pass draws into.
    pub faces: Vec<glow::Framebuffer>,
}

/// The faces must be square and alike: an error names every face and its size.
pub fn check_face_sizes(paths: &[PathBuf], sizes: &[(u32, u32)]) -> Result<u32> {
    let (w, h) = sizes[0];
    if sizes.iter().all(|&s| s == (w, w)) {
        return Ok(w);
    }
    let list: Vec<String> = (paths.iter().zip(sizes).zip(FACES))
        .map(|((p, (w, h)), f)| format!("{f} {} is {w}x{h}", p.display()))
        .collect();
    let why = if w != h || sizes.iter().any(|(w, h)| w != h) {
        "every face must be square"
    } else {
        "every face must be the same size"
    };
    bail!("{why}: {}", list.join(", "))
}

impl CubeMap {
    /// Six PNGs in GL's order (+x, -x, +y, -y, +z, -z), stored sRGB
    /// (sampling returns linear), with the mip chain made by glGenerateMipmap.
    pub fn from_faces(gl: &Gl, paths: &[PathBuf]) -> Result<CubeMap> {
        if paths.len() != 6 {
            bail!("a cube map has 6 faces, {} given", paths.len());
        }
        let mut images = Vec::new();
        for p in paths {
            // load_rgba8 flips rows for 2D textures; cube faces keep theirs.
            let img = load_rgba8(Path::new(p))?;
            images.push(image::imageops::flip_vertical(&img));
        }
        let sizes: Vec<(u32, u32)> = images.iter().map(|i| i.dimensions()).collect();
        let size = check_face_sizes(paths, &sizes)? as i32;
        let c = CubeMap::allocate(gl, size, glow::SRGB8_ALPHA8)?;
        unsafe {
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(c.id));
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 1);
            for (i, img) in images.iter().enumerate() {
                gl.tex_sub_image_2d(
                    glow::TEXTURE_CUBE_MAP_POSITIVE_X + i as u32,
                    0,
                    0,
                    0,
                    size,
                    size,
                    glow::RGBA,
                    glow::UNSIGNED_BYTE,
                    PixelUnpackData::Slice(Some(img.as_raw())),
                );
            }
            gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
            gl.generate_mipmap(glow::TEXTURE_CUBE_MAP);
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
        }
        Ok(c)
    }

    /// An RGBA16F cube map of `size` to render into, a framebuffer on each
    /// face's level 0; the mip chain is made after drawing (`generate_mipmap`).
    pub fn empty(gl: &Gl, size: i32) -> Result<CubeMap> {
        let mut c = CubeMap::allocate(gl, size, glow::RGBA16F)?;
        unsafe {
            for i in 0..6 {
                let fb = gl
                    .create_framebuffer()
                    .map_err(|e| anyhow!("glGenFramebuffers: {e}"))?;
                super::live::made(super::live::Kind::Framebuffer);
                c.faces.push(fb);
                gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
                gl.framebuffer_texture_2d(
                    glow::FRAMEBUFFER,
                    glow::COLOR_ATTACHMENT0,
                    glow::TEXTURE_CUBE_MAP_POSITIVE_X + i,
                    Some(c.id),
                    0,
                );
                let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
                gl.bind_framebuffer(glow::FRAMEBUFFER, None);
                if status != glow::FRAMEBUFFER_COMPLETE {
                    bail!(
                        "the cube map's face {} framebuffer is incomplete: {}",
                        FACES[i as usize],
                        super::framebuffer::status_name(status)
                    );
                }
            }
        }
        Ok(c)
    }

    /// Storage for every level of every face, and the sampling parameters.
    fn allocate(gl: &Gl, size: i32, internal: u32) -> Result<CubeMap> {
        if !(1..=super::texture::MAX_TEXTURE_SIDE as i32).contains(&size) {
            bail!(
                "a cube map face of {size} texels: expected 1..={}",
                super::texture::MAX_TEXTURE_SIDE
            );
        }
        let (format, kind) = match internal {
            glow::RGBA16F => (glow::RGBA, glow::FLOAT),
            _ => (glow::RGBA, glow::UNSIGNED_BYTE),
        };
        unsafe {
            let id = super::live::new_texture(gl)?;
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(id));
            for level in 0..=max_level(size, size) {
                let n = (size >> level).max(1);
                for face in 0..6 {
                    gl.tex_image_2d(
                        glow::TEXTURE_CUBE_MAP_POSITIVE_X + face,
                        level as i32,
                        internal as i32,
                        n,
                        n,
                        0,
                        format,
                        kind,
                        PixelUnpackData::Slice(None),
                    );
                }
            }
            let p = |k: u32, v: u32| gl.tex_parameter_i32(glow::TEXTURE_CUBE_MAP, k, v as i32);
            p(glow::TEXTURE_MIN_FILTER, glow::LINEAR_MIPMAP_LINEAR);
            p(glow::TEXTURE_MAG_FILTER, glow::LINEAR);
            for wrap in [
                glow::TEXTURE_WRAP_S,
                glow::TEXTURE_WRAP_T,
                glow::TEXTURE_WRAP_R,
            ] {
                p(wrap, glow::CLAMP_TO_EDGE);
            }
            gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
            Ok(CubeMap {
                gl: gl.clone(),
                id,
                size,
                internal_format: internal,
                faces: Vec::new(),
            })
        }
    }

    /// glGenerateMipmap, after a pass drew level 0.
    pub fn generate_mipmap(&self) {
        unsafe {
            self.gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(self.id));
            self.gl.generate_mipmap(glow::TEXTURE_CUBE_MAP);
            self.gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
        }
    }

    /// Face `face`'s level `level` read back as RGBA f32, row t = 0 first
    /// (glGetTexImage; an sRGB face comes back as stored, encoded).
    pub fn read_face_f32(&self, face: u32, level: u32) -> Vec<f32> {
        let n = (self.size >> level).max(1);
        let mut out = vec![0f32; (n * n * 4) as usize];
        unsafe {
            self.gl.bind_texture(glow::TEXTURE_CUBE_MAP, Some(self.id));
            self.gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            self.gl.get_tex_image(
                glow::TEXTURE_CUBE_MAP_POSITIVE_X + face,
                level as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(super::framebuffer::bytemuck_f32(&mut out))),
            );
            self.gl.bind_texture(glow::TEXTURE_CUBE_MAP, None);
        }
        out
    }

    /// Level 0 of every face, for the CPU's sampler (src/math/cube_map.rs).
    pub fn read_image(&self) -> crate::math::cube_map::CubeImage {
        let faces = std::array::from_fn(|f| {
            let v = self.read_face_f32(f as u32, 0);
            v.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
        });
        crate::math::cube_map::CubeImage {
            size: self.size as usize,
            faces,
        }
    }
}

impl Drop for CubeMap {
    fn drop(&mut self) {
        unsafe {
            for &fb in &self.faces {
                self.gl.delete_framebuffer(fb);
                super::live::freed(super::live::Kind::Framebuffer);
            }
            self.gl.delete_texture(self.id);
            super::live::freed(super::live::Kind::Texture);
        }
    }
}
