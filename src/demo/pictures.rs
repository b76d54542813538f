//! `gloss render --target` for the images only the pass inspector draws:
//!
//! - `shadow_map.N`: light N's shadow map, a 2D map as the light sees it or
//!   a cube unfolded into the cross (src/demo/shadow_views.rs says how);
//! - `TARGET.N` for a target with mip levels: level N, stretched over the
//!   picture texel by texel (`bloom_levels.1` .. `bloom_levels.4`, the
//!   bloom's four blurs).
//!
//! Each is drawn by the inspector's own code into an RGBA8 framebuffer of
//! the frame's size and read back, so the picture is what the demo shows.
//! Every other name is the renderer's `read_target`.

use super::inspector::{Inspector, views};
use super::shadow_views::{ShadowView, ShadowViews};
use crate::gl::Gl;
use crate::gl::framebuffer::Framebuffer;
use crate::gl::program::Sources;
use crate::renderer::Renderer;
use anyhow::{Result, anyhow, bail};
use image::RgbaImage;

/// The CLI's name for the shadow maps: `shadow_map.N` is light N's.
pub const SHADOW_MAP: &str = "shadow_map";

/// The picture `gloss render --target name` writes, of the frame `r`
/// rendered last.
pub fn target_picture(gl: &Gl, sources: &Sources, r: &Renderer, name: &str) -> Result<RgbaImage> {
    let (target, part) = match name.split_once('.') {
        Some((t, p)) => (t, Some(p)),
        None => (name, None),
    };
    let number = |what: &str, example: u32| -> Result<u32> {
        let p = part
            .ok_or_else(|| anyhow!("--target {name}: name {what}, such as {target}.{example}"))?;
        p.parse()
            .map_err(|_| anyhow!("--target {name}: {p:?} is not {what}"))
    };
    if target == SHADOW_MAP {
        let shadows = r.shadows();
        let casters: Vec<String> = shadows
            .maps
            .iter()
            .map(|(c, _)| c.light.to_string())
            .collect();
        if casters.is_empty() {
            bail!("--target {name}: no light of this scene casts a shadow");
        }
        let light = number("a light's index", shadows.maps[0].0.light as u32)? as usize;
        let kind = |i: usize| r.scene.lights[i].kind;
        let view = ShadowView::of(shadows.maps.iter().map(|(c, _)| c), kind)
            .into_iter()
            .find(|v| v.light == light)
            .ok_or_else(|| {
                anyhow!(
                    "--target {name}: light {light} casts no shadow; the lights that do: {}",
                    casters.join(", ")
                )
            })?;
        let into = framebuffer(gl, r)?;
        ShadowViews::new(gl, sources)?.draw(&view, shadows, &into)?;
        return Ok(into.read_rgba8_top_down(0));
    }
    let Some(mips) = r.targets().mip(target) else {
        return r.read_target(name);
    };
    let level = number("a mip level", mips.first())?;
    if mips.level(level).is_none() {
        let (first, last) = (mips.first(), mips.last());
        bail!("--target {name}: {target} has the mip levels {first}..={last}");
    }
    let view = views(&r.plan, false, &[])
        .into_iter()
        .find(|v| v.target == target && v.level == level)
        .ok_or_else(|| anyhow!("--target {name}: the inspector has no view of it"))?;
    let into = framebuffer(gl, r)?;
    Inspector::new(gl, sources)?.draw(gl, &view, r.targets(), &r.scene.camera, 1.0, &into);
    Ok(into.read_rgba8_top_down(0))
}

/// An RGBA8 framebuffer of the frame's size to draw the picture into.
fn framebuffer(gl: &Gl, r: &Renderer) -> Result<Framebuffer> {
    Framebuffer::new(gl, "picture", r.width, r.height, &[glow::RGBA8], None)
}
