//! An object's `light_map` key (notes 01 §8.2, static lighting): the light
//! map src/lighting/static_lighting.rs bakes when the scene loads.

use super::MeshSource;
use super::file::LightMapFile;
use anyhow::{Result, bail};

/// An object's light map: texels a side, and whether the bake casts shadow rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightMapSettings {
    pub size: u32,
    pub shadows: bool,
}

/// The largest light map side.
pub const MAX_LIGHT_MAP: u32 = 2048;

/// Check object `i`'s `light_map` (its mesh `mesh`).
pub(super) fn light_map(
    i: usize,
    file: Option<LightMapFile>,
    mesh: &MeshSource,
) -> Result<Option<LightMapSettings>> {
    Ok(match file {
        None => None,
        Some(_) if matches!(mesh, MeshSource::Gltf(_) | MeshSource::GltfPart(_)) => {
            bail!(
                "objects[{i}].light_map: a glTF file's meshes are not light-mapped (a skin moves, and its nodes are objects of their own); bake built-in or OBJ meshes"
            )
        }
        Some(l) if !(1..=MAX_LIGHT_MAP).contains(&l.size) => bail!(
            "objects[{i}].light_map.size: expected 1..={MAX_LIGHT_MAP} texels a side, found {}",
            l.size
        ),
        Some(l) => Some(LightMapSettings {
            size: l.size,
            shadows: l.shadows,
        }),
    })
}
