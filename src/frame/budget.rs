//! The frame's budget, checked before anything is allocated or baked, by
//! `gloss plan` as by `gloss render`: every texture the frame asks the GL
//! for (the render targets, shadow maps, the skybox's or sky's cube map,
//! light maps, material textures) against
//!
//! - GL's limits on a side (GL_MAX_TEXTURE_SIZE, GL_MAX_CUBE_MAP_TEXTURE_SIZE,
//!   GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS): only `gloss render`,
//!   which has a GL, checks these; the plan names them as not checked;
//! - `MAX_TEXTURE_BYTES` for one texture and `MEMORY_BUDGET` for all;
//!
//! and the light maps' bake against `MAX_BAKE_WORK`. A message names the
//! key as the scene file writes it, its value, and the limit.

use crate::frame::targets::{TargetDesc, format_name, size_name};
use crate::gl::Gl;
use crate::gl::image_file::MAX_TEXTURE_SIDE;
use crate::scene::skybox::Environment;
use crate::scene::{LightKind, Scene};
use anyhow::{Result, bail};
use glow::HasContext;

/// The most memory gloss asks the GL for in one frame's textures.
pub const MEMORY_BUDGET: u64 = 2 << 30;

/// The most one texture may take (a driver may refuse a larger one even
/// when the sum fits, and then only says GL_OUT_OF_MEMORY).
pub const MAX_TEXTURE_BYTES: u64 = 1 << 30;

/// The most work the light maps' bake may take, in texel-light evaluations,
/// a shadow ray counting `SHADOW_RAY_WORK` more: about half a minute on one
/// core of a laptop (0.5 us an evaluation, 1.5 us a shadow ray).
pub const MAX_BAKE_WORK: u64 = 1 << 26;

pub use crate::frame::light_maps::SHADOW_RAY_WORK;

/// GL's limits on a texture's side, as this GL gives them.
#[derive(Clone, Copy, Debug)]
pub struct GlLimits {
    pub texture: u32,
    pub cube_map: u32,
    pub renderbuffer: u32,
    pub viewport: (u32, u32),
}

impl GlLimits {
    pub fn query(gl: &Gl) -> GlLimits {
        let get = |p| unsafe { gl.get_parameter_i32(p) }.max(0) as u32;
        let mut dims = [0i32; 2];
        unsafe { gl.get_parameter_i32_slice(glow::MAX_VIEWPORT_DIMS, &mut dims) };
        GlLimits {
            texture: get(glow::MAX_TEXTURE_SIZE),
            cube_map: get(glow::MAX_CUBE_MAP_TEXTURE_SIZE),
            renderbuffer: get(glow::MAX_RENDERBUFFER_SIZE),
            viewport: (dims[0].max(0) as u32, dims[1].max(0) as u32),
        }
    }
}

/// Which of GL's limits a texture's side is held to.
#[derive(Clone, Copy, PartialEq)]
enum Side {
    /// A 2D texture.
    Texture,
    /// A face of a cube map.
    Cube,
    /// A render target: a 2D texture drawn into through the viewport.
    Target,
}

/// One texture (or group of textures) the frame asks for.
struct Item {
    /// The key that sets it, with its value ("lights[0].shadow.resolution = 8192").
    key: String,
    /// What it is, in words.
    what: String,
    /// Its side(s) in texels.
    size: (u32, u32),
    side: Side,
    /// Its largest single texture, and all of it.
    largest: u64,
    bytes: u64,
}

