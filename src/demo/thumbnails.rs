//! The inspector's thumbnail strip: every attachment and shadow-map view of
//! the frame at 160 x 90, drawn by the inspector (the shadow maps by
//! src/demo/shadow_views.rs) into a small framebuffer of its own,
//! read back and handed to egui as its own textures (so egui owns them and
//! gloss's framebuffers stay gloss's). Redrawn twice a second while the
//! panel shows them.

use super::inspector::{Inspector, View};
use super::shadow_views::ShadowViews;
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::renderer::Renderer;
use crate::scene::Camera;
use anyhow::Result;
use std::time::{Duration, Instant};

pub const SIZE: (i32, i32) = (160, 90);

pub struct Thumbnails {
    fb: Option<Framebuffer>,
    /// One per view (None: a view with no thumbnail, such as the light volumes).
    pub textures: Vec<Option<egui::TextureHandle>>,
    drawn: Option<Instant>,
}

impl Thumbnails {
    pub fn new() -> Thumbnails {
        Thumbnails {
            fb: None,
            textures: Vec::new(),
            drawn: None,
        }
    }

    /// Draw the attachment views again if half a second has passed (or the
    /// views changed).
    #[allow(clippy::too_many_arguments)]
    pub fn update(
        &mut self,
        gl: &Gl,
        egui_ctx: &egui::Context,
        views: &[View],
        renderer: &Renderer,
        camera: &Camera,
        inspector: &Inspector,
        shadow_views: &mut ShadowViews,
        exposure: f32,
    ) -> Result<()> {
        let stale = self
            .drawn
            .is_none_or(|t| t.elapsed() > Duration::from_millis(500));
        if !stale && self.textures.len() == views.len() {
            return Ok(());
        }
        if self.fb.is_none() {
            self.fb = Some(Framebuffer::new(
                gl,
                "thumbnail",
                SIZE.0,
                SIZE.1,
                &[glow::RGBA8],
                None,
            )?);
        }
        let fb = self.fb.as_ref().expect("made above");
        self.textures.resize_with(views.len(), || None);
        for (i, v) in views.iter().enumerate() {
            if v.volumes.is_some() || v.difference || v.stencil {
                self.textures[i] = None;
                continue;
            }
            match &v.shadow {
                Some(s) => {
                    shadow_views.draw(s, renderer.shadows(), fb)?;
                }
                None => inspector.draw(gl, v, renderer.targets(), camera, exposure, fb),
            }
            let img = fb.read_rgba8_top_down(0);
            let image = egui::ColorImage::from_rgba_unmultiplied(
                [SIZE.0 as usize, SIZE.1 as usize],
                img.as_raw(),
            );
            match &mut self.textures[i] {
                Some(t) => t.set(image, egui::TextureOptions::LINEAR),
                slot => {
                    *slot = Some(egui_ctx.load_texture(
                        format!("thumbnail {i}"),
                        image,
                        egui::TextureOptions::LINEAR,
                    ))
                }
            }
        }
        self.drawn = Some(Instant::now());
        Ok(())
    }
}
