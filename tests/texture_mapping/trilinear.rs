//! Trilinear against bilinear_mip (notes 01 §5.3.1: "Trilinear filtering ...
//! interpolate between the two closest MIP levels"): the checkerboard
//! floor with `render.mip_colors` (level k is LEVEL_COLORS[k], flat), read
//! back linear. At a pixel whose level of detail lambda lies between two
//! levels (its fraction 0.3 to 0.7), the CPU twins say what each filter
//! shows (src/math/texture_mapping.rs): GL_LINEAR_MIPMAP_LINEAR mixes
//! level floor(lambda) and the next by lambda's fraction
//! (`linear_levels`); GL_LINEAR_MIPMAP_NEAREST shows one level's colour
//! (`nearest_level`). The weight of the second level is read from the
//! pixel and each image must match its own twin, not the other's.

use crate::common;
use crate::mip_mapping::quad_lambdas;
use glam::Vec3;
use gloss::frame::texturing::LEVEL_COLORS;
use gloss::math::texture_mapping::{linear_levels, nearest_level};
use gloss::renderer::Output;
use gloss::scene::texturing::FilterOverride;

const LAST: u32 = 8;

fn colour(level: u32) -> Vec3 {
    let c = LEVEL_COLORS[level as usize % LEVEL_COLORS.len()];
    Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32) / 255.0
}

/// For every floor pixel between two levels: (the weight of the second
/// level the image shows, lambda's fraction: trilinear's weight, and
/// bilinear_mip's weight, 0 or 1).
fn weights(filter: FilterOverride) -> Vec<(f32, f64, f64)> {
    let mut s = common::scene("texture-filtering.toml");
    s.render.mip_colors = true;
    s.render.texture_filter = filter;
    let r = common::render(&s, Output::Linear32F);
    let (w, h) = (r.width as i64, r.height as i64);
    let mut out = Vec::new();
    for (i, lambdas) in quad_lambdas(&s, w, h, 256.0).into_iter().enumerate() {
        let Some(l) = lambdas.filter(|l| !l[0].is_nan()) else {
            continue;
        };
        // All four estimates between the same two levels, well inside.
        let (d1, d2, _) = linear_levels(l[0], LAST);
        let fractions: Vec<f64> = l.iter().map(|&x| x - d1 as f64).collect();
        if d2 == d1 || d1 == 0 || fractions.iter().any(|f| !(0.3..=0.7).contains(f)) {
            continue;
        }
        let mean = fractions.iter().sum::<f64>() / 4.0;
        // bilinear_mip: one level, the nearest (ambiguous near 0.5: skipped).
        if (mean - 0.5).abs() < 0.1 {
            continue;
        }
        let nearest = nearest_level(l.iter().sum::<f64>() / 4.0, LAST);
        let bilinear_mip = if nearest == d2 { 1.0 } else { 0.0 };
        let p = &r.linear[i * 4..i * 4 + 3];
        let got = Vec3::new(p[0], p[1], p[2]);
        let (a, b) = (colour(d1), colour(d2));
        let t = (got - a).dot(b - a) / (b - a).length_squared();
        out.push((t, mean, bilinear_mip));
    }
    out
}

/// How many pixels are within `tol` of the trilinear twin and of the
/// bilinear_mip twin.
fn matches(ws: &[(f32, f64, f64)], tol: f64) -> (usize, usize) {
    let near = |t: f32, want: f64| (t as f64 - want).abs() <= tol;
    (
        ws.iter().filter(|(t, tri, _)| near(*t, *tri)).count(),
        ws.iter().filter(|(t, _, bi)| near(*t, *bi)).count(),
    )
}

#[test]
fn trilinear_mixes_two_levels_where_bilinear_mip_shows_one() {
    let tri = weights(FilterOverride::Trilinear);
    let bi = weights(FilterOverride::BilinearMip);
    assert!(
        tri.len() > 5000,
        "only {} pixels between two levels",
        tri.len()
    );
    let (tri_as_tri, tri_as_bi) = matches(&tri, 0.1);
    let (bi_as_tri, bi_as_bi) = matches(&bi, 0.1);
    eprintln!(
        "{} pixels: the trilinear image matches its twin at {tri_as_tri}, bilinear_mip's at {tri_as_bi}; the bilinear_mip image matches its twin at {bi_as_bi}, trilinear's at {bi_as_tri}",
        tri.len()
    );
    // Every pixel of each image is its own filter's, none the other's.
    assert_eq!(
        tri_as_tri,
        tri.len(),
        "trilinear image against the trilinear twin"
    );
    assert_eq!(
        tri_as_bi, 0,
        "trilinear image against the bilinear_mip twin"
    );
    assert_eq!(
        bi_as_bi,
        bi.len(),
        "bilinear_mip image against the bilinear_mip twin"
    );
    assert_eq!(
        bi_as_tri, 0,
        "bilinear_mip image against the trilinear twin"
    );
}
