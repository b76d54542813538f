//! How far shadow mapping (notes 01 §8.5) is from the exact shadows, from
//! per-pixel masks alone: the GL mask read from renders (`shadow_mask`), and
//! the reference `Visibility` a ray tracer gives (`lighting::shadow_reference`).
//! Masks run bottom row first, as glReadPixels and the depth buffer do.
//!
//! The band: a pixel is in the band when its 3x3 neighbourhood (itself and
//! its eight neighbours, clipped at the image's edge) holds both a
//! reference-lit and a reference-shadowed pixel. Those are the pixels either
//! side of the true boundary, where an edge one pixel off is no error.
//!
//! Over the judged pixels (GL considers them, the reference does not call
//! them `Background`, outside the band), as fractions 0..=1:
//! ```text
//! misclassified = #(GL shadowed != reference shadowed) / #judged
//! acne          = #(reference lit, GL shadowed) / #(judged, reference lit)
//! ```
//! Nothing to judge gives NaN, which fails every `<` check.
//!
//! Peter-panning (`contact_gap`), in world units, along a line of pixels that
//! starts at a contact point C (where an object meets the floor, on the side
//! away from the light) and runs into the object's shadow, with P_i the
//! world point of the line's i-th pixel:
//! ```text
//! gap = |P_g - C| - |P_r - C|
//! ```
//! where g is the first pixel of the line GL calls shadowed and r the first
//! the reference calls shadowed: how much later the GL shadow starts than
//! the true one. Positive is a detached shadow; negative, one that starts early.

use std::fmt;

use super::shadow_mask::{GlShadow, ShadowMask};
use glam::Vec3;

/// The exact answer for one pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Visibility {
    /// Nothing drawn (window depth 1).
    Background,
    Lit,
    Shadowed,
}

/// Per pixel, whether it is in the band around the reference's boundary
/// between lit and shadowed (module header).
pub fn boundary_band(reference: &[Visibility], width: usize, height: usize) -> Vec<bool> {
    assert_eq!(
        reference.len(),
        width * height,
        "reference is not width x height"
    );
    let mut band = vec![false; reference.len()];
    for y in 0..height {
        for x in 0..width {
            let (mut lit, mut shadowed) = (false, false);
            for ny in y.saturating_sub(1)..(y + 2).min(height) {
                for nx in x.saturating_sub(1)..(x + 2).min(width) {
                    match reference[ny * width + nx] {
                        Visibility::Lit => lit = true,
                        Visibility::Shadowed => shadowed = true,
                        Visibility::Background => {}
                    }
                }
            }
            band[y * width + x] = lit && shadowed;
        }
    }
    band
}

fn ratio(count: usize, of: usize) -> f64 {
    if of == 0 {
        f64::NAN
    } else {
        count as f64 / of as f64
    }
}

/// Fraction of judged pixels where GL and the reference disagree (module header).
pub fn misclassified_outside_band(gl: &ShadowMask, reference: &[Visibility]) -> f64 {
    ShadowErrors::measure(gl, reference).misclassified
}

/// Fraction of judged reference-lit pixels that GL calls shadowed (module header).
pub fn acne(gl: &ShadowMask, reference: &[Visibility]) -> f64 {
    ShadowErrors::measure(gl, reference).acne
}

/// The pixels of the straight line from pixel `from` to pixel `to` (x, y
/// from the bottom-left, both included; Bresenham), as indices `y * width + x`,
/// stopping where the line leaves the image.
pub fn pixel_line(width: usize, height: usize, from: (i64, i64), to: (i64, i64)) -> Vec<usize> {
    let (dx, dy) = ((to.0 - from.0).abs(), -(to.1 - from.1).abs());
    let (sx, sy) = ((to.0 - from.0).signum(), (to.1 - from.1).signum());
    let (mut x, mut y, mut err) = (from.0, from.1, dx + dy);
    let mut out = Vec::new();
    loop {
        if x < 0 || y < 0 || x >= width as i64 || y >= height as i64 {
            break;
        }
        out.push(y as usize * width + x as usize);
        if (x, y) == to {
            break;
        }
        let e2 = 2 * err;
        if e2 >= dy {
            err += dy;
            x += sx;
        }
        if e2 <= dx {
            err += dx;
            y += sy;
        }
    }
    out
}

