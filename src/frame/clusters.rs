//! Light binning for tiled and clustered shading, on the CPU (GL 3.3 has no
//! compute shaders): Persson, "Practical Clustered Shading" (SIGGRAPH 2015),
//! after Olsson and Assarsson, "Tiled Shading" (2011) and Olsson, Billeter
//! and Assarsson, "Clustered Deferred and Forward Shading" (2012).
//!
//! The view is cut into screen tiles of `tile_size` pixels and, along the
//! view direction, into `slices` depth slices spaced exponentially between
//! the near and far planes (slice k starts at near * (far / near)^(k / S)),
//! so a cluster is about as deep as it is wide at every distance. Each
//! light's bounding sphere at its cutoff radius is binned into every
//! cluster it may touch; a pixel then shades only its own cluster's lights.
//! A light with no finite radius (directional, or Kl = Kq = 0) reaches
//! every pixel: it goes in the `global` list instead.
//!
//! The binning is conservative: for each slice, the part of the sphere
//! inside the slice's depth range lies in a box (the sphere's widest cross
//! section within that range, by that range's depth); the box's eight
//! corners, projected, bound the tiles. A small margin (a pixel, a
//! thousandth of the depth) absorbs the difference between this f32
//! arithmetic and the shader's. The shader still tests each listed light
//! against its radius, so a light listed where it does not reach costs time
//! only, and the image is exactly the light volumes' image.

use glam::{Mat4, Vec3, Vec4};

/// The cluster grid of one view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Tile edge in pixels.
    pub tile_size: u32,
    /// Tiles across and up the view's rectangle.
    pub tiles: (u32, u32),
    /// Depth slices between `near` and `far` (1: tiled shading, no slicing).
    pub slices: u32,
    pub near: f32,
    pub far: f32,
}

impl Grid {
    /// The grid over a `width` x `height` view (pixels).
    pub fn new(width: u32, height: u32, tile_size: u32, slices: u32, near: f32, far: f32) -> Grid {
        let tile_size = tile_size.max(1);
        Grid {
            tile_size,
            tiles: (
                width.div_ceil(tile_size).max(1),
                height.div_ceil(tile_size).max(1),
            ),
            slices: slices.max(1),
            near,
            far,
        }
    }

    /// How many clusters: tiles across x tiles up x slices.
    pub fn clusters(&self) -> usize {
        self.tiles.0 as usize * self.tiles.1 as usize * self.slices as usize
    }

    /// (scale, bias) with slice = floor(ln(depth) * scale + bias): what the
    /// shader is given, and what `slice_of` computes with.
    pub fn slice_scale_bias(&self) -> (f32, f32) {
        let scale = self.slices as f32 / (self.far / self.near).ln();
        (scale, -self.near.ln() * scale)
    }

    /// The slice a point at view-space depth `depth` (> 0, in front of the
    /// eye) falls in, clamped to the grid.
    pub fn slice_of(&self, depth: f32) -> u32 {
        let (scale, bias) = self.slice_scale_bias();
        let s = (depth.max(f32::MIN_POSITIVE).ln() * scale + bias).floor();
        s.clamp(0.0, (self.slices - 1) as f32) as u32
    }

    /// Where slice `k` starts: near * (far / near)^(k / slices).
    pub fn slice_start(&self, k: u32) -> f32 {
        if k == 0 {
            return self.near;
        }
        if k >= self.slices {
            return self.far;
        }
        self.near * (self.far / self.near).powf(k as f32 / self.slices as f32)
    }

    /// The cluster index of tile (x, y) in slice `slice` (the shader's order).
    pub fn index(&self, x: u32, y: u32, slice: u32) -> usize {
        ((slice * self.tiles.1 + y) * self.tiles.0 + x) as usize
    }
}

/// The lists the shader reads.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bins {
    /// Light numbers: first the `global` ones, then each cluster's list.
    pub indices: Vec<u32>,
    /// How many of `indices` every pixel shades (the lights with no radius).
    pub global: u32,
    /// Per cluster: (offset into `indices`, count).
    pub clusters: Vec<[u32; 2]>,
    /// Lights binned nowhere: wholly outside the view.
    pub culled: u32,
}

