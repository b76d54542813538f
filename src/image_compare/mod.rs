//! Image metrics and golden-image checks; shadow masks from renders
//! (`shadow_mask`) and their errors against the exact shadows (`shadow_metrics`).
//!
//! All metrics are in `0..1` units per channel (8-bit values divided by 255)
//! and look at RGB only; alpha is ignored.
//!
//! Golden images live as PNGs; regenerate them with
//! `GLOSS_UPDATE_GOLDEN=1 cargo test --release --test golden` and review the
//! changed files before committing them.

pub mod bloom_reference;
pub mod flip;
mod golden;
pub mod shadow_mask;
pub mod shadow_metrics;

pub use golden::{UPDATE_GOLDEN_ENV, check_golden};

use std::fmt;

use anyhow::bail;
use image::{Rgba, RgbaImage};

/// How much two images differ, in `0..1` units per channel, over RGB.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metrics {
    /// Root-mean-square difference over every RGB channel of every pixel.
    pub rmse: f64,
    /// Largest absolute difference of any RGB channel of any pixel.
    pub max_abs: f64,
    /// Fraction (`0..=1`) of pixels where any RGB channel differs by more than
    /// `over_threshold`.
    pub frac_over: f64,
    /// The threshold `frac_over` was counted against.
    pub over_threshold: f64,
}

impl Metrics {
    /// Metrics of identical images.
    pub fn identical(threshold: f64) -> Self {
        Self {
            rmse: 0.0,
            max_abs: 0.0,
            frac_over: 0.0,
            over_threshold: threshold,
        }
    }

    /// Metrics of images that cannot be compared (different sizes): every
    /// pixel counts as different, infinitely far off.
    pub fn incomparable(threshold: f64) -> Self {
        Self {
            rmse: f64::INFINITY,
            max_abs: f64::INFINITY,
            frac_over: 1.0,
            over_threshold: threshold,
        }
    }
}

impl fmt::Display for Metrics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "RMSE {:.3}/255, max abs {:.1}/255, {:.3}% of pixels differ by more than {}/255",
            self.rmse * 255.0,
            self.max_abs * 255.0,
            self.frac_over * 100.0,
            fmt_steps(self.over_threshold * 255.0),
        )
    }
}

/// Accumulates per-pixel RGB differences.
struct Acc {
    sum_sq: f64,
    max_abs: f64,
    over: u64,
    pixels: u64,
    channels: u64,
    threshold: f64,
}

impl Acc {
    fn new(threshold: f64) -> Self {
        Self {
            sum_sq: 0.0,
            max_abs: 0.0,
            over: 0,
            pixels: 0,
            channels: 0,
            threshold,
        }
    }

    fn pixel(&mut self, diffs: impl IntoIterator<Item = f64>) {
        let mut any_over = false;
        for d in diffs {
            self.sum_sq += d * d;
            self.max_abs = self.max_abs.max(d);
            self.channels += 1;
            // A NaN difference or threshold counts as over.
            any_over |= d > self.threshold || d.is_nan() || self.threshold.is_nan();
        }
        self.pixels += 1;
        self.over += u64::from(any_over);
    }

    fn finish(self) -> Metrics {
        if self.pixels == 0 || self.channels == 0 {
            return Metrics::identical(self.threshold);
        }
        Metrics {
            rmse: (self.sum_sq / self.channels as f64).sqrt(),
            max_abs: self.max_abs,
            frac_over: self.over as f64 / self.pixels as f64,
            over_threshold: self.threshold,
        }
    }
}

/// Compares two 8-bit RGBA images over RGB. `threshold` is in `0..1` units
/// (use `2.0 / 255.0` for "two 8-bit steps"). Errors if the sizes differ.
pub fn compare_rgba8(a: &RgbaImage, b: &RgbaImage, threshold: f64) -> anyhow::Result<Metrics> {
    if a.dimensions() != b.dimensions() {
        bail!(
            "cannot compare images of different sizes: {}x{} vs {}x{}",
            a.width(),
            a.height(),
            b.width(),
            b.height()
        );
    }
    let mut acc = Acc::new(threshold);
    for (pa, pb) in a.pixels().zip(b.pixels()) {
        acc.pixel((0..3).map(|c| f64::from(pa[c].abs_diff(pb[c])) / 255.0));
    }
    Ok(acc.finish())
}

