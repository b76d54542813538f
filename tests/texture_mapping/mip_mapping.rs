//! Notes 01 §5.3, MIP mapping: "MIP map is selected using the level of
//! detail lambda ... calculated using the derivatives of the interpolated
//! texture coordinates". The checkerboard floor running to the horizon
//! (scenes/texture-filtering.toml) with `render.mip_colors` on and the
//! nearest-mip filter: each pixel shows the colour of the level GL picked.
//! The CPU finds, for each pixel, the floor point under it, its (u, v), the
//! derivatives across the pixel's 2 x 2 quad (as the rasteriser takes them),
//! lambda = log2 rho, and the level GL_NEAREST_MIPMAP_NEAREST reads
//! (src/math/texture_mapping.rs). Every pixel not within 0.1 of a switch between
//! levels must show its level's colour.

use crate::common;
use glam::{Vec3, Vec4};
use gloss::frame::texturing::LEVEL_COLORS;
use gloss::math::texture_mapping::{lod, nearest_level};
use gloss::renderer::Output;
use gloss::scene::Scene;

/// For each pixel of the floor (x, y from the bottom), the four level of
/// detail estimates over its 2 x 2 quad (both rows' du/dx with both
/// columns' dv/dy, as the rasteriser may take them), for a texture of
/// `size` texels; None off the floor. Indexed y * w + x.
pub fn quad_lambdas(s: &Scene, w: i64, h: i64, size: f64) -> Vec<Option<[f64; 4]>> {
    let floor = &s.objects[0];
    let t = s.materials[floor.material].texturing;
    let inverse = (s.camera.projection(w as f32 / h as f32) * s.camera.view()).inverse();
    let to_floor = floor.model.inverse();
    // (u, v) x uv_scale under window position (x, y) (y up from the
    // bottom), or None where the ray misses the floor.
    let uv = |x: f64, y: f64| -> Option<(f64, f64)> {
        let ndc = |a: f64, n: i64| (2.0 * a / n as f64 - 1.0) as f32;
        let p = |z: f32| {
            let q = inverse * Vec4::new(ndc(x, w), ndc(y, h), z, 1.0);
            q.truncate() / q.w
        };
        let (a, b) = (p(-1.0), p(1.0));
        let d = b - a;
        if d.y >= 0.0 {
            return None;
        }
        let hit = a - d * (a.y / d.y);
        let local: Vec3 = to_floor.transform_point3(hit);
        if local.x.abs() > 1.0 || local.z.abs() > 1.0 {
            return None;
        }
        // The plane mesh: u = x / 2 + 1/2, v = 1/2 - z / 2.
        let (u, v) = (0.5 + 0.5 * local.x as f64, 0.5 - 0.5 * local.z as f64);
        Some((u * t.uv_scale[0] as f64, v * t.uv_scale[1] as f64))
    };
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            if uv(x as f64 + 0.5, y as f64 + 0.5).is_none() {
                out.push(None);
                continue;
            }
            let (x0, y0) = ((x & !1) as f64 + 0.5, (y & !1) as f64 + 0.5);
            let corners =
                [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)].map(|(i, j)| uv(x0 + i, y0 + j));
            let [Some(a), Some(b), Some(c), Some(d)] = corners else {
                out.push(Some([f64::NAN; 4]));
                continue;
            };
            let mut lambdas = [0.0; 4];
            let mut k = 0;
            for (l, r) in [(a, b), (c, d)] {
                for (lo, hi) in [(a, c), (b, d)] {
                    let (dudx, dvdx) = (r.0 - l.0, r.1 - l.1);
                    let (dudy, dvdy) = (hi.0 - lo.0, hi.1 - lo.1);
                    lambdas[k] = lod(dudx, dvdx, dudy, dvdy, size, size);
                    k += 1;
                }
            }
            out.push(Some(lambdas));
        }
    }
    out
}

#[test]
fn each_pixel_shows_the_level_lambda_predicts() {
    let mut s = common::scene("texture-filtering.toml");
    s.render.mip_colors = true;
    s.render.texture_filter = gloss::scene::texturing::FilterOverride::NearestMip;
    let r = common::render(&s, Output::Srgb8);
    let (w, h) = (r.width as i64, r.height as i64);
    let all = quad_lambdas(&s, w, h, 256.0);
    let (mut checked, mut wrong, mut levels) = (0usize, Vec::new(), [0usize; 9]);
    let mut floor_pixels = 0usize;
    for y in 0..h {
        for x in 0..w {
            let Some(lambdas) = all[(y * w + x) as usize] else {
                continue;
            };
            floor_pixels += 1;
            if lambdas[0].is_nan() {
                continue;
            }
            let level = nearest_level(lambdas[0], 8);
            // The level switches at lambda = k + 1/2.
            let near_switch = lambdas
                .iter()
                .any(|&l| ((l - 0.5) - (l - 0.5).round()).abs() < 0.1);
            if near_switch || lambdas.iter().any(|&l| nearest_level(l, 8) != level) {
                continue;
            }
            checked += 1;
            levels[level as usize] += 1;
            let p = r.image.get_pixel(x as u32, (h - 1 - y) as u32);
            let got = [p[0] > 127, p[1] > 127, p[2] > 127];
            let want = LEVEL_COLORS[level as usize % LEVEL_COLORS.len()].map(|c| c > 127);
            if got != want {
                wrong.push((x, y, level, lambdas[0], [p[0], p[1], p[2]]));
            }
        }
    }
    assert!(
        checked * 10 >= floor_pixels * 7,
        "only {checked} of {floor_pixels} floor pixels were away from a switch between levels"
    );
    assert!(
        wrong.is_empty(),
        "{} of {checked} pixels show another level than lambda predicts; first (x, y from the bottom, level, lambda, rgb): {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(8)]
    );
    for (k, n) in levels.iter().enumerate().take(6) {
        assert!(*n > 0, "no pixel reads level {k}: {levels:?}");
    }
}

#[test]
fn the_plan_reports_the_mip_chains_memory() {
    let s = common::scene("texture-filtering.toml");
    let text = gloss::techniques::plan(&s).to_string();
    // One 256 x 256 RGBA8 texture: 262144 bytes at level 0, 349524 with its chain.
    assert!(text.contains("349524"), "{text}");
}