/// Peter-panning along `line` (pixel indices from the contact point into the
/// shadow, e.g. from `pixel_line`): `|P_g - C| - |P_r - C|` (module header),
/// `points` being every pixel's world point (the mask's layout) and C the
/// `contact` point. None when GL or the reference shadows no pixel of the line.
pub fn contact_gap(
    gl: &ShadowMask,
    reference: &[Visibility],
    points: &[Vec3],
    line: &[usize],
    contact: Vec3,
) -> Option<f32> {
    let start = |shadowed: &dyn Fn(usize) -> bool| {
        let i = line.iter().copied().find(|&i| shadowed(i))?;
        Some((points[i] - contact).length())
    };
    let g = start(&|i| gl.pixels[i] == GlShadow::Shadowed)?;
    let r = start(&|i| reference[i] == Visibility::Shadowed)?;
    Some(g - r)
}

/// The errors of one shadow-mapped image against the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowErrors {
    /// Fraction (0..=1) of judged pixels misclassified.
    pub misclassified: f64,
    /// Fraction (0..=1) of judged reference-lit pixels GL calls shadowed.
    pub acne: f64,
    /// `contact_gap` in world units, when measured.
    pub peter_panning: Option<f32>,
    /// How many pixels were judged, and how many of them the reference lights.
    pub judged: usize,
    pub judged_lit: usize,
}

impl ShadowErrors {
    /// Misclassified and acne (module header); `peter_panning` None, for
    /// the caller to fill from `contact_gap`. Panics if the sizes differ.
    pub fn measure(gl: &ShadowMask, reference: &[Visibility]) -> ShadowErrors {
        let band = boundary_band(reference, gl.width, gl.height);
        assert_eq!(gl.pixels.len(), reference.len(), "mask sizes differ");
        let (mut judged, mut wrong, mut lit, mut acne) = (0, 0, 0, 0);
        for ((&g, &r), &in_band) in gl.pixels.iter().zip(reference).zip(&band) {
            if in_band || g == GlShadow::Ignored || r == Visibility::Background {
                continue;
            }
            let gl_shadowed = g == GlShadow::Shadowed;
            judged += 1;
            wrong += usize::from(gl_shadowed != (r == Visibility::Shadowed));
            if r == Visibility::Lit {
                lit += 1;
                acne += usize::from(gl_shadowed);
            }
        }
        ShadowErrors {
            misclassified: ratio(wrong, judged),
            acne: ratio(acne, lit),
            peter_panning: None,
            judged,
            judged_lit: lit,
        }
    }
}

