//! The textures of `models/` (models.rs): procedural, deterministic, 128 x 128
//! or smaller.

fn noise(x: u32, y: u32) -> f32 {
    let mut h = x.wrapping_mul(0x9e37_79b9) ^ y.wrapping_mul(0x85eb_ca6b);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2c1b_3c6d);
    h ^= h >> 12;
    (h & 0xffff) as f32 / 65535.0
}

/// Is texel (x, y) of a 128 x 128 crate face on the iron frame?
fn frame(x: u32, y: u32) -> bool {
    let edge = x.min(y).min(127 - x).min(127 - y);
    edge < 12
}

pub fn crate_diffuse() -> image::RgbImage {
    image::RgbImage::from_fn(128, 128, |x, y| {
        if frame(x, y) {
            let g = 70.0 + 30.0 * noise(x, y);
            image::Rgb([g as u8, (g * 0.95) as u8, (g * 0.9) as u8])
        } else {
            // Planks 26 texels wide, grain along y.
            let grain = 0.85 + 0.15 * ((x as f32 * 0.9).sin() * 0.5 + 0.5) * noise(x / 3, y / 9);
            let dark = if (x - 12) % 26 < 2 { 0.55 } else { 1.0 };
            let s = grain * dark;
            image::Rgb([(170.0 * s) as u8, (112.0 * s) as u8, (58.0 * s) as u8])
        }
    })
}

pub fn crate_specular() -> image::RgbImage {
    image::RgbImage::from_fn(128, 128, |x, y| {
        let v = if frame(x, y) {
            (200.0 + 55.0 * noise(x, y)) as u8
        } else {
            0
        };
        image::Rgb([v, v, v])
    })
}

/// Grooves between the planks: the height drops 2 texels over the
/// 2-texel gaps, baked to tangent-space normals.
pub fn crate_normal() -> image::RgbImage {
    let texels = gloss::math::bump::bake_normal_map(128, 128, |u, v| {
        let (x, y) = ((u * 128.0) as u32, (v * 128.0) as u32);
        if frame(x.min(127), y.min(127)) {
            2.0
        } else if (x.saturating_sub(12)) % 26 < 2 {
            0.0
        } else {
            1.0
        }
    });
    image::RgbImage::from_fn(128, 128, |x, y| image::Rgb(texels[(y * 128 + x) as usize]))
}

/// A leaf spray: five leaves (ellipses) on a transparent ground; the
/// transparent texels keep the leaves' green so filtering adds no fringe.
pub fn leaf() -> image::RgbaImage {
    let leaves = [
        (64.0, 40.0, 0.0),
        (40.0, 64.0, 0.9),
        (88.0, 64.0, -0.9),
        (52.0, 96.0, 0.4),
        (78.0, 98.0, -0.4),
    ];
    image::RgbaImage::from_fn(128, 128, |x, y| {
        let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
        let inside = leaves.iter().any(|&(cx, cy, a): &(f32, f32, f32)| {
            let (dx, dy) = (px - cx, py - cy);
            let (u, v) = (dx * a.cos() + dy * a.sin(), -dx * a.sin() + dy * a.cos());
            (u / 11.0).powi(2) + (v / 24.0).powi(2) < 1.0
        });
        let stem = (px - 64.0).abs() < 2.0 && py > 40.0;
        let shade = 0.7 + 0.3 * noise(x / 2, y / 2);
        let alpha = if inside || stem { 255 } else { 0 };
        image::Rgba([
            (50.0 * shade) as u8,
            (130.0 * shade) as u8,
            (40.0 * shade) as u8,
            alpha,
        ])
    })
}

pub fn tiles() -> image::RgbImage {
    image::RgbImage::from_fn(128, 128, |x, y| {
        let grout = x % 64 < 3 || y % 64 < 3;
        let dark = ((x / 64) + (y / 64)) % 2 == 0;
        let n = 0.9 + 0.1 * noise(x, y);
        let c = if grout {
            [90.0, 88.0, 84.0]
        } else if dark {
            [150.0, 120.0, 95.0]
        } else {
            [205.0, 195.0, 175.0]
        };
        image::Rgb(c.map(|v| (v * n) as u8))
    })
}

pub fn stone() -> image::RgbImage {
    image::RgbImage::from_fn(128, 128, |x, y| {
        let n = 0.8 + 0.2 * noise(x / 2, y / 2) + 0.05 * noise(x, y);
        image::Rgb([(196.0 * n) as u8, (184.0 * n) as u8, (160.0 * n) as u8])
    })
}

/// Red and gold stripes.
pub fn banner() -> image::RgbImage {
    image::RgbImage::from_fn(64, 128, |x, _| {
        if (x / 8) % 3 == 1 {
            image::Rgb([210, 160, 40])
        } else {
            image::Rgb([150, 20, 25])
        }
    })
}

/// The banner's alpha (map_d, grey): opaque, but for a fringe of 8
/// tassels along the bottom eighth.
pub fn banner_alpha() -> image::GrayImage {
    image::GrayImage::from_fn(64, 128, |x, y| {
        // Image row 0 is the top: tassels 3 texels wide in the bottom 16 rows.
        image::Luma([if y >= 112 && x % 8 >= 3 { 0 } else { 255 }])
    })
}
