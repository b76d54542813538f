//! Cascaded shadow maps (src/techniques/shadows/cascaded_shadow_maps.rs,
//! src/math/cascades.rs, glsl/shadows/cascaded_shadow_maps.glsl) against
//! the exact shadows (src/bench/shadows.rs: a ray from each pixel's surface
//! point to the light against the scene's triangles):
//!
//! * on scenes/cascaded-shadows.toml at 480 x 270, per cascade count and
//!   split scheme, the misclassified pixels stay within the bounds of the
//!   table below, and four practical cascades beat the single map;
//! * a shadow edge that runs across a split is right on both sides of it
//!   and inside the blend band: no gap, no double shadow;
//! * moving the camera sideways a fraction of a texel a frame, or orbiting
//!   it a degree a frame, the shadow edges of stable cascades
//!   stay put in the world and those of tight cascades shimmer.

use crate::common;
use glam::Vec3;
use gloss::bench::shadows::{ShadowEvaluation, evaluate};
use gloss::frame::views::View;
use gloss::image_compare::shadow_mask::GlShadow;
use gloss::image_compare::shadow_metrics::Visibility;
use gloss::lighting::shadow_reference::pixel_world_point;
use gloss::renderer::{Output, render_scene};
use gloss::scene::{CascadeSplit, Pcf, Scene};

fn small() -> Scene {
    let mut s = common::scene("cascaded-shadows.toml");
    s.render.size = (480, 270);
    s
}

fn set(s: &mut Scene, cascades: u32, split: CascadeSplit, lambda: f32) {
    let sh = s.lights[0].shadow.as_mut().unwrap();
    (sh.cascades, sh.split, sh.lambda) = (cascades, split, lambda);
}

fn save(label: &str, e: &ShadowEvaluation) {
    let dir = common::out_dir();
    e.images[0]
        .save(dir.join(format!("{label}.actual.png")))
        .unwrap();
}

/// (cascades, split, lambda, the most misclassified, measured 0.38%,
/// 0.36, 0.14, 0.08, 0.09, 0.02, 0.03, 0.01, 0.01% on llvmpipe): about
/// twice what was measured, and never above the 1% of every shadow scene.
const BOUNDS: [(u32, CascadeSplit, f32, f64); 9] = [
    (1, CascadeSplit::Practical, 0.5, 0.0080),
    (2, CascadeSplit::Uniform, 0.0, 0.0070),
    (2, CascadeSplit::Logarithmic, 0.0, 0.0030),
    (2, CascadeSplit::Practical, 0.5, 0.0020),
    (4, CascadeSplit::Uniform, 0.0, 0.0020),
    (4, CascadeSplit::Logarithmic, 0.0, 0.0006),
    (4, CascadeSplit::Practical, 0.5, 0.0008),
    (4, CascadeSplit::Practical, 0.75, 0.0004),
    (8, CascadeSplit::Practical, 0.75, 0.0004),
];

#[test]
fn each_count_and_split_against_the_exact_shadows() {
    let ctx = common::context(common::backend());
    let mut errors = Vec::new();
    for (cascades, split, lambda, most) in BOUNDS {
        let mut s = small();
        set(&mut s, cascades, split, lambda);
        let e = evaluate(&ctx, &s).unwrap();
        let label = format!("csm-{cascades}-{}-{lambda}", split.name());
        assert!(e.errors.judged > 50_000, "{label}: {}", e.errors);
        if e.errors.misclassified > most || e.errors.acne > 0.005 {
            save(&label, &e);
            panic!("{label}: {} (bound {:.2}%)", e.errors, most * 100.0);
        }
        errors.push(e.errors.misclassified);
    }
    // The single map over a hundred units of field is blocky near the
    // camera; four practical cascades are at least ten times closer.
    assert!(
        errors[0] > 0.002,
        "the single map: {:.3}%",
        errors[0] * 100.0
    );
    assert!(errors[7] * 10.0 < errors[0], "{errors:?}");
    // With perspective, more of the near range beats equal ranges.
    assert!(errors[5] < errors[4] && errors[6] < errors[4], "{errors:?}");
}

