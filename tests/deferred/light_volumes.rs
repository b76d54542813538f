//! src/techniques/deferred/light_volumes.rs: volumes against full-screen
//! deferred within the cutoff bound; the camera inside a volume; spot cones;
//! lights with no finite radius.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::frame::lights::radius;
use gloss::image_compare::{Tolerance, compare_f32};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

/// Linear-light bound for volumes vs full screen: each bounded light may drop
/// at most `cutoff` x (kd + ks) per channel at a pixel beyond its radius.
fn cutoff_bound(scene: &Scene) -> f64 {
    let bounded = scene
        .lights
        .iter()
        .filter(|l| radius(l, scene.render.cutoff).is_some())
        .count();
    let kd = scene
        .materials
        .iter()
        .map(|m| m.diffuse.max_element())
        .fold(0.0, f32::max);
    let ks = scene
        .materials
        .iter()
        .map(|m| m.specular.max_element())
        .fold(0.0, f32::max);
    bounded as f64 * scene.render.cutoff as f64 * (kd + ks) as f64
}

pub fn volumes_vs_fullscreen(name: &str, stencil: bool) {
    let mut base = common::scene(name);
    base.render.stencil_volumes = stencil;
    let full = common::render(&with_path(&base, RenderPath::Deferred), Output::Linear32F);
    let vol = common::render(&with_path(&base, RenderPath::Volumes), Output::Linear32F);
    let m = compare_f32(&vol.linear, &full.linear, 4, 1.0 / 255.0);
    let bound = cutoff_bound(&base) + 2.0 / 255.0;
    eprintln!(
        "{name} (stencil {stencil}): volumes vs full screen (linear): {m}; bound {:.2}/255",
        bound * 255.0
    );
    assert!(
        m.max_abs <= bound,
        "{name}: light volumes differ from full-screen deferred by {:.2}/255 in linear light, more than the cutoff bound {:.2}/255",
        m.max_abs * 255.0,
        bound * 255.0
    );
    // With a cutoff far below one 8-bit step the volumes must cover every lit pixel.
    base.render.cutoff = 1e-5;
    let full = common::render(&with_path(&base, RenderPath::Deferred), Output::Srgb8);
    let vol = common::render(&with_path(&base, RenderPath::Volumes), Output::Srgb8);
    common::assert_close(
        &format!(
            "volumes-tiny-cutoff-{}{}",
            base.name,
            if stencil { "-stencil" } else { "" }
        ),
        &vol.image,
        &full.image,
        &Tolerance {
            threshold: 1.0 / 255.0,
            max_frac_over: 0.001,
            max_abs: Some(2.0 / 255.0),
        },
    );
}

#[test]
fn light_volumes_match_fullscreen_within_cutoff_bound() {
    volumes_vs_fullscreen("mixed-lights.toml", false);
    volumes_vs_fullscreen("default.toml", false);
}

#[test]
fn camera_inside_a_light_volume() {
    let scene = common::scene("inside-volume.toml");
    let l = &scene.lights[0];
    let r = radius(l, scene.render.cutoff).unwrap();
    assert!(
        l.position.distance(scene.camera.eye) < r,
        "the scene must put the camera inside the first light's sphere"
    );
    volumes_vs_fullscreen("inside-volume.toml", false);
    // And the lit region did not disappear (notes 04): with only that light
    // and no ambient term, volumes light exactly the pixels full screen lights.
    let mut only = scene.clone();
    only.lights.truncate(1);
    only.render.ambient = glam::Vec3::ZERO;
    // Below one 8-bit step, so no lit pixel lies beyond the radius.
    only.render.cutoff = 1e-5;
    let count = |p: RenderPath| {
        let img = common::render(&with_path(&only, p), Output::Srgb8).image;
        img.pixels()
            .filter(|p| p.0[..3].iter().any(|&c| c > 0))
            .count()
    };
    let (vol, full) = (count(RenderPath::Volumes), count(RenderPath::Deferred));
    assert!(
        full > 100_000,
        "the light should light most of the view: {full}"
    );
    assert!(
        vol.abs_diff(full) <= full / 1000,
        "camera inside the volume: {vol} lit pixels with volumes, {full} full screen"
    );
}

#[test]
fn spot_cone_volumes_cover_the_lit_region() {
    // Only spot lights, wide and narrow, one grazing; the cutoff tiny so
    // every pixel the spot lights at all must be inside its cone volume.
    let mut scene = common::scene("mixed-lights.toml");
    scene
        .lights
        .retain(|l| l.kind == gloss::scene::LightKind::Spot);
    scene.render.ambient = glam::Vec3::ZERO;
    scene.render.cutoff = 1e-5;
    for outer in [12.0f32, 45.0, 80.0] {
        for l in &mut scene.lights {
            l.outer_angle = outer;
            l.inner_angle = outer * 0.5;
        }
        let full = common::render(&with_path(&scene, RenderPath::Deferred), Output::Srgb8);
        let vol = common::render(&with_path(&scene, RenderPath::Volumes), Output::Srgb8);
        let mut missing = 0;
        for (a, b) in vol.image.pixels().zip(full.image.pixels()) {
            let lit = b.0[..3].iter().any(|&c| c > 2);
            let dark = a.0[..3].iter().all(|&c| c == 0);
            if lit && dark {
                missing += 1;
            }
        }
        assert_eq!(
            missing, 0,
            "outer angle {outer}: {missing} pixels lit by a spot light fall outside its cone volume"
        );
        common::assert_close(
            &format!("spot-cones-{outer}"),
            &vol.image,
            &full.image,
            &Tolerance {
                threshold: 1.0 / 255.0,
                max_frac_over: 0.001,
                max_abs: Some(2.0 / 255.0),
            },
        );
    }
}

#[test]
fn kl_kq_zero_light_renders_full_screen_in_volumes() {
    let mut scene = common::scene("plane.toml");
    scene.lights[0].kl = 0.0;
    scene.lights[0].kq = 0.0;
    scene.lights[0].kc = 3.0;
    let fwd = common::render(&with_path(&scene, RenderPath::Forward), Output::Srgb8);
    let vol = common::render(&with_path(&scene, RenderPath::Volumes), Output::Srgb8);
    common::assert_close(
        "volumes-unbounded-light",
        &vol.image,
        &fwd.image,
        &DEFERRED_BOUND,
    );
}
