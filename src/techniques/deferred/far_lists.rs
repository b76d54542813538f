//! The far field's per-cluster far lists (`render.far_radius = a`), beyond
//! the notes, for the pixels no far-field sample stands for (edges, curved
//! surfaces: docs/deferred/far_field.md, "Far lists"). Without them such a
//! pixel sums the far part of every light itself; on a GPU a warp then
//! waits for its slowest pixel, so a few of them cost every pixel the loop
//! over all lights.
//!
//! With them each light's far part is split once more, by a weight `v(d)`
//! that is 0 up to `a r` and rises (a smoothstep) to 1 at `2 a r` (`r`: the
//! cutoff radius; `a >= 1`, so `v` is 0 wherever the near part is not):
//!
//! - `(1 - v) x far`: the lights within `2 a r`. Tiled shading bins them
//!   per cluster as it bins the near parts (src/frame/clusters.rs, spheres
//!   of radius `2 a r`); a pixel that keeps no sample sums its own
//!   cluster's far list, exactly.
//! - `v x far`: every light at least `a r` away. The far-field pass stores,
//!   per sample, its diffuse light as order-1 spherical harmonics (band 0
//!   moved to make the sample's own normal exact) and its specular light;
//!   such a pixel takes them from the nearest of its four samples within
//!   `a r_min / 2` of it, and sums them itself only where none is
//!   (glsl/common/far_field.glsl, `far_fallback`).
//!
//! Upload: one R32UI buffer, as tiled shading's: each cluster's near
//! (offset, count), then each cluster's far (offset, count), then the near
//! light numbers, then the far ones.

use crate::frame::clusters::{self, Bins, Bound, Grid};
use crate::frame::lights::FrameLights;
use crate::scene::{Light, Scene};
use glam::{Mat4, Vec3};

/// Each light's bound for its far list: the sphere of radius `2 a r`
/// (`a`: `render.far_radius`) around it, as `sphere` gives it (tiled
/// shading's `bounding_sphere`, which bounds a spot light's cone); nowhere
/// for the lights with no far part (no radius, or a shadow map this frame).
/// Whether the lists run at all is `far_field::lists_on`.
pub fn far_bounds(
    scene: &Scene,
    lights: &FrameLights,
    casting: &[usize],
    bounding_sphere: fn(&Light, f32) -> (Vec3, f32),
) -> Vec<Bound> {
    let a = scene.render.far_radius as f32;
    (scene.lights.iter().zip(&lights.lights).enumerate())
        .map(|(i, (l, f))| match (casting.contains(&i), f.radius) {
            (false, Some(r)) => {
                let (c, r) = bounding_sphere(l, 2.0 * a * r);
                Bound::Sphere(c, r)
            }
            _ => Bound::Apart,
        })
        .collect()
}

/// The far lists on `grid` (the grid the near lists were binned on).
pub fn bin(grid: &Grid, view: Mat4, projection: Mat4, size: (u32, u32), bounds: &[Bound]) -> Bins {
    clusters::bin(grid, view, projection, size, bounds)
}

/// What tiled shading uploads, and where: the texels (near table, far
/// table, near numbers, far numbers), the near numbers' first texel
/// (`u_index_base`) and the far numbers' (`u_far_index_base`). Without far
/// lists (`far` None) the layout is tiled shading's own.
pub fn texels(near: &Bins, far: Option<&Bins>) -> (Vec<u32>, i32, i32) {
    let tables = near.clusters.len() * if far.is_some() { 4 } else { 2 };
    let mut out: Vec<u32> = Vec::with_capacity(tables + near.indices.len());
    out.extend(near.clusters.iter().flatten());
    if let Some(f) = far {
        out.extend(f.clusters.iter().flatten());
    }
    out.extend(&near.indices);
    let far_base = out.len() as i32;
    if let Some(f) = far {
        out.extend(&f.indices);
    }
    (out, tables as i32, far_base)
}

/// How many texels the upload takes: to check against
/// GL_MAX_TEXTURE_BUFFER_SIZE before building it.
pub fn texel_count(near: &Bins, far: &Bins) -> usize {
    4 * near.clusters.len() + near.indices.len() + far.indices.len()
}
