//! The `[tessellation]` table: a terrain drawn as patches that the GL 4.0
//! tessellator divides (notes 01 §3.1; src/techniques/vertex_geometry/
//! tessellation.rs).
//!
//! ```toml
//! [tessellation]
//! size = 20.0                  # the terrain's side, centred on the origin, on y = 0
//! patches = 16                 # patches a side
//! height = 1.5                 # the displacement map's white, in world units
//! displacement = "assets/ripples.png"   # grey PNG, read linear
//! levels = [1.0, 32.0]         # tessellation levels far and near
//! distances = [3.0, 30.0]      # where the level is the near one, and the far one
//! edges = "shared"             # "shared": a level per edge (no cracks); "per_patch": one per patch (cracks)
//! color = [0.45, 0.55, 0.35]
//! wireframe = false
//! ```

use super::checks::{finite, non_negative};
use anyhow::{Result, bail};
use glam::Vec3;
use serde::Deserialize;
use std::path::{Path, PathBuf};

#[derive(Deserialize, Debug, Clone)]
#[serde(deny_unknown_fields)]
pub(super) struct TessellationFile {
    #[serde(default = "size")]
    size: f32,
    #[serde(default = "patches")]
    patches: u32,
    #[serde(default = "height")]
    height: f32,
    displacement: String,
    #[serde(default = "levels")]
    levels: [f32; 2],
    #[serde(default = "distances")]
    distances: [f32; 2],
    #[serde(default = "shared")]
    edges: String,
    #[serde(default = "color")]
    color: [f32; 3],
    #[serde(default)]
    wireframe: bool,
}

fn size() -> f32 {
    20.0
}
fn patches() -> u32 {
    16
}
fn height() -> f32 {
    1.0
}
fn levels() -> [f32; 2] {
    [1.0, 32.0]
}
fn distances() -> [f32; 2] {
    [3.0, 30.0]
}
fn shared() -> String {
    "shared".into()
}
fn color() -> [f32; 3] {
    [0.45, 0.55, 0.35]
}

/// The most patches a side (256 x 256 patches of 4 corners).
pub const MAX_PATCHES: u32 = 256;
/// GL_MAX_TESS_GEN_LEVEL is at least 64 on every GL 4.0.
pub const MAX_LEVEL: f32 = 64.0;

/// The terrain, checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Tessellation {
    pub size: f32,
    pub patches: u32,
    pub height: f32,
    pub displacement: PathBuf,
    /// Far and near level.
    pub levels: [f32; 2],
    /// Near and far distance.
    pub distances: [f32; 2],
    /// A level per edge, from the edge's middle (the notes' rule); false:
    /// one level per patch, from its centre.
    pub shared_edges: bool,
    pub color: Vec3,
    pub wireframe: bool,
}

pub(super) fn resolve(f: Option<&TessellationFile>, base: &Path) -> Result<Option<Tessellation>> {
    let Some(t) = f else { return Ok(None) };
    if !(t.size.is_finite() && t.size > 0.0) {
        bail!("tessellation.size: expected a side > 0, found {}", t.size);
    }
    if !(1..=MAX_PATCHES).contains(&t.patches) {
        bail!(
            "tessellation.patches: expected 1..={MAX_PATCHES} patches a side, found {}",
            t.patches
        );
    }
    finite("tessellation.height", &[t.height])?;
    super::camera_limits::within_world("tessellation.size", &[t.size])?;
    super::camera_limits::within_world("tessellation.height", &[t.height])?;
    let [far, near] = t.levels;
    if !(far.is_finite() && near.is_finite() && far >= 1.0 && near >= far && near <= MAX_LEVEL) {
        bail!(
            "tessellation.levels: expected [far, near] with 1 <= far <= near <= {MAX_LEVEL}, found {:?}",
            t.levels
        );
    }
    non_negative("tessellation.distances", &t.distances)?;
    if t.distances[1] <= t.distances[0] {
        bail!(
            "tessellation.distances: expected [near, far] with near < far, found {:?}",
            t.distances
        );
    }
    non_negative("tessellation.color", &t.color)?;
    let shared_edges = match t.edges.as_str() {
        "shared" => true,
        "per_patch" => false,
        w => bail!("tessellation.edges: expected \"shared\" or \"per_patch\", found \"{w}\""),
    };
    let displacement = super::checks::relative_to(base, &t.displacement);
    if let Some(why) = crate::assets::not_a_file(&displacement) {
        bail!(
            "tessellation.displacement: file {} {why}",
            displacement.display()
        );
    }
    // Decoded now, so that a broken map is an error when the scene is read
    // (not a warning when the pass runs), in printable words.
    if let Err(e) = crate::gl::image_file::load_rgba8(&displacement) {
        bail!(
            "tessellation.displacement: {}",
            super::text::printable(&format!("{e:#}"))
        );
    }
    Ok(Some(Tessellation {
        size: t.size,
        patches: t.patches,
        height: t.height,
        displacement,
        levels: t.levels,
        distances: t.distances,
        shared_edges,
        color: Vec3::from(t.color),
        wireframe: t.wireframe,
    }))
}
