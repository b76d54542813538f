//! `skybox-px.png` ... `skybox-nz.png`: the six 128x128 faces of a cube
//! map (+x, -x, +y, -y, +z, -z; scenes/skybox.toml): an environment with a
//! horizon (a sky graded to the zenith above, a checkered ground plane
//! below, a dark line where they meet), each face framed in its own colour
//! (x red / magenta, y green / yellow, z blue / cyan) and labelled with its
//! name, so that a student sees which face is which.
//!
//! Every texel is the environment along the direction through its centre
//! (`gloss::math::cube_map::direction`, GL's face table), so the faces meet
//! without a seam but for their frames. Seen from inside the cube, GL's
//! faces are mirror images (the face table is left-handed), so the labels
//! are drawn mirrored and read the right way round in the skybox.

use gloss::math::cube_map::direction;

/// The faces' file names, in GL's order.
pub const FILES: [&str; 6] = [
    "skybox-px.png",
    "skybox-nx.png",
    "skybox-py.png",
    "skybox-ny.png",
    "skybox-pz.png",
    "skybox-nz.png",
];

const SIZE: u32 = 128;

const TINT: [[f32; 3]; 6] = [
    [0.9, 0.15, 0.1],
    [0.8, 0.1, 0.7],
    [0.15, 0.75, 0.15],
    [0.9, 0.8, 0.1],
    [0.15, 0.3, 0.95],
    [0.1, 0.8, 0.85],
];

/// 5x7 glyphs, top row first, for "+-XYZ".
fn glyph(c: char) -> [u8; 7] {
    match c {
        '+' => [0, 4, 4, 31, 4, 4, 0],
        '-' => [0, 0, 0, 31, 0, 0, 0],
        'X' => [17, 17, 10, 4, 10, 17, 17],
        'Y' => [17, 17, 10, 4, 4, 4, 4],
        _ => [31, 1, 2, 4, 8, 16, 31],
    }
}

/// The environment (sRGB-ish colour) along unit direction `d`.
fn environment(d: glam::DVec3) -> [f64; 3] {
    let mix = |a: [f64; 3], b: [f64; 3], t: f64| std::array::from_fn(|i| a[i] + (b[i] - a[i]) * t);
    if d.y.abs() < 0.012 {
        return [0.12, 0.12, 0.14];
    }
    if d.y > 0.0 {
        mix([0.78, 0.86, 0.95], [0.2, 0.4, 0.82], d.y.sqrt())
    } else {
        // The ground plane y = -1, in squares of 1, fading into haze.
        let p = d / -d.y;
        let dark = (p.x.floor() + p.z.floor()).rem_euclid(2.0) == 0.0;
        let ground = if dark {
            [0.25, 0.4, 0.18]
        } else {
            [0.45, 0.6, 0.3]
        };
        mix([0.7, 0.72, 0.7], ground, (-d.y * 4.0).min(1.0))
    }
}

/// Face `f`, row 0 = t = 0 (the image's top: faces are not flipped).
pub fn face(f: usize) -> image::RgbImage {
    let name: Vec<char> = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"][f].chars().collect();
    let (scale, w, h) = (4, 2 * 6 * 4, 7 * 4);
    let (x0, y0) = ((SIZE - w) / 2, (SIZE - h) / 2);
    image::RgbImage::from_fn(SIZE, SIZE, |i, j| {
        let n = f64::from(SIZE);
        let d = direction(f, (f64::from(i) + 0.5) / n, (f64::from(j) + 0.5) / n).normalize();
        let mut c = environment(d);
        let frame = i < 3 || j < 3 || i >= SIZE - 3 || j >= SIZE - 3;
        if frame {
            c = TINT[f].map(f64::from);
        }
        // The label, mirrored in s (see the module comment), on a dark plate.
        let (li, lj) = (SIZE - 1 - i, j);
        if (x0 - 4..x0 + w + 4).contains(&li) && (y0 - 4..y0 + h + 4).contains(&lj) {
            c = c.map(|v| v * 0.3);
            if (x0..x0 + w).contains(&li) && (y0..y0 + h).contains(&lj) {
                let (gx, gy) = ((li - x0) / scale, (lj - y0) / scale);
                let (k, col) = ((gx / 6) as usize, gx % 6);
                if col < 5 && glyph(name[k])[gy as usize] >> (4 - col) & 1 == 1 {
                    c = TINT[f].map(|v| 0.4 + 0.6 * f64::from(v));
                }
            }
        }
        image::Rgb(c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8))
    })
}
