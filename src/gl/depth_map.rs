//! Depth textures that a shadow pass renders into: one GL_TEXTURE_2D, or one
//! GL_TEXTURE_CUBE_MAP of six square faces, each with the framebuffers that
//! draw into it (notes 01 §8.5: "The map is the depth buffer").
//!
//! Creation sets only the texture object's own parameters, which the
//! caller chooses (src/frame/shadows.rs sets the comparison mode there);
//! binding and drawing stay in the technique's file.

use super::Gl;
use super::framebuffer::{bytemuck_f32, status_name};
use anyhow::{Result, anyhow, bail};
use glow::{HasContext, PixelUnpackData};

/// The internal format of every depth map: 32-bit float depth.
pub const FORMAT: u32 = glow::DEPTH_COMPONENT32F;

/// A depth texture and the framebuffers that render into it.
pub struct DepthMap {
    gl: Gl,
    pub texture: glow::Texture,
    /// GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP or GL_TEXTURE_2D_ARRAY.
    pub target: u32,
    /// Texels along a side (of each face).
    pub size: i32,
    /// A 2D map: one framebuffer. A cube: one per face (+x, -x, +y, -y, +z,
    /// -z), then, when asked for, one with the whole cube attached as a
    /// layered image (glFramebufferTexture) for a geometry shader's gl_Layer.
    pub framebuffers: Vec<glow::Framebuffer>,
}

