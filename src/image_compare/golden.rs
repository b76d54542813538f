//! Golden-image checks: compare a rendering with the PNG it should match,
//! and on a mismatch save the actual, expected and diff images for review.
//! With `GLOSS_UPDATE_GOLDEN=1` the goldens are (re)written instead.

use std::path::{Path, PathBuf};

use anyhow::{Context, bail};
use image::RgbaImage;

use super::{Metrics, Tolerance, compare_rgba8, diff_image};

/// Environment variable that makes [`check_golden`] (re)write golden images
/// instead of comparing against them.
pub const UPDATE_GOLDEN_ENV: &str = "GLOSS_UPDATE_GOLDEN";

/// Keeps `[A-Za-z0-9_.-]` and replaces everything else with `_`, so that a
/// test name cannot escape `out_dir`.
fn file_stem(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect();
    let s = s.trim_start_matches('.');
    if s.is_empty() {
        "image".to_string()
    } else {
        s.to_string()
    }
}

fn save_png(img: &RgbaImage, path: &Path) -> anyhow::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("creating directory {}", dir.display()))?;
    }
    img.save_with_format(path, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))
}

/// Checks `actual` against the PNG at `golden_path`.
///
/// - With `GLOSS_UPDATE_GOLDEN=1` in the environment, writes `actual` to
///   `golden_path` (creating directories) and returns identical metrics.
/// - If the golden file is missing, errors and says how to create it.
/// - Otherwise compares over RGB with `tol.threshold`; if the images differ
///   in size or are outside `tol`, writes `<out_dir>/<name>.actual.png`,
///   `.expected.png`, `.diff.png` (see [`diff_image`]) and `.flip.png` (the
///   FLIP map, [`super::flip`]) and returns an error naming the metrics,
///   the FLIP mean and max, the tolerance and the four paths.
pub fn check_golden(
    name: &str,
    actual: &RgbaImage,
    golden_path: &Path,
    out_dir: &Path,
    tol: &Tolerance,
) -> anyhow::Result<Metrics> {
    let update = std::env::var(UPDATE_GOLDEN_ENV).is_ok_and(|v| v == "1");
    check_golden_impl(name, actual, golden_path, out_dir, tol, update)
}