impl Bins {
    /// The mean number of listed lights over the clusters that list any.
    pub fn mean_per_cluster(&self) -> f32 {
        let used: Vec<u32> = (self.clusters.iter().map(|c| c[1]))
            .filter(|&n| n > 0)
            .collect();
        if used.is_empty() {
            return 0.0;
        }
        used.iter().sum::<u32>() as f32 / used.len() as f32
    }

    /// The longest cluster list.
    pub fn max_per_cluster(&self) -> u32 {
        self.clusters.iter().map(|c| c[1]).max().unwrap_or(0)
    }
}

/// What the binning does with a light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// Into the clusters this sphere (world centre, radius) may touch.
    Sphere(Vec3, f32),
    /// Into the global list: every pixel shades it.
    Everywhere,
    /// Nowhere: the caller shades it some other way (a shadow caster).
    Apart,
}

/// One light's footprint in one slice: tiles x0..=x1, y0..=y1.
struct Footprint {
    light: u32,
    slice: u32,
    x: (u32, u32),
    y: (u32, u32),
}

/// Bin the lights' bounds into `grid`. `view` takes world space to the
/// view's eye space (looking down -Z), `projection` eye space to clip space;
/// `size` is the view's rectangle in pixels.
pub fn bin(grid: &Grid, view: Mat4, projection: Mat4, size: (u32, u32), bounds: &[Bound]) -> Bins {
    let mut bins = Bins {
        clusters: vec![[0, 0]; grid.clusters()],
        ..Bins::default()
    };
    let mut prints = Vec::new();
    for (i, b) in bounds.iter().enumerate() {
        let (centre, radius) = match *b {
            Bound::Sphere(c, r) => (c, r),
            Bound::Everywhere => {
                bins.indices.push(i as u32);
                continue;
            }
            Bound::Apart => continue,
        };
        let before = prints.len();
        footprints(
            grid,
            view,
            projection,
            size,
            i as u32,
            centre,
            radius,
            &mut prints,
        );
        if prints.len() == before {
            bins.culled += 1;
        }
    }
    bins.global = bins.indices.len() as u32;
    // Count, then place: each cluster's list is contiguous, in light order.
    for p in &prints {
        for y in p.y.0..=p.y.1 {
            for x in p.x.0..=p.x.1 {
                bins.clusters[grid.index(x, y, p.slice)][1] += 1;
            }
        }
    }
    let mut offset = bins.global;
    for c in &mut bins.clusters {
        c[0] = offset;
        offset += c[1];
    }
    bins.indices.resize(offset as usize, 0);
    let mut fill: Vec<u32> = bins.clusters.iter().map(|c| c[0]).collect();
    for p in &prints {
        for y in p.y.0..=p.y.1 {
            for x in p.x.0..=p.x.1 {
                let c = grid.index(x, y, p.slice);
                bins.indices[fill[c] as usize] = p.light;
                fill[c] += 1;
            }
        }
    }
    bins
}

/// The clusters a sphere may touch, slice by slice.
#[allow(clippy::too_many_arguments)]
fn footprints(
    grid: &Grid,
    view: Mat4,
    projection: Mat4,
    size: (u32, u32),
    light: u32,
    centre: Vec3,
    radius: f32,
    out: &mut Vec<Footprint>,
) {
    let c = view.transform_point3(centre);
    let depth = -c.z;
    // The margin: the shader reconstructs depth from a 24-bit buffer.
    let (lo, hi) = (
        (depth - radius).max(grid.near) * (1.0 - 1e-3),
        (depth + radius).min(grid.far) * (1.0 + 1e-3),
    );
    if depth + radius < grid.near
        || depth - radius > grid.far
        || lo.is_nan()
        || hi.is_nan()
        || lo > hi
    {
        return;
    }
    for slice in grid.slice_of(lo)..=grid.slice_of(hi) {
        // The slab of depths this slice holds, within the sphere's.
        // (The last slice runs to `hi`, which the margin puts past far.)
        let z0 = grid.slice_start(slice).max(lo);
        let end = if slice + 1 == grid.slices {
            hi
        } else {
            grid.slice_start(slice + 1).min(hi)
        };
        let z1 = end.max(z0);
        // The sphere's widest cross section within [z0, z1].
        let gap = if depth < z0 {
            z0 - depth
        } else if depth > z1 {
            depth - z1
        } else {
            0.0
        };
        // (r - gap)(r + gap), not r^2 - gap^2: r^2 overflows f32 past 1.8e19
        // (a tiny cutoff gives such radii).
        let r = ((radius - gap) * (radius + gap)).max(0.0).sqrt() * (1.0 + 1e-4);
        let Some((x, y)) = tiles_of_box(grid, projection, size, c, r, z0, z1) else {
            continue;
        };
        out.push(Footprint { light, slice, x, y });
    }
}

