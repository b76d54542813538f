//! src/techniques/deferred/far_field.rs: each light split into a near part
//! (tiled shading's lists) and a far part (summed once per k x k pixels and
//! interpolated), which add up to the whole light. With k = 1 every sample
//! is the pixel itself: the image is forward rendering's within the deferred
//! bound, where tiled shading without the far field is off by the dropped
//! tails (asserted, so that the comparison can fail). With k = 4 and 8 the
//! interpolation stays within FAR_BOUND of forward, on the shipped scenes
//! and on the hard cases.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use glam::Vec3;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::renderer::Output;
use gloss::scene::{Accumulation, Light, LightKind, RenderPath, Scene};

/// The far field interpolated from one sample per k x k pixels (k <= 8)
/// against forward: at most 1% of pixels more than 2/255 off, none more
/// than 10/255 (8-bit sRGB; measured at most 0.5% and 8/255, many-lights
/// at k = 8 and 320x180). Tiled shading at the same cutoff without it is
/// off by up to 100/255 on many-lights.
const FAR_BOUND: Tolerance = Tolerance {
    threshold: 2.0 / 255.0,
    max_frac_over: 0.01,
    max_abs: Some(10.0 / 255.0),
};

pub(super) fn far(scene: &Scene, k: u32) -> Scene {
    let mut s = with_path(scene, RenderPath::Tiled);
    s.render.far_field = k;
    s.render.accumulation = Accumulation::Rgba32f;
    s
}

fn against_forward(label: &str, base: &Scene, ks: &[u32], tol: &Tolerance) {
    let fwd = common::render(&with_path(base, RenderPath::Forward), Output::Srgb8);
    for &k in ks {
        let t = common::render(&far(base, k), Output::Srgb8);
        let m = common::assert_close(
            &format!("far-field-{label}-k{k}-vs-forward"),
            &t.image,
            &fwd.image,
            tol,
        );
        eprintln!("{label}: far field k = {k} vs forward: {m}");
    }
}

#[test]
fn one_sample_per_pixel_is_forward_and_the_cutoff_alone_is_not() {
    for name in ["many-lights.toml", "mixed-lights.toml", "far-field.toml"] {
        let mut base = common::scene(name);
        base.render.size = (240, 136);
        base.render.cutoff = 5.0 / 256.0;
        against_forward(&base.name.clone(), &base, &[1], &DEFERRED_BOUND);
        if name == "many-lights.toml" {
            let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
            let cut = common::render(&far(&base, 0), Output::Srgb8);
            let m = compare_rgba8(&cut.image, &fwd.image, 1.0 / 255.0).unwrap();
            assert!(
                m.max_abs > 40.0 / 255.0,
                "without the far field the cutoff drops the tails: {m}"
            );
        }
    }
}

#[test]
fn interpolated_far_field_stays_near_forward() {
    for name in ["many-lights.toml", "far-field.toml", "logl-like.toml"] {
        let mut base = common::scene(name);
        base.render.size = (320, 180);
        against_forward(&base.name.clone(), &base, &[4, 8], &FAR_BOUND);
    }
}

pub(super) fn point(position: Vec3, k: [f32; 3]) -> Light {
    Light {
        range: None,
        kind: LightKind::Point,
        position,
        direction: Vec3::NEG_Y,
        color: Vec3::new(1.0, 0.8, 0.6),
        intensity: 1.0,
        kc: k[0],
        kl: k[1],
        kq: k[2],
        inner_angle: 0.0,
        outer_angle: 0.0,
        shadow: None,
    }
}

