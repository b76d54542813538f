//! The pixel probe on the tiled path (src/techniques/deferred/tiled_shading.rs):
//! which cluster the pixel falls in, found as glsl/deferred/tiled_shading.frag
//! finds it (its tile from the pixel, its depth slice from the view-space
//! depth), and that cluster's light list as the tiled pass uploaded it this
//! frame (the lists it keeps in `DrawList::tiled_lists`), with the lights
//! every pixel shades (no radius: the global list; a shadow map: their own
//! loop). The lights reaching the point are those of these lists whose
//! radius holds it: the test the shader makes for each listed light.

use super::Renderer;
use crate::frame::clusters::{Bins, Grid};
use glam::Vec3;

/// The pixel's cluster and what the tiled pass listed for it.
#[derive(Clone, Debug, PartialEq)]
pub struct TileLists {
    /// The tile (column, row from the bottom, as gl_FragCoord counts) and
    /// the grid's size in tiles.
    pub tile: (u32, u32),
    pub tiles: (u32, u32),
    /// The depth slice, of `slices`.
    pub slice: u32,
    pub slices: u32,
    /// The cluster's list, in the order the shader loops over it.
    pub listed: Vec<usize>,
    /// The lights with no radius, shaded at every pixel.
    pub global: Vec<usize>,
    /// The lights with a shadow map, shaded at every pixel in a loop of their own.
    pub casters: Vec<usize>,
}

impl Renderer {
    /// The grid and lists the tiled pass uploaded for the camera's view in
    /// the frame last drawn (None: no tiled pass ran).
    pub fn tiled_lists(&self) -> Option<(Grid, Bins)> {
        self.draws.tiled_lists.borrow().clone()
    }

    /// The cluster of pixel (`x`, `y`) (from the top left) at view-space
    /// point `view` and the lists the tiled pass gave it; None off the
    /// tiled path or where nothing was drawn.
    pub(super) fn tile_lists(&self, x: u32, y: u32, view: Option<Vec3>) -> Option<TileLists> {
        let runs = (self.plan.passes.iter())
            .any(|p| crate::techniques::ALL[p.technique].name == "tiled_shading");
        let view = view?;
        let (grid, bins) = self.tiled_lists().filter(|_| runs)?;
        let gl_y = self.height as u32 - 1 - y;
        let tile = (
            (x / grid.tile_size).min(grid.tiles.0 - 1),
            (gl_y / grid.tile_size).min(grid.tiles.1 - 1),
        );
        let slice = grid.slice_of(-view.z);
        let [offset, count] = bins.clusters[grid.index(tile.0, tile.1, slice)];
        let (first, n) = (offset as usize, count as usize);
        let as_lights = |v: &[u32]| v.iter().map(|&i| i as usize).collect();
        Some(TileLists {
            tile,
            tiles: grid.tiles,
            slice,
            slices: grid.slices,
            listed: as_lights(&bins.indices[first..first + n]),
            global: as_lights(&bins.indices[..bins.global as usize]),
            casters: self.shadows.casting_lights(),
        })
    }
}

impl std::fmt::Display for TileLists {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let list = |v: &[usize]| match v.is_empty() {
            true => "none".to_string(),
            false => (v.iter().map(|l| l.to_string()))
                .collect::<Vec<_>>()
                .join(", "),
        };
        write!(
            f,
            "tile ({}, {}) of {}x{} (from the bottom left), depth slice {} of {}: the tiled pass listed {}; every pixel: {} (no radius), {} (shadow maps)",
            self.tile.0,
            self.tile.1,
            self.tiles.0,
            self.tiles.1,
            self.slice,
            self.slices,
            list(&self.listed),
            list(&self.global),
            list(&self.casters),
        )
    }
}