fn items(scene: &Scene, targets: &[TargetDesc], width: u32, height: u32) -> Vec<Item> {
    let mut v = Vec::new();
    let largest_target = (targets.iter())
        .flat_map(|t| t.single_textures(width, height))
        .max()
        .unwrap_or(0);
    v.push(Item {
        key: format!("render.size = {width}x{height} (or --size)"),
        what: format!(
            "the {} path's {} render targets",
            scene.render.path.name(),
            targets.len()
        ),
        size: (width, height),
        side: Side::Target,
        largest: largest_target,
        bytes: targets.iter().map(|t| t.bytes(width, height)).sum(),
    });
    let depth = crate::frame::targets::bytes_per_pixel(crate::gl::depth_map::FORMAT);
    for c in crate::frame::shadows::casters(scene) {
        let r = c.shadow.resolution;
        let face = u64::from(r) * u64::from(r) * depth;
        let (what, side, bytes) = if c.cube {
            let f = format_name(crate::gl::depth_map::FORMAT);
            let what = format!("the point light's shadow cube map (6 faces of {r}x{r} {f})");
            (what, Side::Cube, 6 * face)
        } else {
            let kind = match scene.lights[c.light].kind {
                LightKind::Spot => "spot",
                _ => "directional",
            };
            (
                format!("the {kind} light's shadow map"),
                Side::Texture,
                face,
            )
        };
        v.push(Item {
            key: format!("lights[{}].shadow.resolution = {r}", c.light),
            what,
            size: (r, r),
            side,
            largest: bytes,
            bytes,
        });
    }
    match scene.environment() {
        Some(Environment::Faces(paths)) => {
            if let Ok((w, h)) = crate::gl::image_file::dimensions(&paths[0])
                && w.max(h) <= MAX_TEXTURE_SIDE
            {
                // SRGB8_ALPHA8 with its mip chain (a third more).
                let bytes = 6 * u64::from(w) * u64::from(h) * 4 * 4 / 3;
                v.push(Item {
                    key: format!("skybox.faces = {w}x{h} images"),
                    what: "the skybox's cube map (6 faces, with their mip levels)".into(),
                    size: (w, h),
                    side: Side::Cube,
                    largest: bytes,
                    bytes,
                });
            }
        }
        Some(Environment::Sky { size }) => {
            let bytes = 6 * u64::from(size) * u64::from(size) * 8 * 4 / 3;
            v.push(Item {
                key: format!("skybox.size = {size}"),
                what: "the sky's RGBA16F cube map".into(),
                size: (size, size),
                side: Side::Cube,
                largest: bytes,
                bytes,
            });
        }
        None => {}
    }
    for (i, o) in scene.objects.iter().enumerate() {
        if let Some(l) = o.light_map.filter(|_| scene.render.light_maps) {
            let bytes = u64::from(l.size) * u64::from(l.size) * 8;
            v.push(Item {
                key: format!("objects[{i}].light_map.size = {}", l.size),
                what: format!("object {}'s RGBA16F light map", o.name),
                size: (l.size, l.size),
                side: Side::Texture,
                largest: bytes,
                bytes,
            });
        }
    }
    let mut seen = Vec::new();
    for m in &scene.materials {
        for (key, p) in [
            ("diffuse_texture", &m.diffuse_texture),
            ("normal_map", &m.normal_map),
            ("specular_map", &m.specular_map),
            ("alpha_map", &m.alpha_map),
            ("metallic_roughness", &m.pbr.metallic_roughness),
            ("occlusion", &m.pbr.occlusion),
            ("emissive_map", &m.pbr.emissive_map),
        ] {
            let Some(p) = p.as_ref().filter(|p| !seen.contains(*p)) else {
                continue;
            };
            seen.push(p.clone());
            // A side past MAX_TEXTURE_SIDE: the loader refuses it, in its words.
            if let Ok((w, h)) = crate::gl::image_file::dimensions(p)
                && w.max(h) <= MAX_TEXTURE_SIDE
            {
                let bytes = u64::from(w) * u64::from(h) * 4 * 4 / 3;
                v.push(Item {
                    key: format!("materials.{}.{key} = {w}x{h} image", m.name),
                    what: format!("texture {}", p.display()),
                    size: (w, h),
                    side: Side::Texture,
                    largest: bytes,
                    bytes,
                });
            }
        }
    }
    v
}

