//! The ambient light pass, SSAO (notes 03, Ambient Light;
//! src/techniques/deferred/ambient_light.rs), against the analytic corner
//! and the ray-traced CPU reference (src/lighting/ambient_occlusion.rs).
//! AO definition: cosine-weighted visibility within r (docs/deferred/ambient_light.md).
//!
//! * an open plane seen down to a grazing angle, 4, 16 and 64 samples,
//!   blurred or not: AO exactly 1 on every pixel, and on every G-buffer
//!   path the image is bit for bit the image without [ambient_occlusion]
//!   (the ambient term counted once);
//! * a 90-degree corner, r = 0.5, 64 samples: per pixel within
//!   CORNER_MAX_ERROR (0.04; measured 0.023) of
//!   AO(d) = 1 - (acos a - a sqrt(1 - a^2)) / pi,  a = (d + bias) / r,
//!   blurred over the pass's 4x4 window, and within CORNER_MEAN_ERROR
//!   (0.005; measured 0.0018) on average, over the pixels whose
//!   r-neighbourhood is on screen;
//! * the image border (the corner cut by every edge): no pixel of the
//!   4-pixel band darker than the analytic AO by more than BORDER_DARKER
//!   (0.06; measured 0.024): what SSAO cannot see it leaves open;
//! * a ball 4.5 r in front of a wall: no darkened wall pixel at all (halo
//!   width 0: the range check and the depth-aware blur);
//! * the shipped scene at 192x108 against the CPU reference (256 rays a
//!   pixel): mean and 95th-percentile |error| within 0.02 and 0.1 at 16
//!   samples (measured 0.012 and 0.066); the mean falls from 4 to 16 to 64
//!   samples, and without the blur by more than 1.5 times from 4 to 64
//!   (measured 0.021 to 0.0077).

use crate::common;
use crate::with_path;
use glam::Vec3;
use gloss::bench::ssao::{AoFrame, error, render_ao};
use gloss::lighting::ambient_occlusion::corner;
use gloss::lighting::shadow_reference::pixel_world_point;
use gloss::renderer::Output;
use gloss::scene::ambient_occlusion::AmbientOcclusion;
use gloss::scene::{RenderPath, Scene};

/// Bounds of the corner test (64 samples, blurred).
const CORNER_MAX_ERROR: f32 = 0.04;
const CORNER_MEAN_ERROR: f64 = 0.005;
/// The border band (pixels) and how much darker than the analytic AO it may be.
const BORDER: usize = 4;
const BORDER_DARKER: f32 = 0.06;
/// The shipped scene against the reference, 16 samples, blurred.
const SCENE_MEAN_ERROR: f64 = 0.02;
const SCENE_P95_ERROR: f64 = 0.1;

fn parse(text: &str) -> Scene {
    Scene::parse(text, std::path::Path::new("ambient-light-test.toml")).expect("test scene parses")
}

/// A scene with `objects` (TOML), the camera at `eye` looking at `target`,
/// SSAO with `samples` and r = 0.5, on the deferred path.
fn scene(eye: [f32; 3], target: [f32; 3], size: (u32, u32), samples: u32, objects: &str) -> Scene {
    parse(&format!(
        r#"
[camera]
eye = {eye:?}
target = {target:?}
fov_y = 50.0
near = 0.1
far = 60.0

[render]
path = "deferred"
size = [{}, {}]
ambient = [0.5, 0.5, 0.5]

[ambient_occlusion]
samples = {samples}
radius = 0.5
bias = 0.01

[[lights]]
type = "directional"
direction = [-0.3, -1.0, -0.4]
intensity = 0.5

[materials.grey]
diffuse = [0.7, 0.7, 0.7]
specular = [0.0, 0.0, 0.0]
{objects}
"#,
        size.0, size.1
    ))
}

const PLANE: &str = r#"
[[objects]]
mesh = "plane"
material = "grey"
scale = [60.0, 1.0, 60.0]
"#;

/// The floor (z from 0 to 10) and a wall in z = 0 facing +z (y from 0 to 10).
const CORNER: &str = r#"
[[objects]]
name = "floor"
mesh = "plane"
material = "grey"
position = [0.0, 0.0, 5.0]
scale = [10.0, 1.0, 5.0]

