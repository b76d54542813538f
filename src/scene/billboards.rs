//! Billboards in a scene file (notes 05, "Billboards"): textured quads that
//! face the camera, given one by one (`[[billboards]]`) or scattered by a
//! seeded generator (`[[billboard_fields]]`, a forest or a meadow).
//!
//! ```toml
//! [[billboards]]
//! sprite = "assets/tree.png"   # RGBA PNG; alpha 0 where the tree is not
//! center = [0.0, 2.0, 0.0]     # the quad's centre, world space
//! size = [3.0, 4.0]            # width, height
//! kind = "cylindrical"         # or "spherical" (the default)
//!
//! [[billboard_fields]]
//! sprite = "assets/grass.png"
//! kind = "spherical"           # "cylindrical" is the default
//! count = 300
//! seed = 7
//! area = [-10.0, 10.0, -10.0, 10.0]   # [xmin, xmax, zmin, zmax]
//! ground = 0.0                 # the bottom edges stand at this height
//! height = [0.5, 1.0]          # each billboard's height, drawn in this range
//! aspect = 1.0                 # width / height
//! ```

use super::camera_limits::within_world;
use super::checks::finite;
use super::light_grid::SplitMix;
use super::settings::BillboardKind;
use crate::assets;
use anyhow::{Result, bail};
use glam::{Vec2, Vec3};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The most billboards a scene may have (lists and fields together).
pub const MAX_BILLBOARDS: usize = 100_000;

/// One `[[billboards]]` entry, as written (the sprite relative to the file).
#[derive(Deserialize, serde::Serialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BillboardFile {
    pub sprite: String,
    pub center: [f32; 3],
    pub size: [f32; 2],
    #[serde(default = "spherical")]
    pub kind: BillboardKind,
}

/// One `[[billboard_fields]]` entry, as written.
#[derive(Deserialize, serde::Serialize, Debug, Clone, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BillboardFieldFile {
    pub sprite: String,
    #[serde(default = "cylindrical")]
    pub kind: BillboardKind,
    pub count: usize,
    #[serde(default = "one_u64")]
    pub seed: u64,
    /// [xmin, xmax, zmin, zmax]
    pub area: [f32; 4],
    #[serde(default)]
    pub ground: f32,
    /// [min, max] height.
    pub height: [f32; 2],
    /// width / height
    #[serde(default = "one")]
    pub aspect: f32,
}

fn spherical() -> BillboardKind {
    BillboardKind::Spherical
}
fn cylindrical() -> BillboardKind {
    BillboardKind::Cylindrical
}
fn one_u64() -> u64 {
    1
}
fn one() -> f32 {
    1.0
}

/// One billboard: a quad of `size` (width, height) about `center`, showing
/// sprite `sprite` (an index into `Scene::sprites`).
#[derive(Clone, Debug, PartialEq)]
pub struct Billboard {
    pub center: Vec3,
    pub size: Vec2,
    pub sprite: usize,
    pub kind: BillboardKind,
}

impl super::Scene {
    /// Take new `[[billboards]]` and `[[billboard_fields]]` (the demo edits
    /// them), checked as the loader checks them; on an error nothing changes.
    pub fn set_billboards(
        &mut self,
        list: Vec<BillboardFile>,
        fields: Vec<BillboardFieldFile>,
    ) -> Result<()> {
        let base = self.path.parent().unwrap_or(Path::new("."));
        let (sprites, billboards) = expand(&list, &fields, base)?;
        (self.sprites, self.billboards) = (sprites, billboards);
        (self.billboard_list, self.billboard_fields) = (list, fields);
        Ok(())
    }
}

/// The sprites (PNG paths, each once, in order of first use) and the
/// billboards of a `[[billboards]]` list, then of each field, in file order
/// (sprites relative to `base`).
pub(super) fn expand(
    list: &[BillboardFile],
    fields: &[BillboardFieldFile],
    base: &Path,
) -> Result<(Vec<PathBuf>, Vec<Billboard>)> {
    let mut sprites: Vec<PathBuf> = Vec::new();
    let mut sprite_index = |key: &str, written: &str| -> Result<usize> {
        let p = super::checks::relative_to(base, written);
        if let Some(i) = sprites.iter().position(|s| *s == p) {
            return Ok(i);
        }
        if !assets::has_extension(written, "png") {
            bail!("{key}: expected an RGBA .png file, found \"{written}\"");
        }
        if let Some(why) = assets::not_a_file(&p) {
            bail!("{key}: sprite file {} {why}", p.display());
        }
        sprites.push(p);
        Ok(sprites.len() - 1)
    };
    let total: usize = list.len()
        + fields
            .iter()
            .map(|g| g.count)
            .fold(0, usize::saturating_add);
    if total > MAX_BILLBOARDS {
        bail!("billboards: at most {MAX_BILLBOARDS} billboards in a scene, found {total}");
    }
    let mut out = Vec::with_capacity(total);
    for (i, b) in list.iter().enumerate() {
        let key = |k: &str| format!("billboards[{i}].{k}");
        finite(&key("center"), &b.center)?;
        within_world(&key("center"), &b.center)?;
        positive(&key("size"), &b.size)?;
        out.push(Billboard {
            center: Vec3::from(b.center),
            size: Vec2::from(b.size),
            sprite: sprite_index(&key("sprite"), &b.sprite)?,
            kind: b.kind,
        });
    }
    for (i, g) in fields.iter().enumerate() {
        let key = |k: &str| format!("billboard_fields[{i}].{k}");
        let [x0, x1, z0, z1] = g.area;
        finite(&key("area"), &g.area)?;
        within_world(&key("area"), &g.area)?;
        if !(x0 <= x1 && z0 <= z1) {
            bail!(
                "{}: expected [xmin, xmax, zmin, zmax] with min <= max, found {:?}",
                key("area"),
                g.area
            );
        }
        finite(&key("ground"), &[g.ground])?;
        within_world(&key("ground"), &[g.ground])?;
        positive(&key("height"), &g.height)?;
        if g.height[0] > g.height[1] {
            bail!(
                "{}: expected [min, max] with min <= max, found {:?}",
                key("height"),
                g.height
            );
        }
        positive(&key("aspect"), &[g.aspect])?;
        let sprite = sprite_index(&key("sprite"), &g.sprite)?;
        out.extend(generate(g, sprite));
    }
    Ok((sprites, out))
}

fn positive(key: &str, v: &[f32]) -> Result<()> {
    finite(key, v)?;
    within_world(key, v)?;
    if v.iter().any(|x| *x <= 0.0) {
        bail!("{key}: expected values > 0, found {v:?}");
    }
    Ok(())
}

/// A field's billboards: uniform in the area, standing on the ground, the
/// same ones for the same seed everywhere.
fn generate(g: &BillboardFieldFile, sprite: usize) -> Vec<Billboard> {
    let mut rng = SplitMix(g.seed);
    let [x0, x1, z0, z1] = g.area;
    (0..g.count)
        .map(|_| {
            let x = x0 + (x1 - x0) * rng.next_f32();
            let z = z0 + (z1 - z0) * rng.next_f32();
            let h = g.height[0] + (g.height[1] - g.height[0]) * rng.next_f32();
            Billboard {
                center: Vec3::new(x, g.ground + 0.5 * h, z),
                size: Vec2::new(h * g.aspect, h),
                sprite,
                kind: g.kind,
            }
        })
        .collect()
}