#[test]
fn far_field_hard_cases() {
    let mut base = common::scene("default.toml");
    base.render.size = (256, 192);
    base.render.cutoff = 5.0 / 256.0;
    let cases: Vec<(&str, Vec<Light>)> = vec![
        // On the surface (distance 0), and on a corner of four samples.
        ("on-surface", vec![point(Vec3::ZERO, [1.0, 0.7, 1.8])]),
        // Kq = 0: a long linear tail, most of it in the far part.
        (
            "kq-0",
            vec![point(Vec3::new(0.5, 0.4, 0.0), [1.0, 0.5, 0.0])],
        ),
        // Kl = Kq = 0: no radius, no far part; shaded whole everywhere.
        (
            "constant",
            vec![
                point(Vec3::new(0.0, 2.0, 0.0), [4.0, 0.0, 0.0]),
                point(Vec3::new(1.0, 0.5, 1.0), [1.0, 0.7, 1.8]),
            ],
        ),
        // Never brighter than the cutoff: radius 0, all of it far.
        (
            "radius-0",
            vec![point(Vec3::new(0.0, 1.0, 0.0), [60.0, 0.0, 0.0])],
        ),
        // The camera inside every light's volume.
        (
            "eye-inside",
            (0..6)
                .map(|i| {
                    point(
                        base.camera.eye + Vec3::new(i as f32 * 0.1, 0.0, 0.0),
                        [1.0, 0.09, 0.032],
                    )
                })
                .collect(),
        ),
    ];
    for (label, lights) in cases {
        let mut s = base.clone();
        s.lights = lights;
        against_forward(label, &s, &[1], &DEFERRED_BOUND);
        against_forward(label, &s, &[4], &FAR_BOUND);
    }
}

#[test]
fn the_plan_has_the_far_field_only_when_asked_on_the_tiled_path() {
    let mut base = common::scene("many-lights.toml");
    base.render.size = (1280, 720);
    let on = gloss::techniques::plan(&far(&base, 8));
    let text = on.to_string();
    assert!(on.has_pass("far field"), "{text}");
    assert!(
        text.contains("1 full-screen triangle at 160x90 (one sample per 8x8 pixels)"),
        "{text}"
    );
    assert!(text.contains("1/8 of the frame each way"), "{text}");
    let order: Vec<&str> = on.passes.iter().map(|p| p.name).collect();
    assert_eq!(order, ["gbuffer", "far field", "lighting", "composite"]);
    let off = gloss::techniques::plan(&far(&base, 0));
    assert!(!off.has_pass("far field"), "{off}");
    let mut fwd = far(&base, 8);
    fwd.render.path = RenderPath::Forward;
    assert!(!gloss::techniques::plan(&fwd).has_pass("far field"));
    // Only lights with no radius: nothing has a far part.
    let mut directional = far(&base, 8);
    for l in &mut directional.lights {
        l.kind = LightKind::Directional;
    }
    assert!(!gloss::techniques::plan(&directional).has_pass("far field"));
}

/// The bound holds pixel by pixel: the far field at k = 4 and 8 against
/// the exact far part (k = 1, the same G-buffer and sums in RGBA32F) is
/// within each pixel's bound, plus 1/255 for the two images' 8-bit
/// rounding. With k = 1 the bound is the stored values' rounding alone.
#[test]
fn every_pixel_is_within_its_bound() {
    let ctx = common::context(common::backend());
    for name in ["far-field.toml", "default.toml"] {
        let mut base = common::scene(name);
        base.render.size = (320, 180);
        let exact = common::render_with(&ctx, &far(&base, 1), Output::Srgb8).image;
        let b1 = gloss::bench::bound::far_field_pixels(&ctx, &far(&base, 1), &exact)
            .unwrap()
            .unwrap();
        let worst1 = b1.iter().copied().fold(0.0, f64::max);
        assert!(worst1 <= 1.0 / 255.0, "{name}: k = 1 bound {worst1}");
        for k in [4, 8] {
            let s = far(&base, k);
            let image = common::render_with(&ctx, &s, Output::Srgb8).image;
            let bound = gloss::bench::bound::far_field_pixels(&ctx, &s, &image)
                .unwrap()
                .unwrap();
            let (mut worst_ratio, mut outside) = (0.0f64, Vec::new());
            for (i, (a, e)) in image.pixels().zip(exact.pixels()).enumerate() {
                let d = (0..3)
                    .map(|c| (f64::from(a[c]) - f64::from(e[c])).abs() / 255.0)
                    .fold(0.0, f64::max);
                if d > bound[i] + 1.0 / 255.0 {
                    outside.push((i % 320, i / 320, d * 255.0, bound[i] * 255.0));
                }
                if d > 1.0 / 255.0 {
                    worst_ratio = worst_ratio.max(d / bound[i].max(1e-12));
                }
            }
            assert!(
                outside.is_empty(),
                "{name} k = {k}: {} pixels outside their bound (x, y, error, bound x255): {:?}",
                outside.len(),
                &outside[..outside.len().min(10)]
            );
            eprintln!(
                "{name} k = {k}: every pixel within its bound; largest error / bound {worst_ratio:.3}"
            );
        }
    }
}