impl fmt::Display for ShadowErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "misclassified {:.2}% of {} pixels outside the band, acne {:.2}% of {} lit pixels, ",
            self.misclassified * 100.0,
            self.judged,
            self.acne * 100.0,
            self.judged_lit
        )?;
        match self.peter_panning {
            Some(gap) => write!(f, "peter-panning {gap:.4} world units"),
            None => write!(f, "peter-panning not measured"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use GlShadow as G;
    use Visibility as V;

    /// 10x10: columns 0..=4 lit, 5..=9 shadowed.
    fn halves() -> Vec<Visibility> {
        (0..100)
            .map(|i| if i % 10 < 5 { V::Lit } else { V::Shadowed })
            .collect()
    }

    #[test]
    fn the_band_is_one_pixel_either_side_of_the_boundary() {
        let band = boundary_band(&halves(), 10, 10);
        for (i, &b) in band.iter().enumerate() {
            assert_eq!(b, i % 10 == 4 || i % 10 == 5, "pixel {i}");
        }
        // Lit against background is no boundary.
        let r: Vec<Visibility> = (0..100)
            .map(|i| if i % 10 < 5 { V::Lit } else { V::Background })
            .collect();
        assert!(boundary_band(&r, 10, 10).iter().all(|&b| !b));
        // A single shadowed pixel in a corner: its 2x2 corner is the band.
        let mut r = vec![V::Lit; 9];
        r[0] = V::Shadowed;
        let band = boundary_band(&r, 3, 3);
        assert_eq!(
            band,
            [true, true, false, true, true, false, false, false, false]
        );
    }

    #[test]
    fn metrics_on_a_synthetic_mask() {
        let reference = halves();
        let mut pixels: Vec<GlShadow> = reference
            .iter()
            .map(|&v| if v == V::Lit { G::Lit } else { G::Shadowed })
            .collect();
        let mut gl = ShadowMask {
            width: 10,
            height: 10,
            pixels: pixels.clone(),
        };
        let e = ShadowErrors::measure(&gl, &reference);
        // 100 pixels less the 20 of the band; 40 of them lit.
        assert_eq!(
            (e.misclassified, e.acne, e.judged, e.judged_lit),
            (0.0, 0.0, 80, 40)
        );
        // The GL edge one pixel to the right: inside the band, no error.
        for y in 0..10 {
            pixels[y * 10 + 5] = G::Lit;
        }
        pixels[11] = G::Shadowed; // acne at (1, 1)
        pixels[88] = G::Lit; // a missed shadow at (8, 8)
        pixels[90] = G::Ignored; // (0, 9): the light does not reach it
        gl.pixels = pixels;
        let e = ShadowErrors::measure(&gl, &reference);
        assert_eq!((e.judged, e.judged_lit), (79, 39));
        assert_eq!(e.misclassified, 2.0 / 79.0);
        assert_eq!(e.acne, 1.0 / 39.0);
        assert_eq!(misclassified_outside_band(&gl, &reference), 2.0 / 79.0);
        assert_eq!(acne(&gl, &reference), 1.0 / 39.0);
        assert_eq!(
            ShadowErrors {
                peter_panning: Some(0.25),
                ..e
            }
            .to_string(),
            "misclassified 2.53% of 79 pixels outside the band, acne 2.56% of 39 lit pixels, \
             peter-panning 0.2500 world units"
        );
        // Nothing to judge: NaN, never "no error".
        let all_ignored = ShadowMask {
            width: 10,
            height: 10,
            pixels: vec![G::Ignored; 100],
        };
        assert!(misclassified_outside_band(&all_ignored, &reference).is_nan());
    }

    #[test]
    fn pixel_lines_step_one_pixel_and_stop_at_the_edge() {
        assert_eq!(pixel_line(10, 10, (0, 0), (3, 1)), vec![0, 1, 12, 13]);
        assert_eq!(pixel_line(10, 10, (2, 2), (2, 2)), vec![22]);
        assert_eq!(pixel_line(4, 3, (1, 1), (1, -5)), vec![5, 1]);
        assert_eq!(pixel_line(4, 3, (3, 0), (0, 0)), vec![3, 2, 1, 0]);
    }

    #[test]
    fn contact_gap_is_the_late_start_in_world_units() {
        // A 10x1 line along x, pixel i at world x = 0.1 i, the contact at x = 0.
        let points: Vec<Vec3> = (0..10)
            .map(|i| Vec3::new(0.1 * i as f32, 0.0, 0.0))
            .collect();
        let line: Vec<usize> = (0..10).collect();
        let reference: Vec<Visibility> = (0..10)
            .map(|i| if i >= 1 { V::Shadowed } else { V::Lit })
            .collect();
        let mask = |from: usize| ShadowMask {
            width: 10,
            height: 1,
            pixels: (0..10)
                .map(|i| if i >= from { G::Shadowed } else { G::Lit })
                .collect(),
        };
        let gap = |gl: &ShadowMask| contact_gap(gl, &reference, &points, &line, Vec3::ZERO);
        assert!((gap(&mask(4)).unwrap() - 0.3).abs() < 1e-6);
        assert_eq!(gap(&mask(1)), Some(0.0));
        assert!((gap(&mask(0)).unwrap() + 0.1).abs() < 1e-6);
        assert_eq!(gap(&mask(10)), None);
        // Ignored pixels are not shadowed: the GL shadow starts at 6.
        let mut gl = mask(4);
        gl.pixels[4] = G::Ignored;
        gl.pixels[5] = G::Ignored;
        assert!((gap(&gl).unwrap() - 0.5).abs() < 1e-6);
    }
}
