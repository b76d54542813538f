//! Notes 01 §5.1 (and §4.1, "Use Barycentric coordinates"): texture
//! coordinates across a triangle. scenes/texture-affine.toml's floor (one
//! quad, two triangles, wholly in front of the camera) with the ramp
//! texture and nearest filtering, so each pixel names the texel it read. The
//! CPU projects the quad's four vertices, finds each pixel centre's
//! screen-space barycentric coordinates (a, b, c) in its triangle, and
//! predicts:
//!
//! - perspective-correct: uv = (a uv_a / w_a + b uv_b / w_b + c uv_c / w_c)
//!   / (a / w_a + b / w_b + c / w_c): "divide by w, interpolate, multiply
//!   back";
//! - affine (`noperspective`): uv = a uv_a + b uv_b + c uv_c.
//!
//! Every pixel away from a texel's edge and the triangles' edges reads the
//! texel its mode predicts, and the two modes differ by many texels.

use crate::common;
use glam::{Vec2, Vec4};
use gloss::geometry;
use gloss::math::texturing::{WrapRule, nearest_texel};
use gloss::renderer::Output;
use gloss::scene::texturing::UvInterpolation;

fn floor(mode: UvInterpolation) -> gloss::scene::Scene {
    let mut s = common::scene("texture-affine.toml");
    let m = &mut s.materials[s.objects[0].material];
    m.diffuse_texture = Some(common::root().join("scenes/assets/uv-ramp.png"));
    m.texturing.filter = gloss::scene::texturing::TextureFilter::Nearest;
    m.texturing.wrap = [gloss::scene::texturing::Wrap::Clamp; 2];
    m.texturing.uv_scale = [1.0, 1.0];
    s.render.uv_interpolation = mode;
    s
}

/// Distance of x from the nearest whole number.
fn off_whole(x: f64) -> f64 {
    (x - x.round()).abs()
}

#[test]
fn perspective_correct_and_affine_texture_coordinates_match_their_formulas() {
    let ctx = common::context(common::backend());
    let s = floor(UvInterpolation::Perspective);
    let (w, h) = (s.render.size.0 as f64, s.render.size.1 as f64);
    let vp = s.camera.projection((w / h) as f32) * s.camera.view();
    let mesh = geometry::plane(2.0, 2.0, 1);
    // Each vertex: window position, 1 / w, uv.
    let verts: Vec<(Vec2, f64, Vec2)> = mesh
        .vertices
        .iter()
        .map(|v| {
            let clip = vp * s.objects[0].model * Vec4::from((glam::Vec3::from(v.position), 1.0));
            assert!(clip.w > 0.1, "the quad lies wholly in front of the camera");
            let ndc = clip.truncate() / clip.w;
            let win = Vec2::new(
                ((ndc.x + 1.0) * 0.5) * w as f32,
                ((ndc.y + 1.0) * 0.5) * h as f32,
            );
            (win, 1.0 / clip.w as f64, Vec2::from(v.uv))
        })
        .collect();
    let images = [UvInterpolation::Perspective, UvInterpolation::Affine]
        .map(|mode| common::render_with(&ctx, &floor(mode), Output::Srgb8).image);
    let (mut checked, mut apart, mut wrong) = ([0usize; 2], 0usize, Vec::new());
    for y in 0..h as u32 {
        for x in 0..w as u32 {
            let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            for tri in mesh.indices.chunks(3) {
                let [a, b, c] = [0, 1, 2].map(|k| verts[tri[k] as usize]);
                let area = (b.0 - a.0).perp_dot(c.0 - a.0) as f64;
                let bary = [
                    (c.0 - b.0).perp_dot(p - b.0) as f64 / area,
                    (a.0 - c.0).perp_dot(p - c.0) as f64 / area,
                    (b.0 - a.0).perp_dot(p - a.0) as f64 / area,
                ];
                // Inside, and a pixel or more from every edge.
                if bary.iter().any(|&l| l < 0.0) {
                    continue;
                }
                let edge_px = bary
                    .iter()
                    .zip([(b.0, c.0), (c.0, a.0), (a.0, b.0)])
                    .map(|(l, (e0, e1))| l * area.abs() / (e1 - e0).length() as f64)
                    .fold(f64::MAX, f64::min);
                if edge_px < 1.5 {
                    continue;
                }
                let v = [a, b, c];
                let affine = (0..3).fold((0.0, 0.0), |acc, k| {
                    (
                        acc.0 + bary[k] * v[k].2.x as f64,
                        acc.1 + bary[k] * v[k].2.y as f64,
                    )
                });
                let q: f64 = (0..3).map(|k| bary[k] * v[k].1).sum();
                let perspective = (0..3).fold((0.0, 0.0), |acc, k| {
                    let wk = bary[k] * v[k].1 / q;
                    (acc.0 + wk * v[k].2.x as f64, acc.1 + wk * v[k].2.y as f64)
                });
                let row = (h as u32) - 1 - y;
                for (m, uv) in [perspective, affine].iter().enumerate() {
                    // Away from a texel's edge (1/20 texel).
                    if off_whole(uv.0 * 64.0) < 0.05 || off_whole(uv.1 * 64.0) < 0.05 {
                        continue;
                    }
                    checked[m] += 1;
                    let want = (
                        nearest_texel(uv.0, 64, WrapRule::Clamp) as i64,
                        nearest_texel(uv.1, 64, WrapRule::Clamp) as i64,
                    );
                    let got = crate::ramp_texel(images[m].get_pixel(x, row));
                    if got != want {
                        wrong.push((["perspective", "affine"][m], x, y, got, want));
                    }
                }
                if (perspective.1 - affine.1).abs() * 64.0 > 5.0 {
                    apart += 1;
                }
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{} pixels read another texel than their formula gives; first (mode, x, y from the bottom, read, predicted): {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(8)]
    );
    assert!(checked[0] > 20_000 && checked[1] > 20_000, "{checked:?}");
    // The artefact is large: thousands of pixels 5 texels or more apart in v.
    assert!(
        apart > 5_000,
        "only {apart} pixels differ by 5 texels between the modes"
    );
}
