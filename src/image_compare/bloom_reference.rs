//! The CPU reference of the bloom of notes 03, "Blur Pass and Merge Pass",
//! in f64 at full resolution, with none of the GPU's shortcuts (no mip
//! levels, no linear-tap trick, no half floats).
//!
//! Images are linear RGBA, 4 floats a pixel, rows bottom first, as
//! glReadPixels(GL_RGBA, GL_FLOAT) returns them. Only RGB is blurred; the
//! output's alpha is the input's, sanitised.
//!
//! 1. Sanitise every channel: NaN becomes 0, +inf the largest finite half
//!    float (65504), and a negative value 0. The bloom's mip levels are
//!    half floats (RGBA16F): a NaN would spread over the whole blur and
//!    poison every pixel it reaches (NaN × 0 is NaN), +inf likewise (inf ×
//!    0), and no light is negative: a negative value comes from a bug
//!    upstream and would dim its neighbours. 65504 is what an overflowing
//!    half float would clamp to if it did not turn into inf.
//! 2. Four separable Gaussian blurs (rows, then columns), with the notes'
//!    sigma and radius in full-resolution pixels, clamped to the edge (a
//!    texel beyond the border reads the border's, as GL_CLAMP_TO_EDGE does).
//! 3. The Spencer merge: 0.8843 g + 0.1 g(6.2) + 0.012 g(24.9)
//!    + 0.0027 g(81.0) + 0.001 g(263).
//!
//! The reference computes its Gaussian weights itself, not with
//! `math::gaussian` (which the GPU passes use): a wrong weight there shows
//! up as a difference here.

use anyhow::{Result, bail};

/// The notes' four blurs: (sigma, radius), in full-resolution pixels.
pub const NOTES_BLURS: [(f64, u32); 4] = [(6.2, 24), (24.9, 80), (81.0, 243), (263.0, 799)];

/// The Spencer weights of the merge: the original, then the four blurs.
pub const SPENCER_WEIGHTS: [f64; 5] = [0.8843, 0.1, 0.012, 0.0027, 0.001];

/// The largest finite half float: what +inf is sanitised to.
pub const HALF_MAX: f64 = 65504.0;

/// What the bloom does: the blurs and the merge weights.
#[derive(Debug, Clone, PartialEq)]
pub struct BloomParams {
    /// (sigma, radius) of each blur, in full-resolution pixels.
    pub blurs: [(f64, u32); 4],
    /// The weight of the original, then of each blur.
    pub weights: [f64; 5],
}

impl Default for BloomParams {
    fn default() -> Self {
        Self {
            blurs: NOTES_BLURS,
            weights: SPENCER_WEIGHTS,
        }
    }
}

/// One channel value made safe to blur (see the module docs, step 1).
pub fn sanitise(v: f32) -> f64 {
    if v.is_nan() || v <= 0.0 {
        0.0
    } else if v.is_infinite() {
        HALF_MAX
    } else {
        f64::from(v)
    }
}

/// The bloom of `rgba` (`width × height`, 4 floats a pixel, bottom row
/// first), as 4 f64 a pixel.
pub fn bloom(rgba: &[f32], width: usize, height: usize, p: &BloomParams) -> Result<Vec<f64>> {
    let planes = sanitised_planes(rgba, width, height)?;
    let mut out = planes
        .iter()
        .map(|c| scaled(c, p.weights[0]))
        .collect::<Vec<_>>();
    for (&(sigma, radius), &weight) in p.blurs.iter().zip(&p.weights[1..]) {
        if weight == 0.0 {
            continue;
        }
        let w = gaussian(sigma, radius);
        for (acc, plane) in out.iter_mut().zip(&planes) {
            let blurred = blur_plane(plane, width, height, &w);
            for (a, b) in acc.iter_mut().zip(blurred) {
                *a += weight * b;
            }
        }
    }
    let alpha: Vec<f64> = rgba.chunks_exact(4).map(|p| sanitise(p[3])).collect();
    Ok(interleave(&out, &alpha))
}

/// One separable Gaussian blur of `rgba` (sanitised first), as 4 f64 a pixel.
pub fn gaussian_blur(
    rgba: &[f32],
    width: usize,
    height: usize,
    sigma: f64,
    radius: u32,
) -> Result<Vec<f64>> {
    let planes = sanitised_planes(rgba, width, height)?;
    let w = gaussian(sigma, radius);
    let out: Vec<Vec<f64>> = planes
        .iter()
        .map(|c| blur_plane(c, width, height, &w))
        .collect();
    let alpha: Vec<f64> = rgba.chunks_exact(4).map(|p| sanitise(p[3])).collect();
    Ok(interleave(&out, &alpha))
}

/// The normalised one-sided weights `exp(-i² / (2 sigma²))`, `i = 0..=radius`;
/// `[1]` when sigma is not above 0 or the radius is 0.
fn gaussian(sigma: f64, radius: u32) -> Vec<f64> {
    if sigma.is_nan() || sigma <= 0.0 || radius == 0 {
        return vec![1.0];
    }
    let raw: Vec<f64> = (0..=radius)
        .map(|i| (-(f64::from(i) * f64::from(i)) / (2.0 * sigma * sigma)).exp())
        .collect();
    let total = raw[0] + 2.0 * raw[1..].iter().sum::<f64>();
    raw.into_iter().map(|w| w / total).collect()
}

