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
use glam::{DVec2, Vec4};
use gloss::geometry;
use gloss::math::interpolation::{barycentric, edge_distance, mix3, perspective_correct};
use gloss::math::texture_mapping::{WrapRule, nearest_texel};
use gloss::renderer::Output;
use gloss::scene::texturing::Interpolation;

fn floor(mode: Interpolation) -> gloss::scene::Scene {
    let mut s = common::scene("texture-affine.toml");
    let m = &mut s.materials[s.objects[0].material];
    m.diffuse_texture = Some(common::root().join("scenes/assets/uv-ramp.png"));
    m.texturing.filter = gloss::scene::texturing::TextureFilter::Nearest;
    m.texturing.wrap = [gloss::scene::texturing::Wrap::Clamp; 2];
    m.texturing.uv_scale = [1.0, 1.0];
    s.render.interpolation = mode;
    s
}

/// Distance of x from the nearest whole number.
fn off_whole(x: f64) -> f64 {
    (x - x.round()).abs()
}

#[test]
fn perspective_correct_and_affine_texture_coordinates_match_their_formulas() {
    let ctx = common::context(common::backend());
    let s = floor(Interpolation::Perspective);
    let (w, h) = (s.render.size.0 as f64, s.render.size.1 as f64);
    let vp = s.camera.projection((w / h) as f32) * s.camera.view();
    let mesh = geometry::plane(2.0, 2.0, 1);
    // Each vertex: window position, clip w, uv.
    let verts: Vec<(DVec2, f64, DVec2)> = mesh
        .vertices
        .iter()
        .map(|v| {
            let clip = vp * s.objects[0].model * Vec4::from((glam::Vec3::from(v.position), 1.0));
            assert!(clip.w > 0.1, "the quad lies wholly in front of the camera");
            let ndc = DVec2::new(f64::from(clip.x / clip.w), f64::from(clip.y / clip.w));
            let win = (ndc + 1.0) * 0.5 * DVec2::new(w, h);
            (
                win,
                f64::from(clip.w),
                DVec2::new(f64::from(v.uv[0]), f64::from(v.uv[1])),
            )
        })
        .collect();
    let images = [Interpolation::Perspective, Interpolation::Affine]
        .map(|mode| common::render_with(&ctx, &floor(mode), Output::Srgb8).image);
    let (mut checked, mut apart, mut wrong) = ([0usize; 2], 0usize, Vec::new());
    for y in 0..h as u32 {
        for x in 0..w as u32 {
            let p = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            for tri in mesh.indices.chunks(3) {
                let v = [0, 1, 2].map(|k| verts[tri[k] as usize]);
                let screen = v.map(|v| v.0);
                let Some(bary) = barycentric(p, screen) else {
                    continue;
                };
                // Inside, and more than 1.5 pixels from every edge.
                if bary.iter().any(|&l| l < 0.0) || edge_distance(p, screen) < 1.5 {
                    continue;
                }
                let persp = perspective_correct(bary, v.map(|v| v.1));
                let uv_with =
                    |wt: [f64; 3]| (mix3(wt, v.map(|v| v.2.x)), mix3(wt, v.map(|v| v.2.y)));
                let (perspective, affine) = (uv_with(persp), uv_with(bary));
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