fn check_golden_impl(
    name: &str,
    actual: &RgbaImage,
    golden_path: &Path,
    out_dir: &Path,
    tol: &Tolerance,
    update: bool,
) -> anyhow::Result<Metrics> {
    if update {
        save_png(actual, golden_path)
            .with_context(|| format!("updating golden image for {name}"))?;
        return Ok(Metrics::identical(tol.threshold));
    }
    if !golden_path.exists() {
        bail!(
            "golden image for {name} is missing: {}\n\
             create it by running the test with {UPDATE_GOLDEN_ENV}=1, e.g.\n  \
             {UPDATE_GOLDEN_ENV}=1 cargo test --release --test golden\n\
             and check the new image before committing it",
            golden_path.display()
        );
    }
    let expected = image::open(golden_path)
        .with_context(|| format!("reading golden image {}", golden_path.display()))?
        .to_rgba8();

    let (metrics, size_note) = if expected.dimensions() == actual.dimensions() {
        (compare_rgba8(actual, &expected, tol.threshold)?, None)
    } else {
        (
            Metrics::incomparable(tol.threshold),
            Some(format!(
                "size differs: actual {}x{}, expected {}x{}\n",
                actual.width(),
                actual.height(),
                expected.width(),
                expected.height()
            )),
        )
    };
    if size_note.is_none() && tol.accepts(&metrics) {
        return Ok(metrics);
    }

    let stem = file_stem(name);
    let paths: [PathBuf; 4] = [
        out_dir.join(format!("{stem}.actual.png")),
        out_dir.join(format!("{stem}.expected.png")),
        out_dir.join(format!("{stem}.diff.png")),
        out_dir.join(format!("{stem}.flip.png")),
    ];
    save_png(actual, &paths[0])?;
    save_png(&expected, &paths[1])?;
    save_png(&diff_image(actual, &expected), &paths[2])?;
    // The perceptual error and its map, where the sizes allow one.
    let flip_line = match super::flip::flip(actual, &expected) {
        Ok(f) => {
            let map = image::DynamicImage::ImageRgb8(f.map).to_rgba8();
            save_png(&map, &paths[3])?;
            format!(
                "FLIP:     mean {:.4}, max {:.4}; map: {}",
                f.mean,
                f.max,
                paths[3].display()
            )
        }
        Err(e) => format!("FLIP:     none ({e})"),
    };
    bail!(
        "{name} does not match its golden image {}\n\
         {}got:      {metrics}\n\
         allowed:  {tol}\n\
         actual:   {}\n\
         expected: {}\n\
         diff x8:  {}\n\
         {flip_line}",
        golden_path.display(),
        size_note.unwrap_or_default(),
        paths[0].display(),
        paths[1].display(),
        paths[2].display()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image_compare::tests::{TOL, solid};
    use image::Rgba;

    fn temp_dir(tag: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("gloss-image-compare-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn golden_missing_says_how_to_create_it() {
        let dir = temp_dir("missing");
        let golden = dir.join("nope.png");
        let e = check_golden_impl("nope", &solid(2, 2, [0; 4]), &golden, &dir, &TOL, false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("GLOSS_UPDATE_GOLDEN=1 cargo test"), "{e}");
        assert!(e.contains(&golden.display().to_string()), "{e}");
    }

    #[test]
    fn golden_update_then_pass() {
        let dir = temp_dir("update");
        let golden = dir.join("golden").join("g.png");
        let img = solid(4, 3, [1, 2, 3, 255]);
        check_golden_impl("g", &img, &golden, &dir, &TOL, true).unwrap();
        assert!(golden.exists());
        let m = check_golden_impl("g", &img, &golden, &dir, &TOL, false).unwrap();
        assert_eq!(m.rmse, 0.0);
        // A 1-step difference everywhere is under the 2/255 threshold.
        let near = solid(4, 3, [2, 3, 4, 255]);
        check_golden_impl("g", &near, &golden, &dir, &TOL, false).unwrap();
        assert!(!dir.join("g.actual.png").exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn golden_failure_writes_files_and_names_them() {
        let dir = temp_dir("fail");
        let golden = dir.join("f.png");
        let expected = solid(4, 4, [50, 50, 50, 255]);
        save_png(&expected, &golden).unwrap();
        let mut actual = expected.clone();
        actual.put_pixel(1, 2, Rgba([60, 50, 50, 255]));
        let out = dir.join("out");
        let e = check_golden_impl("scene/f", &actual, &golden, &out, &TOL, false)
            .unwrap_err()
            .to_string();
        let stems = ["actual", "expected", "diff"];
        for s in stems {
            let p = out.join(format!("scene_f.{s}.png"));
            assert!(p.exists(), "{} missing", p.display());
            assert!(e.contains(&p.display().to_string()), "{e}");
        }
        assert!(e.contains("6.250% of pixels"), "{e}");
        // The FLIP map is written and named, with a mean above 0 (one
        // pixel of 16 differs).
        let flip_map = out.join("scene_f.flip.png");
        assert!(flip_map.exists(), "{} missing", flip_map.display());
        assert!(e.contains(&flip_map.display().to_string()), "{e}");
        let f = crate::image_compare::flip::flip(&actual, &expected).unwrap();
        assert!(f.mean > 0.0, "{}", f.mean);
        assert!(e.contains(&format!("FLIP:     mean {:.4}", f.mean)), "{e}");
        assert!(e.contains(&TOL.to_string()), "{e}");
        let diff = image::open(out.join("scene_f.diff.png"))
            .unwrap()
            .to_rgba8();
        assert_eq!(diff.get_pixel(1, 2), &Rgba([80, 0, 0, 255]));
        assert_eq!(
            image::open(out.join("scene_f.actual.png"))
                .unwrap()
                .to_rgba8(),
            actual
        );

        // A different size fails the same way, with a note.
        let small = solid(2, 2, [50, 50, 50, 255]);
        let e = check_golden_impl("small", &small, &golden, &out, &TOL, false)
            .unwrap_err()
            .to_string();
        assert!(e.contains("actual 2x2, expected 4x4"), "{e}");
        assert!(out.join("small.diff.png").exists());
        assert!(e.contains("FLIP:     none (cannot compute FLIP"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn file_stem_stays_in_out_dir() {
        assert_eq!(file_stem("../../etc/passwd"), "_.._etc_passwd");
        assert_eq!(file_stem(""), "image");
        assert_eq!(file_stem("a b"), "a_b");
    }
}