impl DepthMap {
    /// A `size` x `size` GL_TEXTURE_2D of `FORMAT`, with one framebuffer.
    pub fn new_2d(gl: &Gl, size: i32) -> Result<DepthMap> {
        let mut m = Self::allocate(gl, glow::TEXTURE_2D, size)?;
        let fb = m.framebuffer("2D shadow map", |gl, t| unsafe {
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::DEPTH_ATTACHMENT,
                glow::TEXTURE_2D,
                Some(t),
                0,
            )
        })?;
        m.framebuffers.push(fb);
        Ok(m)
    }

    /// A GL_TEXTURE_CUBE_MAP of six `size` x `size` faces of `FORMAT`, a
    /// framebuffer per face and, with `layered`, one for the whole cube.
    pub fn new_cube(gl: &Gl, size: i32, layered: bool) -> Result<DepthMap> {
        let mut m = Self::allocate(gl, glow::TEXTURE_CUBE_MAP, size)?;
        for face in 0..6 {
            let fb = m.framebuffer("cube shadow map face", |gl, t| unsafe {
                gl.framebuffer_texture_2d(
                    glow::FRAMEBUFFER,
                    glow::DEPTH_ATTACHMENT,
                    glow::TEXTURE_CUBE_MAP_POSITIVE_X + face,
                    Some(t),
                    0,
                )
            })?;
            m.framebuffers.push(fb);
        }
        if layered {
            let fb = m.framebuffer("layered cube shadow map", |gl, t| unsafe {
                gl.framebuffer_texture(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, Some(t), 0)
            })?;
            m.framebuffers.push(fb);
        }
        Ok(m)
    }

    /// A GL_TEXTURE_2D_ARRAY of `layers` `size` x `size` images of
    /// `FORMAT` (a directional light's cascades, one layer each) and a
    /// framebuffer per layer (glFramebufferTextureLayer): each layer is
    /// drawn in a pass of its own, with no geometry shader.
    pub fn new_array(gl: &Gl, size: i32, layers: i32) -> Result<DepthMap> {
        if !(1..=16384).contains(&size) || !(1..=256).contains(&layers) {
            bail!("a depth map array of {layers} layers of {size} x {size} texels");
        }
        let target = glow::TEXTURE_2D_ARRAY;
        let mut m = unsafe {
            let texture = super::live::new_texture(gl)?;
            gl.bind_texture(target, Some(texture));
            gl.tex_image_3d(
                target,
                0,
                FORMAT as i32,
                size,
                size,
                layers,
                0,
                glow::DEPTH_COMPONENT,
                glow::FLOAT,
                PixelUnpackData::Slice(None),
            );
            gl.tex_parameter_i32(target, glow::TEXTURE_MAX_LEVEL, 0);
            gl.tex_parameter_i32(target, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
            gl.tex_parameter_i32(target, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
            gl.bind_texture(target, None);
            DepthMap {
                gl: gl.clone(),
                texture,
                target,
                size,
                framebuffers: Vec::new(),
            }
        };
        for layer in 0..layers {
            let fb = m.framebuffer("cascade layer", |gl, t| unsafe {
                gl.framebuffer_texture_layer(
                    glow::FRAMEBUFFER,
                    glow::DEPTH_ATTACHMENT,
                    Some(t),
                    0,
                    layer,
                )
            })?;
            m.framebuffers.push(fb);
        }
        Ok(m)
    }

    fn allocate(gl: &Gl, target: u32, size: i32) -> Result<DepthMap> {
        if !(1..=16384).contains(&size) {
            bail!("a depth map of {size} x {size} texels");
        }
        unsafe {
            let texture = super::live::new_texture(gl)?;
            gl.bind_texture(target, Some(texture));
            let images: &[u32] = if target == glow::TEXTURE_2D {
                &[glow::TEXTURE_2D]
            } else {
                &[
                    glow::TEXTURE_CUBE_MAP_POSITIVE_X,
                    glow::TEXTURE_CUBE_MAP_NEGATIVE_X,
                    glow::TEXTURE_CUBE_MAP_POSITIVE_Y,
                    glow::TEXTURE_CUBE_MAP_NEGATIVE_Y,
                    glow::TEXTURE_CUBE_MAP_POSITIVE_Z,
                    glow::TEXTURE_CUBE_MAP_NEGATIVE_Z,
                ]
            };
            for &image in images {
                gl.tex_image_2d(
                    image,
                    0,
                    FORMAT as i32,
                    size,
                    size,
                    0,
                    glow::DEPTH_COMPONENT,
                    glow::FLOAT,
                    PixelUnpackData::Slice(None),
                );
            }
            // One level: no mipmaps, so the filters must not ask for them.
            gl.tex_parameter_i32(target, glow::TEXTURE_MAX_LEVEL, 0);
            gl.tex_parameter_i32(target, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
            gl.tex_parameter_i32(target, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
            gl.bind_texture(target, None);
            Ok(DepthMap {
                gl: gl.clone(),
                texture,
                target,
                size,
                framebuffers: Vec::new(),
            })
        }
    }

    /// A framebuffer with only this depth texture attached (`attach` does
    /// it): no colour, so glDrawBuffer(GL_NONE), checked complete.
    fn framebuffer(
        &self,
        what: &str,
        attach: impl Fn(&glow::Context, glow::Texture),
    ) -> Result<glow::Framebuffer> {
        let gl = &self.gl;
        unsafe {
            let fb = gl
                .create_framebuffer()
                .map_err(|e| anyhow!("glGenFramebuffers: {e}"))?;
            super::live::made(super::live::Kind::Framebuffer);
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fb));
            attach(gl, self.texture);
            gl.draw_buffer(glow::NONE);
            gl.read_buffer(glow::NONE);
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            if status != glow::FRAMEBUFFER_COMPLETE {
                gl.delete_framebuffer(fb);
                super::live::freed(super::live::Kind::Framebuffer);
                bail!("{what} framebuffer is incomplete: {}", status_name(status));
            }
            Ok(fb)
        }
    }

    /// Read one image back as floats, row 0 at the bottom (`face` 0..6 of a
    /// cube, a layer of an array, 0 for a 2D map): the demo's inspector and the tests.
    pub fn read(&self, face: u32) -> Vec<f32> {
        let gl = &self.gl;
        let fb = self.framebuffers[face as usize];
        let mut out = vec![0f32; (self.size * self.size) as usize];
        unsafe {
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, Some(fb));
            gl.read_pixels(
                0,
                0,
                self.size,
                self.size,
                glow::DEPTH_COMPONENT,
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(bytemuck_f32(&mut out))),
            );
            gl.bind_framebuffer(glow::READ_FRAMEBUFFER, None);
        }
        out
    }
}

impl Drop for DepthMap {
    fn drop(&mut self) {
        unsafe {
            for fb in self.framebuffers.drain(..) {
                self.gl.delete_framebuffer(fb);
                super::live::freed(super::live::Kind::Framebuffer);
            }
            self.gl.delete_texture(self.texture);
            super::live::freed(super::live::Kind::Texture);
        }
    }
}