[[objects]]
name = "wall"
mesh = "plane"
material = "grey"
position = [0.0, 5.0, 0.0]
rotation = [90.0, 0.0, 0.0]
scale = [10.0, 1.0, 5.0]
"#;

fn ao_frame(s: &Scene) -> AoFrame {
    let ctx = common::context(common::backend());
    render_ao(&ctx, s).unwrap_or_else(|e| panic!("rendering the AO: {e:#}"))
}

/// Write `values` (rows bottom-up, None: background) as a grey PNG.
fn save(name: &str, f: &AoFrame, values: &[Option<f32>]) -> String {
    let (w, h) = (f.width as u32, f.height as u32);
    let img = image::RgbaImage::from_fn(w, h, |x, y| {
        let v = values[((h - 1 - y) * w + x) as usize];
        match v {
            Some(v) => {
                let g = (v.clamp(0.0, 1.0) * 255.0).round() as u8;
                image::Rgba([g, g, g, 255])
            }
            None => image::Rgba([60, 0, 60, 255]),
        }
    });
    let path = common::out_dir().join(format!("{name}.png"));
    img.save(&path).unwrap();
    path.display().to_string()
}

fn surface_ao(f: &AoFrame) -> Vec<Option<f32>> {
    (f.ao.iter().zip(&f.depth))
        .map(|(&a, &d)| (d < 1.0).then_some(a))
        .collect()
}

#[test]
fn an_open_plane_is_unoccluded_exactly_and_the_ambient_term_is_added_once() {
    // From above down to the horizon: grazing angles included.
    for samples in [4, 16, 64] {
        for blur in [true, false] {
            let mut s = scene(
                [0.0, 1.5, 6.0],
                [0.0, 0.0, -20.0],
                (160, 90),
                samples,
                PLANE,
            );
            if let Some(ao) = &mut s.render.ambient_occlusion {
                ao.blur = blur;
            }
            let f = ao_frame(&s);
            let surface = surface_ao(&f);
            let pixels = surface.iter().flatten().count();
            assert!(
                pixels > 160 * 40,
                "the plane fills the lower half: {pixels}"
            );
            let below = surface.iter().flatten().filter(|&&a| a != 1.0).count();
            if below > 0 {
                let path = save("ambient-light-plane.actual", &f, &surface);
                panic!(
                    "{samples} samples, blur {blur}: {below} of {pixels} pixels of an open plane have AO < 1 (AO image: {path})"
                );
            }
        }
    }
    // AO = 1: each G-buffer path draws what it draws without SSAO, bit for bit.
    let ctx = common::context(common::backend());
    let with = scene([0.0, 1.5, 6.0], [0.0, 0.0, -20.0], (160, 90), 16, PLANE);
    let mut without = with.clone();
    without.render.ambient_occlusion = None;
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Tiled,
        RenderPath::Prepass,
    ] {
        let a = common::render_with(&ctx, &with_path(&with, path), Output::Srgb8);
        let b = common::render_with(&ctx, &with_path(&without, path), Output::Srgb8);
        assert!(
            a.image.as_raw() == b.image.as_raw(),
            "{path:?}: AO = 1 everywhere, yet the image differs from the one without SSAO"
        );
    }
}

/// The corner's analytic AO at each surface pixel of `f` (None: background):
/// d is the distance to the other plane (the floor's z, the wall's y).
fn corner_analytic(f: &AoFrame, ao: &AmbientOcclusion) -> Vec<Option<f32>> {
    (0..f.depth.len())
        .map(|i| {
            let d = f.depth[i];
            (d < 1.0).then(|| {
                let (x, y) = (i % f.width, i / f.width);
                let p = pixel_world_point(x, y, d, f.inverse_view_projection, f.width, f.height);
                let n = f.normals[i];
                let dist = if n.dot(Vec3::Y) > 0.9 { p.z } else { p.y };
                corner(dist + ao.bias, ao.radius)
            })
        })
        .collect()
}