/// The R, G and B planes of `rgba`, sanitised.
fn sanitised_planes(rgba: &[f32], width: usize, height: usize) -> Result<[Vec<f64>; 3]> {
    if width == 0
        || height == 0
        || width.checked_mul(height).and_then(|n| n.checked_mul(4)) != Some(rgba.len())
    {
        bail!(
            "bloom reference: {} floats do not make a {width}x{height} RGBA image",
            rgba.len()
        );
    }
    Ok(std::array::from_fn(|c| {
        rgba.chunks_exact(4).map(|p| sanitise(p[c])).collect()
    }))
}

fn scaled(plane: &[f64], s: f64) -> Vec<f64> {
    plane.iter().map(|v| v * s).collect()
}

fn interleave(rgb: &[Vec<f64>], alpha: &[f64]) -> Vec<f64> {
    let mut out = Vec::with_capacity(alpha.len() * 4);
    for (i, a) in alpha.iter().enumerate() {
        out.extend([rgb[0][i], rgb[1][i], rgb[2][i], *a]);
    }
    out
}

/// Rows, then columns, clamped to the edge.
fn blur_plane(plane: &[f64], width: usize, height: usize, w: &[f64]) -> Vec<f64> {
    let mut rows = vec![0.0; plane.len()];
    for y in 0..height {
        blur_line(
            &plane[y * width..(y + 1) * width],
            w,
            &mut rows[y * width..(y + 1) * width],
        );
    }
    let mut out = vec![0.0; plane.len()];
    let mut column = vec![0.0; height];
    let mut blurred = vec![0.0; height];
    for x in 0..width {
        for y in 0..height {
            column[y] = rows[y * width + x];
        }
        blur_line(&column, w, &mut blurred);
        for y in 0..height {
            out[y * width + x] = blurred[y];
        }
    }
    out
}

/// One line through the kernel, the line padded with copies of its ends.
fn blur_line(line: &[f64], w: &[f64], out: &mut [f64]) {
    let r = w.len() - 1;
    let n = line.len();
    let padded: Vec<f64> = (0..n + 2 * r)
        .map(|i| line[i.saturating_sub(r).min(n - 1)])
        .collect();
    for (x, o) in out.iter_mut().enumerate() {
        let c = x + r;
        let mut s = w[0] * padded[c];
        for (i, wi) in w.iter().enumerate().skip(1) {
            s += wi * (padded[c - i] + padded[c + i]);
        }
        *o = s;
    }
}

/// A point-spread function measured on an image: the blur of one bright
/// pixel, in full-resolution pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Psf {
    /// The total of R + G + B over the image.
    pub energy: f64,
    /// The intensity-weighted mean position (pixel centres at integers).
    pub centroid: (f64, f64),
    /// The root second moment along x and y about the bright pixel (x0, y0).
    pub sigma: (f64, f64),
    /// The same about the centroid.
    pub sigma_centroid: (f64, f64),
}

/// The point-spread function of the image `rgba` (4 values a pixel, bottom
/// row first) about the pixel (x0, y0), with R + G + B as the intensity.
/// None when the image is empty, has the wrong length, or no positive energy.
pub fn psf<T: Copy + Into<f64>>(
    rgba: &[T],
    width: usize,
    height: usize,
    x0: usize,
    y0: usize,
) -> Option<Psf> {
    if width * height * 4 != rgba.len() || rgba.is_empty() {
        return None;
    }
    let (mut e, mut sx, mut sy, mut sxx, mut syy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (i, p) in rgba.chunks_exact(4).enumerate() {
        let v: f64 = p[0].into() + p[1].into() + p[2].into();
        let dx = (i % width) as f64 - x0 as f64;
        let dy = (i / width) as f64 - y0 as f64;
        e += v;
        sx += v * dx;
        sy += v * dy;
        sxx += v * dx * dx;
        syy += v * dy * dy;
    }
    if !e.is_finite() || e <= 0.0 {
        return None;
    }
    let (mx, my) = (sx / e, sy / e);
    Some(Psf {
        energy: e,
        centroid: (x0 as f64 + mx, y0 as f64 + my),
        sigma: ((sxx / e).sqrt(), (syy / e).sqrt()),
        sigma_centroid: (
            (sxx / e - mx * mx).max(0.0).sqrt(),
            (syy / e - my * my).max(0.0).sqrt(),
        ),
    })
}

/// The sum of each of R, G and B over an image of 4 values a pixel.
pub fn energy<T: Copy + Into<f64>>(rgba: &[T]) -> [f64; 3] {
    let mut e = [0.0; 3];
    for p in rgba.chunks_exact(4) {
        for (c, v) in e.iter_mut().zip(p) {
            *c += (*v).into();
        }
    }
    e
}

#[cfg(test)]
#[path = "bloom_reference_tests.rs"]
mod tests;