/// The tiles the box [c.x ± r] x [c.y ± r] x depths [z0, z1] (eye space,
/// z0 >= near > 0) projects onto, or None when it misses the view.
fn tiles_of_box(
    grid: &Grid,
    projection: Mat4,
    size: (u32, u32),
    c: Vec3,
    r: f32,
    z0: f32,
    z1: f32,
) -> Option<((u32, u32), (u32, u32))> {
    let all = ((0, grid.tiles.0 - 1), (0, grid.tiles.1 - 1));
    let (mut min, mut max) = (
        glam::Vec2::splat(f32::INFINITY),
        glam::Vec2::splat(f32::NEG_INFINITY),
    );
    for corner in 0..8 {
        let x = if corner & 1 == 0 { c.x - r } else { c.x + r };
        let y = if corner & 2 == 0 { c.y - r } else { c.y + r };
        let z = if corner & 4 == 0 { -z0 } else { -z1 };
        let clip = projection * Vec4::new(x, y, z, 1.0);
        // In front of the near plane w > 0 (perspective) or w = 1 (orthographic).
        let ndc = clip.truncate().truncate() / clip.w.max(f32::MIN_POSITIVE);
        if !ndc.is_finite() {
            // A box too large for f32 (inf * 0 in the projection): it
            // covers the view, so every tile, conservatively.
            return Some(all);
        }
        min = min.min(ndc);
        max = max.max(ndc);
    }
    // NDC to pixels within the view's rectangle, one pixel of margin.
    let (w, h) = (size.0 as f32, size.1 as f32);
    let px = |n: f32, extent: f32| (n * 0.5 + 0.5) * extent;
    let (x0, x1) = (px(min.x, w) - 1.0, px(max.x, w) + 1.0);
    let (y0, y1) = (px(min.y, h) - 1.0, px(max.y, h) + 1.0);
    if x1 < 0.0 || y1 < 0.0 || x0 > w || y0 > h {
        return None; // off screen
    }
    let t = grid.tile_size as f32;
    let tile = |p: f32, n: u32| ((p / t).floor().max(0.0) as u32).min(n - 1);
    Some((
        (tile(x0, grid.tiles.0), tile(x1, grid.tiles.0)),
        (tile(y0, grid.tiles.1), tile(y1, grid.tiles.1)),
    ))
}

/// `bin`, coarsening the grid (tiles twice as wide, half the slices) until
/// the lists fit in `max_texels` (GL_MAX_TEXTURE_BUFFER_SIZE) as tiled
/// shading uploads them: every cluster's (offset, count), two texels, then
/// the light numbers, in one buffer. Always ends, at worst with one cluster
/// that lists every light. Returns the grid used.
pub fn bin_within(
    grid: &Grid,
    view: Mat4,
    projection: Mat4,
    size: (u32, u32),
    bounds: &[Bound],
    max_texels: usize,
) -> (Grid, Bins) {
    let mut g = *grid;
    loop {
        let bins = bin(&g, view, projection, size, bounds);
        let fits = 2 * bins.clusters.len() + bins.indices.len() <= max_texels;
        let coarsest = g.tiles == (1, 1) && g.slices == 1;
        if fits || coarsest {
            return (g, bins);
        }
        g = Grid::new(
            size.0,
            size.1,
            g.tile_size.saturating_mul(2),
            (g.slices / 2).max(1),
            g.near,
            g.far,
        );
    }
}

#[cfg(test)]
mod tests;