/// `values` averaged over the 4x4 pixels the blur pass averages (from -2
/// to +1 each way, the surface pixels among them): at the corner the blur
/// averages across the seam, where AO(d) has its V-shaped minimum, and
/// lifts it by a few hundredths; the analytic AO blurred alike shows that.
/// (Every neighbour there is within r/4 of the pixel's plane: the pass's
/// depth test keeps them all.)
fn blurred(f: &AoFrame, values: &[Option<f32>]) -> Vec<Option<f32>> {
    let (w, h) = (f.width as i64, f.height as i64);
    (0..values.len())
        .map(|i| {
            values[i]?;
            let (x, y) = ((i % f.width) as i64, (i / f.width) as i64);
            let mut window = Vec::new();
            for dy in -2..2 {
                for dx in -2..2 {
                    let (u, v) = (x + dx, y + dy);
                    if (0..w).contains(&u) && (0..h).contains(&v) {
                        window.extend(values[(v * w + u) as usize]);
                    }
                }
            }
            Some(window.iter().sum::<f32>() / window.len() as f32)
        })
        .collect()
}

/// Whether the r-neighbourhood of pixel (x, y)'s point lies on the screen
/// (its points r along each axis project into the image): what lies beyond
/// the border SSAO cannot see, and the border has its own test.
fn on_screen(f: &AoFrame, x: usize, y: usize, r: f32) -> bool {
    let i = y * f.width + x;
    let p = pixel_world_point(
        x,
        y,
        f.depth[i],
        f.inverse_view_projection,
        f.width,
        f.height,
    );
    let vp = f.inverse_view_projection.inverse();
    [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z]
        .iter()
        .all(|&e| {
            let c = vp * (p + r * e).extend(1.0);
            c.w > 0.0 && c.x.abs() <= c.w && c.y.abs() <= c.w
        })
}

#[test]
fn a_corner_matches_the_analytic_ao() {
    let s = scene([0.3, 1.0, 2.2], [0.0, 0.25, 0.0], (192, 108), 64, CORNER);
    let ao = s.render.ambient_occlusion.unwrap();
    let f = ao_frame(&s);
    let expected = blurred(&f, &corner_analytic(&f, &ao));
    let (mut worst, mut sum, mut n, mut dark) = (0.0f32, 0.0f64, 0, 0);
    for (i, &e) in expected.iter().enumerate() {
        let (x, y) = (i % f.width, i / f.width);
        if let (Some(e), true) = (e, on_screen(&f, x, y, ao.radius)) {
            let err = (f.ao[i] - e).abs();
            worst = worst.max(err);
            sum += f64::from(err);
            n += 1;
            dark += usize::from(e < 0.99);
        }
    }
    let mean = sum / n as f64;
    eprintln!("corner: {n} pixels ({dark} occluded), mean |error| {mean:.4}, max {worst:.4}");
    assert!(dark > n / 10, "the corner fills the view: {dark} of {n}");
    if worst > CORNER_MAX_ERROR || mean > CORNER_MEAN_ERROR {
        let a = save("ambient-light-corner.actual", &f, &surface_ao(&f));
        let b = save("ambient-light-corner.expected", &f, &expected);
        panic!(
            "corner: max |AO - analytic| {worst:.4} (bound {CORNER_MAX_ERROR}), mean {mean:.4} (bound {CORNER_MEAN_ERROR}): {a}, {b}"
        );
    }
}

#[test]
fn the_image_border_is_no_darker_than_the_reference() {
    // The corner cut by every edge of the image: occluders beyond the
    // border are unknown to SSAO, which may only make it lighter there.
    let s = scene([0.6, 0.45, 0.9], [0.2, 0.2, 0.0], (160, 90), 16, CORNER);
    let ao = s.render.ambient_occlusion.unwrap();
    let f = ao_frame(&s);
    let expected = corner_analytic(&f, &ao);
    let (mut darkest, mut n) = (0.0f32, 0);
    for (i, &e) in expected.iter().enumerate() {
        let (x, y) = (i % f.width, i / f.width);
        let band = x < BORDER || y < BORDER || x + BORDER >= f.width || y + BORDER >= f.height;
        if let (Some(e), true) = (e, band) {
            darkest = darkest.max(e - f.ao[i]);
            n += 1;
        }
    }
    eprintln!("border: {n} pixels, at most {darkest:.4} darker than the analytic AO");
    assert!(n > 400, "{n}");
    if darkest > BORDER_DARKER {
        let a = save("ambient-light-border.actual", &f, &surface_ao(&f));
        let b = save("ambient-light-border.expected", &f, &expected);
        panic!("border: {darkest:.4} darker than the reference (bound {BORDER_DARKER}): {a}, {b}");
    }
}