/// Compares two linear float images stored as interleaved pixels of
/// `channels` floats (normally RGBA, `channels = 4`); only the first three
/// channels (RGB) count, so alpha is ignored.
///
/// Two equal values (including equal infinities) differ by 0; a NaN against
/// anything but NaN differs by `+inf`. If the buffers cannot be compared
/// (`channels == 0`, different lengths, or a length that is not a multiple of
/// `channels`) the result is [`Metrics::incomparable`].
pub fn compare_f32(a: &[f32], b: &[f32], channels: usize, threshold: f64) -> Metrics {
    if channels == 0 || a.len() != b.len() || !a.len().is_multiple_of(channels) {
        return Metrics::incomparable(threshold);
    }
    let rgb = channels.min(3);
    let mut acc = Acc::new(threshold);
    for (pa, pb) in a.chunks_exact(channels).zip(b.chunks_exact(channels)) {
        acc.pixel(pa[..rgb].iter().zip(&pb[..rgb]).map(|(&x, &y)| {
            let (x, y) = (f64::from(x), f64::from(y));
            if x == y || (x.is_nan() && y.is_nan()) {
                0.0
            } else {
                let d = (x - y).abs();
                if d.is_nan() { f64::INFINITY } else { d }
            }
        }));
    }
    acc.finish()
}

/// Colour of pixels that exist in only one of the images passed to
/// [`diff_image`].
pub const DIFF_MISSING: Rgba<u8> = Rgba([255, 0, 255, 255]);

/// Per-pixel `|a - b|` of RGB, amplified 8x and clamped, with alpha 255, so
/// that differences of a step or two are visible.
///
/// If the sizes differ the result covers both images and pixels that exist in
/// only one of them are [`DIFF_MISSING`] (magenta).
pub fn diff_image(a: &RgbaImage, b: &RgbaImage) -> RgbaImage {
    let (w, h) = (a.width().max(b.width()), a.height().max(b.height()));
    RgbaImage::from_fn(w, h, |x, y| {
        match (a.get_pixel_checked(x, y), b.get_pixel_checked(x, y)) {
            (Some(pa), Some(pb)) => {
                let ch = |c: usize| pa[c].abs_diff(pb[c]).saturating_mul(8);
                Rgba([ch(0), ch(1), ch(2), 255])
            }
            _ => DIFF_MISSING,
        }
    })
}

/// How far an image may be from its golden image.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Per-channel difference (`0..1` units) above which a pixel counts as
    /// differing.
    pub threshold: f64,
    /// Largest allowed fraction (`0..=1`) of differing pixels.
    pub max_frac_over: f64,
    /// If set, no channel of any pixel may differ by more than this.
    pub max_abs: Option<f64>,
}

impl Tolerance {
    /// Whether `m` (computed with this tolerance's threshold) is within it.
    /// NaN metrics never pass.
    pub fn accepts(&self, m: &Metrics) -> bool {
        m.frac_over <= self.max_frac_over && self.max_abs.is_none_or(|t| m.max_abs <= t)
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "at most {:.2}% of pixels differ by more than {}/255 in any channel",
            self.max_frac_over * 100.0,
            fmt_steps(self.threshold * 255.0)
        )?;
        if let Some(m) = self.max_abs {
            write!(
                f,
                ", and no channel differs by more than {}/255",
                fmt_steps(m * 255.0)
            )?;
        }
        Ok(())
    }
}

