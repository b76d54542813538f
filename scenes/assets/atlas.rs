//! The texture atlas assets (notes 01 §5: "all textures for a mesh
//! typically stored in a single texture image"): four 128 x 128 tiles in
//! one 256 x 256 image, red, green, blue and magenta, each striped in two
//! shades of its hue, and a cube whose faces' uvs point into them.
//!
//! * `atlas.png` + `atlas-cube.obj`: the tiles edge to edge, the faces'
//!   uvs on the tiles' edges. Bilinear filtering at a face's edge and every
//!   mip level past 0 blend a tile with its neighbours: the faces' edges
//!   bleed the other tiles' colours.
//! * `atlas-padded.png` + `atlas-cube-padded.obj`: each tile's picture
//!   shrunk to 112 x 112 inside an 8-texel gutter that repeats its edge
//!   texels, the faces' uvs on the pictures' edges. Up to mip level 3 a
//!   tile's texels average only its own picture and gutter (8 texels are 1
//!   at level 3); the materials cap the level there (`max_lod = 3`).

use gloss::geometry::{self, MeshData};

/// The tile size, and the gutter of the padded atlas, in texels.
pub const TILE: u32 = 128;
pub const GUTTER: u32 = 8;

/// Tile k's two shades: red, green, blue, magenta, each with the other
/// channels at 0, so that any other tile's colour in a face is measurable.
fn shades(k: u32) -> [[u8; 3]; 2] {
    match k {
        0 => [[210, 0, 0], [150, 0, 0]],
        1 => [[0, 200, 0], [0, 140, 0]],
        2 => [[0, 0, 220], [0, 0, 150]],
        _ => [[200, 0, 200], [140, 0, 140]],
    }
}

/// Tile k's picture at (x, y) of a `size`-texel square: diagonal stripes.
fn picture(k: u32, x: u32, y: u32, size: u32) -> [u8; 3] {
    let stripe = ((x + y) * 16 / size) % 2;
    shades(k)[stripe as usize]
}

/// The atlas: tile k at column k % 2, image row k / 2 (row 0 on top).
pub fn atlas(padded: bool) -> image::RgbImage {
    image::RgbImage::from_fn(2 * TILE, 2 * TILE, |x, y| {
        let k = (x / TILE) + 2 * (y / TILE);
        let (tx, ty) = (x % TILE, y % TILE);
        let texel = if padded {
            // The picture inside the gutter; the gutter repeats its edge.
            let inner = TILE - 2 * GUTTER;
            let clamp = |t: u32| t.clamp(GUTTER, TILE - GUTTER - 1) - GUTTER;
            picture(k, clamp(tx), clamp(ty), inner)
        } else {
            picture(k, tx, ty, TILE)
        };
        image::Rgb(texel)
    })
}

/// The unit cube with face f's 0..1 uvs moved onto tile f % 4 (onto its
/// picture, inside the gutter, when `padded`).
pub fn cube(padded: bool) -> MeshData {
    let mut m = geometry::cube();
    let size = (2 * TILE) as f32;
    let inset = if padded { GUTTER as f32 } else { 0.0 };
    for (i, v) in m.vertices.iter_mut().enumerate() {
        let k = (i / 4) as u32 % 4;
        // The tile's texel rectangle; v runs up, image rows down.
        let (x0, y_top) = ((k % 2 * TILE) as f32 + inset, (k / 2 * TILE) as f32 + inset);
        let span = TILE as f32 - 2.0 * inset;
        let u = (x0 + v.uv[0] * span) / size;
        let vv = 1.0 - (y_top + (1.0 - v.uv[1]) * span) / size;
        v.uv = [u, vv];
    }
    m
}