#[test]
fn an_object_far_in_front_leaves_no_halo_on_the_background() {
    // A wall in z = -3 facing the camera, a ball of radius 0.5 at z = -0.25:
    // 2.25 = 4.5 r in front of the wall, so nothing lies within r of the
    // wall and its true AO is 1 up to the ball's silhouette.
    let objects = r#"
[[objects]]
name = "wall"
mesh = "plane"
material = "grey"
position = [0.0, 0.0, -3.0]
rotation = [90.0, 0.0, 0.0]
scale = [20.0, 1.0, 20.0]

[[objects]]
name = "ball"
mesh = "sphere"
material = "grey"
position = [0.0, 0.0, -0.25]
scale = [0.5, 0.5, 0.5]
"#;
    let s = scene([0.0, 0.0, 3.0], [0.0, 0.0, -3.0], (160, 120), 16, objects);
    let f = ao_frame(&s);
    let wall = |i: usize| {
        let (x, y) = (i % f.width, i / f.width);
        let p = pixel_world_point(
            x,
            y,
            f.depth[i],
            f.inverse_view_projection,
            f.width,
            f.height,
        );
        f.depth[i] < 1.0 && p.z < -2.9
    };
    let walls = (0..f.ao.len()).filter(|&i| wall(i)).count();
    let ball = (0..f.ao.len())
        .filter(|&i| f.depth[i] < 1.0 && !wall(i))
        .count();
    let halo: Vec<usize> = (0..f.ao.len())
        .filter(|&i| wall(i) && f.ao[i] != 1.0)
        .collect();
    eprintln!(
        "halo: {walls} wall pixels, {ball} ball pixels, {} wall pixels below 1",
        halo.len()
    );
    assert!(ball > 500 && walls > 10_000, "{ball} {walls}");
    if !halo.is_empty() {
        let path = save("ambient-light-halo.actual", &f, &surface_ao(&f));
        panic!(
            "{} wall pixels darkened by a ball 4.5 r in front (halo width bound: 0): {path}",
            halo.len()
        );
    }
}

#[test]
fn the_shipped_scene_matches_the_ray_traced_reference_and_improves_with_samples() {
    let mut base = common::scene("ambient-occlusion.toml");
    base.render.size = (192, 108);
    let ao = base.render.ambient_occlusion.unwrap();
    let ctx = common::context(common::backend());
    let mut reference = None;
    let mut errors = Vec::new();
    for (samples, blur) in [(4, true), (16, true), (64, true), (4, false), (64, false)] {
        let mut s = base.clone();
        s.render.ambient_occlusion = Some(AmbientOcclusion {
            samples,
            blur,
            ..ao
        });
        let f = render_ao(&ctx, &s).unwrap();
        let r = reference.get_or_insert_with(|| f.reference(&s, ao.radius, 256).unwrap());
        let e = error(&f.ao, r);
        eprintln!(
            "{samples} samples, blur {blur}: mean |error| {:.4}, p95 {:.4} over {} pixels",
            e.mean, e.p95, e.pixels
        );
        if samples == 16 && blur && (e.mean > SCENE_MEAN_ERROR || e.p95 > SCENE_P95_ERROR) {
            let a = save("ambient-light-scene.actual", &f, &surface_ao(&f));
            let b = save("ambient-light-scene.reference", &f, r);
            panic!(
                "16 samples: mean {:.4} (bound {SCENE_MEAN_ERROR}), p95 {:.4} (bound {SCENE_P95_ERROR}): {a}, {b}",
                e.mean, e.p95
            );
        }
        errors.push(e.mean);
    }
    assert!(
        errors[0] > errors[1] && errors[1] > errors[2],
        "blurred, the mean error falls with the sample count (4, 16, 64): {errors:?}"
    );
    assert!(
        errors[3] > 1.5 * errors[4],
        "unblurred, 4 samples are noisier than 64: {errors:?}"
    );
}

#[test]
fn the_ssao_passes_restore_the_gl_state_on_every_g_buffer_path() {
    // With GL debug output on, a pass that sampled a texture of the
    // framebuffer it draws into would fail here too (src/gl/debug.rs).
    let ctx = common::context(common::backend());
    let base = common::scene("ambient-occlusion.toml");
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Tiled,
        RenderPath::Prepass,
    ] {
        let changed = common::state_left_changed(&ctx, &with_path(&base, path), 96, 54);
        assert!(changed.is_empty(), "{path:?}:\n  {}", changed.join("\n  "));
    }
}