/// An 8-bit step count: "2" for 2.0, "2.5" for 2.5.
fn fmt_steps(v: f64) -> String {
    if (v - v.round()).abs() < 1e-6 {
        format!("{}", v.round())
    } else {
        format!("{v:.2}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn solid(w: u32, h: u32, c: [u8; 4]) -> RgbaImage {
        RgbaImage::from_pixel(w, h, Rgba(c))
    }

    pub(super) const TOL: Tolerance = Tolerance {
        threshold: 2.0 / 255.0,
        max_frac_over: 0.001,
        max_abs: None,
    };

    #[test]
    fn rgba8_metrics_on_hand_made_images() {
        // 2x2: one pixel off by 10 in red, one off by 1 in green and blue,
        // alpha differs everywhere (ignored).
        let a = solid(2, 2, [100, 100, 100, 255]);
        let mut b = solid(2, 2, [100, 100, 100, 0]);
        b.put_pixel(0, 0, Rgba([110, 100, 100, 0]));
        b.put_pixel(1, 1, Rgba([100, 101, 99, 0]));
        let m = compare_rgba8(&a, &b, 2.0 / 255.0).unwrap();
        let expect_rmse = ((100.0 + 1.0 + 1.0) / 12.0f64).sqrt() / 255.0;
        assert!((m.rmse - expect_rmse).abs() < 1e-12, "{m:?}");
        assert!((m.max_abs - 10.0 / 255.0).abs() < 1e-12);
        assert_eq!(m.frac_over, 0.25);
        assert_eq!(m.over_threshold, 2.0 / 255.0);
        // With threshold 0 both changed pixels count.
        assert_eq!(compare_rgba8(&a, &b, 0.0).unwrap().frac_over, 0.5);
        // Identical images.
        assert_eq!(compare_rgba8(&a, &a, 0.0).unwrap(), Metrics::identical(0.0));
        // Empty images compare equal.
        let e = RgbaImage::new(0, 0);
        assert_eq!(compare_rgba8(&e, &e, 0.0).unwrap().rmse, 0.0);
    }

    #[test]
    fn rgba8_size_mismatch_is_an_error() {
        let e = compare_rgba8(&solid(2, 2, [0; 4]), &solid(3, 2, [0; 4]), 0.0).unwrap_err();
        assert!(e.to_string().contains("2x2 vs 3x2"), "{e}");
    }

    #[test]
    fn f32_metrics_ignore_alpha_and_handle_bad_input() {
        let a = [0.5f32, 0.5, 0.5, 1.0, 0.0, 0.0, 0.0, 1.0];
        let b = [0.5f32, 0.75, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0];
        let m = compare_f32(&a, &b, 4, 0.1);
        assert!((m.rmse - (0.0625f64 / 6.0).sqrt()).abs() < 1e-12, "{m:?}");
        assert_eq!(m.max_abs, 0.25);
        assert_eq!(m.frac_over, 0.5);
        // NaN against a number is infinitely far; NaN against NaN is equal.
        let m = compare_f32(&[f32::NAN, 0.0, 0.0, 1.0], &[0.0, 0.0, 0.0, 1.0], 4, 0.1);
        assert_eq!(m.max_abs, f64::INFINITY);
        assert_eq!(m.frac_over, 1.0);
        let m = compare_f32(
            &[f32::NAN, f32::INFINITY, 0.0],
            &[f32::NAN, f32::INFINITY, 0.0],
            3,
            0.0,
        );
        assert_eq!(m, Metrics::identical(0.0));
        // Incomparable buffers.
        assert_eq!(compare_f32(&a, &b[..4], 4, 0.1), Metrics::incomparable(0.1));
        assert_eq!(compare_f32(&a, &b, 0, 0.1), Metrics::incomparable(0.1));
        assert_eq!(
            compare_f32(&a[..6], &b[..6], 4, 0.1),
            Metrics::incomparable(0.1)
        );
        assert_eq!(compare_f32(&[], &[], 4, 0.1), Metrics::identical(0.1));
    }

    #[test]
    fn diff_image_amplifies_and_marks_missing() {
        let a = solid(2, 1, [10, 200, 0, 255]);
        let mut b = solid(3, 1, [12, 100, 0, 7]);
        b.put_pixel(1, 0, Rgba([10, 200, 0, 0]));
        let d = diff_image(&a, &b);
        assert_eq!(d.dimensions(), (3, 1));
        assert_eq!(d.get_pixel(0, 0), &Rgba([16, 255, 0, 255]));
        assert_eq!(d.get_pixel(1, 0), &Rgba([0, 0, 0, 255]));
        assert_eq!(d.get_pixel(2, 0), &DIFF_MISSING);
    }

    #[test]
    fn tolerance_states_itself_in_words() {
        assert_eq!(
            TOL.to_string(),
            "at most 0.10% of pixels differ by more than 2/255 in any channel"
        );
        let t = Tolerance {
            threshold: 1.5 / 255.0,
            max_frac_over: 0.0,
            max_abs: Some(8.0 / 255.0),
        };
        assert_eq!(
            t.to_string(),
            "at most 0.00% of pixels differ by more than 1.50/255 in any channel, \
             and no channel differs by more than 8/255"
        );
        assert!(!t.accepts(&Metrics {
            max_abs: 9.0 / 255.0,
            ..Metrics::identical(t.threshold)
        }));
        assert!(!t.accepts(&Metrics {
            frac_over: f64::NAN,
            ..Metrics::identical(t.threshold)
        }));
    }
}
