//! The cascade colours (`shadow.cascade_colors`; src/frame/shadows/cascades.rs,
//! glsl/shadows/cascade_block.glsl) on every path the cascades run on:
//! forward tints the point it lights; deferred, volumes and tiled tint in
//! the composite by the G-buffer's point; the light pre-pass in its combine
//! pass. Per pixel, the tint (the linear image with colours over the one
//! without) must be the cascade that the CPU's split computation
//! (`math::cascades::splits`, Zhang et al.'s practical split) gives for the
//! pixel's view depth, rebuilt from the depth buffer.

use crate::common;
use glam::Vec3;
use gloss::frame::views::View;
use gloss::lighting::shadow_reference::pixel_world_point;
use gloss::math::cascades::splits;
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene};

/// The tints of glsl/shadows/cascade_block.glsl, as the docs page lists them.
const TINTS: [Vec3; 4] = [
    Vec3::new(1.0, 0.45, 0.45),
    Vec3::new(0.45, 1.0, 0.45),
    Vec3::new(0.5, 0.6, 1.0),
    Vec3::new(1.0, 1.0, 0.4),
];

fn scene(path: RenderPath, colors: bool) -> Scene {
    let mut s = common::scene("cascaded-shadows.toml");
    s.render.size = (320, 180);
    s.render.path = path;
    // The far plane inside the field: the frame's visible fit then keeps
    // camera.far (the field reaches further), so the CPU knows the range.
    s.camera.far = 40.0;
    // Looking further down, so that the first cascade (to 3.3) holds floor.
    s.camera.target = Vec3::new(0.0, 0.0, 2.0);
    let sh = s.lights[0].shadow.as_mut().unwrap();
    // No blend band: each pixel one cascade's tint.
    (sh.cascade_colors, sh.blend) = (colors, 0.0);
    s
}

#[test]
fn the_cascade_colour_at_each_pixel_is_the_cpu_splits_cascade_on_every_path() {
    let ctx = common::context(common::backend());
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Tiled,
        RenderPath::Prepass,
    ] {
        let on = scene(path, true);
        let sh = on.lights[0].shadow.unwrap();
        let (near, far) = (on.camera.near, on.camera.far);
        let split = splits(near, far, sh.cascades, sh.lambda);
        assert_eq!(split.len() as u32, sh.cascades + 1);
        let a = render_scene(&ctx, &on, Output::Linear32F).unwrap();
        let b = render_scene(&ctx, &scene(path, false), Output::Linear32F).unwrap();
        let (w, h) = (a.width as usize, a.height as usize);
        let (tinted, plain, depth) = (a.read_linear(), b.read_linear(), a.read_depth());
        let inverse = a
            .frame_uniforms(&on.camera, &View::camera())
            .inverse_view_projection;
        let forward = (on.camera.target - on.camera.eye).normalize();
        let (mut judged, mut wrong, mut per) = (0, 0, [0usize; 4]);
        let mut first_wrong = None;
        for y in 0..h {
            for x in 0..w {
                let d = depth[y * w + x];
                if d >= 1.0 {
                    continue;
                }
                let p = pixel_world_point(x, y, d, inverse, w, h);
                let z = (p - on.camera.eye).dot(forward);
                // Away from the splits (0.5 % of the depth): a pixel's
                // depth is its centre's, the shader's its own.
                if split.iter().any(|s| (z - s).abs() < 0.005 * s) {
                    continue;
                }
                let k = (1..split.len() - 1).filter(|&i| z > split[i]).count();
                let i = 4 * (y * w + x);
                let c = Vec3::new(plain[i], plain[i + 1], plain[i + 2]);
                if c.min_element() < 0.01 {
                    continue;
                }
                let ratio = Vec3::new(tinted[i], tinted[i + 1], tinted[i + 2]) / c;
                let (best, err) = (0..4)
                    .map(|t| (t, (ratio - TINTS[t]).abs().max_element()))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .unwrap();
                judged += 1;
                per[k] += 1;
                if best != k || err > 0.01 {
                    wrong += 1;
                    first_wrong.get_or_insert((x, y, z, k, ratio));
                }
            }
        }
        eprintln!(
            "{path}: splits {split:?}; {judged} pixels judged (per cascade {per:?}), {wrong} with another tint"
        );
        assert!(
            per.iter().all(|&n| n > 100),
            "{path}: too few pixels in some cascade: {per:?}"
        );
        assert!(
            wrong * 1000 <= judged,
            "{path}: {wrong} of {judged} pixels tinted otherwise; first (x, y, view depth, CPU cascade, ratio): {first_wrong:?}"
        );
    }
}