/// A wall along the view axis under a low sun from the side: its shadow's
/// edge runs straight through the split at view depth 15.25 (two uniform
/// cascades of [0.5, 30]: the camera's far plane lies inside the field).
fn wall_across_the_split(blend: f32, resolution: u32, light: [f32; 3], look_down: f32) -> Scene {
    let text = format!(
        r#"
        name = "csm-split"
        [camera]
        eye = [0.0, 3.0, 0.0]
        target = [0.0, {}, -12.0]
        fov_y = 60.0
        near = 0.5
        far = 30.0
        [render]
        size = [480, 270]
        ambient = [0.05, 0.05, 0.05]
        [[lights]]
        type = "directional"
        direction = [{}, {}, {}]
        shadow = {{ resolution = {resolution}, cascades = 2, split = "uniform", stable = true, blend = {blend}, pcf = "none" }}
        [materials.grey]
        diffuse = [0.8, 0.8, 0.8]
        specular = [0.0, 0.0, 0.0]
        [[objects]]
        name = "floor"
        mesh = "plane"
        material = "grey"
        position = [0.0, 0.0, -40.0]
        scale = [20.0, 1.0, 45.0]
        [[objects]]
        name = "wall"
        mesh = "cube"
        material = "grey"
        position = [3.0, 2.0, -40.0]
        scale = [0.1, 2.0, 39.0]
    "#,
        3.0 - look_down,
        light[0],
        light[1],
        light[2]
    );
    Scene::parse(&text, std::path::Path::new("csm-split.toml")).unwrap()
}

#[test]
fn a_shadow_edge_across_a_split_has_no_gap_and_no_double_shadow() {
    let ctx = common::context(common::backend());
    for (blend, stable) in [(0.0, true), (0.2, true), (0.0, false), (0.2, false)] {
        let mut s = wall_across_the_split(blend, 1024, [-0.3, -1.0, 0.0], 0.0);
        s.lights[0].shadow.as_mut().unwrap().stable = stable;
        let e = evaluate(&ctx, &s).unwrap();
        let (w, h) = (e.mask.width, e.mask.height);
        let eye = s.camera.eye;
        let forward = (s.camera.target - eye).normalize();
        // The floor's pixels from the blend band's start to past the split
        // (view depth 12 to 18; the split is at 15.25, the band 0.2 x 14.75
        // before it), not on the true boundary (a 5 x 5 block alike).
        let (mut judged, mut shadowed, mut gap, mut double) = (0, 0, 0, 0);
        for y in 2..h - 2 {
            for x in 2..w - 2 {
                let i = y * w + x;
                if e.depth[i] >= 1.0 || e.mask.pixels[i] == GlShadow::Ignored {
                    continue;
                }
                let p = pixel_world_point(x, y, e.depth[i], e.inverse_view_projection, w, h);
                let z = (p - eye).dot(forward);
                if p.y.abs() > 1e-3 || !(12.0..=18.0).contains(&z) {
                    continue;
                }
                let r = e.reference[i];
                let alike = (-2..=2).all(|dy: isize| {
                    (-2..=2).all(|dx: isize| {
                        let j = (y as isize + dy) as usize * w + (x as isize + dx) as usize;
                        e.reference[j] == r
                    })
                });
                if !alike || r == Visibility::Background {
                    continue;
                }
                judged += 1;
                let gl_shadowed = e.mask.pixels[i] == GlShadow::Shadowed;
                match (r, gl_shadowed) {
                    (Visibility::Shadowed, true) => shadowed += 1,
                    (Visibility::Shadowed, false) => gap += 1,
                    (Visibility::Lit, true) => double += 1,
                    _ => {}
                }
            }
        }
        let label = format!("csm-split-blend-{blend}-stable-{stable}");
        if !(judged > 3_000 && shadowed > 300) || gap + double > judged / 200 {
            save(&label, &e);
            panic!(
                "{label}: {judged} floor pixels judged about the split, {shadowed} shadowed; {gap} lit that the wall shadows (gap), {double} shadowed that are lit (double shadow): at most 0.5%"
            );
        }
    }
}

/// One frame of the shimmer test: whether each floor pixel is dark, the
/// depth, and the camera's view-projection.
struct Frame {
    dark: Vec<Option<bool>>,
    depth: Vec<f32>,
    view_projection: glam::Mat4,
    size: (usize, usize),
}

fn frame(s: &Scene, ctx: &gloss::gl::Headless) -> Frame {
    let r = render_scene(ctx, s, Output::Srgb8).unwrap();
    let (w, h) = (r.width as usize, r.height as usize);
    let depth = r.read_depth();
    let image = r.read_image();
    let inverse = r
        .frame_uniforms(&s.camera, &View::camera())
        .inverse_view_projection;
    let mut dark = vec![None; w * h];
    for y in 0..h {
        for x in 0..w {
            let d = depth[y * w + x];
            if d >= 1.0 || pixel_world_point(x, y, d, inverse, w, h).y.abs() > 1e-3 {
                continue;
            }
            // The floor: lit 0.8 x N.L (about 180 in sRGB), or the ambient (about 60).
            dark[y * w + x] = Some(image.get_pixel(x as u32, (h - 1 - y) as u32)[0] < 120);
        }
    }
    Frame {
        dark,
        depth,
        view_projection: inverse.inverse(),
        size: (w, h),
    }
}