/// Check the frame of `scene`, with render targets `targets` at `width` x
/// `height`, against the budget, and against `gl`'s limits when there is
/// a GL. Returns what it could not check without one, in words.
pub fn check(
    scene: &Scene,
    targets: &[TargetDesc],
    width: u32,
    height: u32,
    gl: Option<&GlLimits>,
) -> Result<Vec<String>> {
    let file = scene.path.display();
    let items = items(scene, targets, width, height);
    let mut unchecked = Vec::new();
    for it in &items {
        let (w, h) = it.size;
        let limits: Vec<(&str, u32)> = match (gl, it.side) {
            (None, _) => Vec::new(),
            (Some(g), Side::Texture) => vec![("GL_MAX_TEXTURE_SIZE", g.texture)],
            (Some(g), Side::Cube) => vec![("GL_MAX_CUBE_MAP_TEXTURE_SIZE", g.cube_map)],
            (Some(g), Side::Target) => vec![
                ("GL_MAX_TEXTURE_SIZE", g.texture),
                ("GL_MAX_RENDERBUFFER_SIZE", g.renderbuffer),
                ("GL_MAX_VIEWPORT_DIMS", g.viewport.0.min(g.viewport.1)),
            ],
        };
        for (name, limit) in limits {
            if w.max(h) > limit {
                bail!(
                    "{file}: {}: {} is {w}x{h}, larger than this GL's {name} ({limit})",
                    it.key,
                    it.what
                );
            }
        }
        if gl.is_none() && it.side == Side::Cube {
            unchecked.push(format!("GL_MAX_CUBE_MAP_TEXTURE_SIZE for {}", it.key));
        }
        if it.largest > MAX_TEXTURE_BYTES {
            bail!(
                "{file}: {}: {} takes {}; gloss asks for at most {} in one texture (MAX_TEXTURE_BYTES)",
                it.key,
                it.what,
                amount(it.largest),
                amount(MAX_TEXTURE_BYTES)
            );
        }
    }
    let total: u64 = items.iter().map(|i| i.bytes).sum();
    if total > MEMORY_BUDGET {
        let mut parts: Vec<&Item> = items.iter().filter(|i| i.bytes > 0).collect();
        parts.sort_by_key(|i| std::cmp::Reverse(i.bytes));
        let list: Vec<String> = (parts.iter().take(4))
            .map(|i| format!("{} ({}): {}", i.key, i.what, amount(i.bytes)))
            .collect();
        bail!(
            "{file}: the frame's textures take {}, over gloss's budget of {} (MEMORY_BUDGET); the largest: {}",
            amount(total),
            amount(MEMORY_BUDGET),
            list.join("; ")
        );
    }
    check_bake(scene)?;
    Ok(unchecked)
}

fn check_bake(scene: &Scene) -> Result<()> {
    let work = crate::frame::light_maps::bake_work(scene);
    let total: u64 = work.iter().map(|w| w.1).sum();
    if total <= MAX_BAKE_WORK {
        return Ok(());
    }
    let (i, most) = *work.iter().max_by_key(|w| w.1).expect("some work");
    let l = scene.objects[i].light_map.expect("a light map");
    bail!(
        "{}: objects[{i}].light_map = {{ size = {}, shadows = {} }}: baking the light maps takes {total} texel-light evaluations ({} lights; a shadow ray counts {} more), over gloss's limit of {MAX_BAKE_WORK} (MAX_BAKE_WORK); this one takes {most}: lower its size, the lights or shadows",
        scene.path.display(),
        l.size,
        l.shadows,
        scene.lights.len(),
        SHADOW_RAY_WORK
    )
}

/// "5.20 GiB", "341 KiB": `size_name`, with GiB.
fn amount(bytes: u64) -> String {
    if bytes >= 1 << 30 {
        format!("{:.2} GiB", bytes as f64 / f64::from(1u32 << 30))
    } else {
        size_name(bytes)
    }
}