/// The floor pixels of `b` whose world point, seen in `a` (the nearest
/// pixel, away from `a`'s edges), was dark there and is lit here or the
/// other way round: the shadow moved on the floor.
fn flips(a: &Frame, b: &Frame) -> usize {
    let (w, h) = b.size;
    let inverse = b.view_projection.inverse();
    let mut n = 0;
    for y in 0..h {
        for x in 0..w {
            let Some(now) = b.dark[y * w + x] else {
                continue;
            };
            let p = pixel_world_point(x, y, b.depth[y * w + x], inverse, w, h);
            let q = a.view_projection.project_point3(p);
            let (xa, ya) = ((q.x + 1.0) * 0.5 * w as f32, (q.y + 1.0) * 0.5 * h as f32);
            if !(0.0..w as f32).contains(&xa) || !(0.0..h as f32).contains(&ya) {
                continue;
            }
            // Only where `a` is alike a pixel around: a pixel's centre may
            // land either side of an edge that did not move.
            let (xa, ya) = (xa as usize, ya as usize);
            let then = a.dark[ya * w + xa];
            let alike = (ya.saturating_sub(1)..(ya + 2).min(h)).all(|y| {
                (xa.saturating_sub(1)..(xa + 2).min(w)).all(|x| a.dark[y * w + x] == then)
            });
            if let (Some(then), true) = (then, alike) {
                n += (then != now) as usize;
            }
        }
    }
    n
}

/// The floor pixels whose shadow moved, summed over five frame pairs, for
/// stable and for tight cascades, the camera moved by `camera(scene, k)` at
/// frame k: (stable, tight).
fn shimmer(ctx: &gloss::gl::Headless, camera: impl Fn(&mut Scene, usize)) -> (usize, usize) {
    let mut by_fit = Vec::new();
    for stable in [true, false] {
        let mut s = wall_across_the_split(0.0, 128, [-1.0, -0.55, 0.5], 3.0);
        // The light turned so that the wall's shadow edge runs across its
        // texel grid: a staircase of coarse texels.
        let sh = s.lights[0].shadow.as_mut().unwrap();
        (sh.stable, sh.pcf, sh.cascades, sh.resolution) = (stable, Pcf::None, 4, 128);
        let frames: Vec<Frame> = (0..6)
            .map(|k| {
                let mut f = s.clone();
                camera(&mut f, k);
                frame(&f, ctx)
            })
            .collect();
        by_fit.push(
            frames
                .windows(2)
                .map(|p| flips(&p[0], &p[1]))
                .sum::<usize>(),
        );
    }
    (by_fit[0], by_fit[1])
}

#[test]
fn moving_the_camera_a_fraction_of_a_texel_stable_cascades_do_not_shimmer() {
    let ctx = common::context(common::backend());
    // The first cascade's texel is about 0.13 world units: a step of
    // about a third of it sideways each frame.
    let step = Vec3::new(0.045, 0.0, 0.0);
    let (stable, tight) = shimmer(&ctx, |f, k| {
        f.camera.eye += step * k as f32;
        f.camera.target += step * k as f32;
    });
    eprintln!(
        "camera moved sideways: floor pixels whose shadow moved, stable {stable}, tight {tight}"
    );
    // Measured on llvmpipe: stable 0, tight 253 pixels over five pairs.
    assert!(
        tight > 100 && stable * 10 <= tight,
        "floor pixels whose shadow moved from frame to frame: stable {stable}, tight {tight}"
    );
}

#[test]
fn orbiting_the_camera_in_small_steps_stable_cascades_do_not_shimmer() {
    // The issue's case: an orbiting camera, measured frame to frame. The
    // eye turns about the target around the vertical axis, a degree a
    // frame: the view's frustum turns, so tight cascades' boxes change size
    // and their texel grids slide; the stable cascades' bounding spheres
    // keep their size and their boxes snap to whole texels. (At a quarter
    // of a degree a frame tight cascades moved only 33 pixels.)
    let ctx = common::context(common::backend());
    let (stable, tight) = shimmer(&ctx, |f, k| {
        let turn = glam::Quat::from_rotation_y((1.0 * k as f32).to_radians());
        f.camera.eye = f.camera.target + turn * (f.camera.eye - f.camera.target);
    });
    eprintln!("camera orbiting: floor pixels whose shadow moved, stable {stable}, tight {tight}");
    // Measured on llvmpipe: stable 3, tight 414 pixels over five pairs.
    assert!(
        tight > 100 && stable * 10 <= tight,
        "floor pixels whose shadow moved from frame to frame: stable {stable}, tight {tight}"
    );
}
