//! src/techniques/deferred/tiled_shading.rs: the binning decides what a
//! pixel costs, never what it shows. Tiled shading tests each listed light
//! against its radius as the light-volume shader does, so its image equals
//! the light volumes' at the same cutoff (both summed in RGBA32F: within
//! 1/255 everywhere), for every tile size and slice count; with a cutoff far
//! below an 8-bit step it equals forward within the deferred bound. A light
//! the binning wrongly left out of a cluster shows as a hole of up to its
//! whole contribution, far beyond these bounds.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use glam::Vec3;
use gloss::image_compare::{Tolerance, compare_f32};
use gloss::renderer::Output;
use gloss::scene::{Accumulation, Light, LightKind, RenderPath, Scene};

/// Within 1/255 at every pixel (8-bit sRGB output).
const SAME_SUM: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.0,
    max_abs: Some(1.0 / 255.0),
};

fn tiled(scene: &Scene, tile: u32, slices: u32) -> Scene {
    let mut s = with_path(scene, RenderPath::Tiled);
    s.render.tile_size = tile;
    s.render.depth_slices = slices;
    s.render.accumulation = Accumulation::Rgba32f;
    s
}

/// Tiled (several grids) against light volumes, both in RGBA32F.
fn tiled_matches_volumes(label: &str, base: &Scene, grids: &[(u32, u32)]) {
    let mut vol = with_path(base, RenderPath::Volumes);
    vol.render.accumulation = Accumulation::Rgba32f;
    let volumes = common::render(&vol, Output::Srgb8);
    for &(tile, slices) in grids {
        let t = common::render(&tiled(base, tile, slices), Output::Srgb8);
        let m = common::assert_close(
            &format!("tiled-vs-volumes-{label}-{tile}px-{slices}"),
            &t.image,
            &volumes.image,
            &SAME_SUM,
        );
        eprintln!("{label}: tiled {tile} px x {slices} slices vs volumes: {m}");
    }
}

#[test]
fn tiled_shading_matches_light_volumes_for_every_grid() {
    let grids = [(16, 16), (16, 1), (7, 3), (64, 64)];
    for name in [
        "tiled-shading.toml",
        "many-lights.toml",
        "mixed-lights.toml",
        "default.toml",
    ] {
        let mut base = common::scene(name);
        base.render.size = (240, 136);
        tiled_matches_volumes(&base.name.clone(), &base, &grids);
    }
}

#[test]
fn tiled_shading_with_a_tiny_cutoff_matches_forward() {
    for name in ["mixed-lights.toml", "many-lights.toml"] {
        let mut base = common::scene(name);
        base.render.size = (240, 136);
        base.render.cutoff = 1e-5;
        let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
        let t = common::render(&tiled(&base, 16, 16), Output::Srgb8);
        let m = common::assert_close(
            &format!("tiled-tiny-cutoff-vs-forward-{}", base.name),
            &t.image,
            &fwd.image,
            &DEFERRED_BOUND,
        );
        eprintln!("{name}: tiled, cutoff 1e-5, vs forward: {m}");
    }
}

fn point(position: Vec3, color: Vec3, k: [f32; 3]) -> Light {
    Light {
        range: None,
        kind: LightKind::Point,
        position,
        direction: Vec3::NEG_Y,
        color,
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
fn tiled_hard_cases() {
    // default.toml's camera looks at the origin: at 256 x 192 the origin
    // lands on pixel (128, 96), a corner of four 16-pixel tiles and of
    // four 32-pixel ones.
    let mut base = common::scene("default.toml");
    base.render.size = (256, 192);
    let grids = [(16, 16), (32, 1), (5, 7)];

    // No light: no lighting pass, the ambient term alone, as forward.
    let mut none = base.clone();
    none.lights.clear();
    let plan = gloss::techniques::plan(&tiled(&none, 16, 16));
    assert!(!plan.passes.iter().any(|p| p.name == "lighting"), "{plan}");
    let t = common::render(&tiled(&none, 16, 16), Output::Srgb8);
    let f = common::render(&with_path(&none, RenderPath::Forward), Output::Srgb8);
    common::assert_close("tiled-no-lights", &t.image, &f.image, &DEFERRED_BOUND);

    // One light, on the tile corner, a hand's breadth above the floor; and
    // one exactly on a surface (distance 0: the sphere light of radius 0.01).
    for (label, y) in [("above", 0.3), ("on-surface", 0.0)] {
        let mut one = base.clone();
        one.lights = vec![point(Vec3::new(0.0, y, 0.0), Vec3::ONE, [1.0, 0.7, 1.8])];
        tiled_matches_volumes(&format!("one-light-{label}"), &one, &grids);
    }

    // Kq = 0 (the radius from Kl alone) and Kl = Kq = 0 (no finite radius:
    // the global list, every pixel) beside ordinary lights.
    let mut odd = base.clone();
    odd.lights = vec![
        point(
            Vec3::new(-1.5, 0.5, 0.5),
            Vec3::new(1.0, 0.3, 0.2),
            [1.0, 2.0, 0.0],
        ),
        point(
            Vec3::new(1.5, 0.5, 0.5),
            Vec3::new(0.2, 0.3, 1.0),
            [4.0, 0.0, 0.0],
        ),
        point(
            Vec3::new(0.0, 0.4, 1.5),
            Vec3::new(0.3, 1.0, 0.3),
            [1.0, 0.7, 1.8],
        ),
    ];
    let lights = gloss::frame::lights::FrameLights::new(&odd);
    assert_eq!(
        lights
            .lights
            .iter()
            .map(|l| l.radius.is_some())
            .collect::<Vec<_>>(),
        [true, false, true]
    );
    tiled_matches_volumes("kq0-and-unbounded", &odd, &grids);

    // The camera inside many volumes at once: the eye among many-lights'
    // lights, near the floor.
    let mut inside = common::scene("many-lights.toml");
    inside.render.size = (240, 136);
    inside.camera.eye = Vec3::new(0.3, 0.7, 2.0);
    inside.camera.target = Vec3::new(0.0, 0.5, -4.0);
    let around = inside
        .lights
        .iter()
        .filter(|l| {
            let r = gloss::frame::lights::radius(l, inside.render.cutoff).unwrap();
            l.position.distance(inside.camera.eye) < r
        })
        .count();
    assert!(around >= 5, "the eye is inside {around} volumes");
    tiled_matches_volumes("camera-inside-volumes", &inside, &grids);
}

/// 10,000 lights: more than any uniform block holds, so only the tiled path
/// draws them (from buffer textures). Light adds up, so the reference is
/// the sum of light-volume renders of 1,000 lights each, in linear light
/// with no ambient term.
#[test]
fn ten_thousand_lights_equal_the_sum_of_their_parts() {
    let mut base = common::scene("many-lights.toml");
    base.render.size = (160, 90);
    base.render.ambient = Vec3::ZERO;
    base.set_light_count(10_000).expect("a light grid");
    assert_eq!(base.lights.len(), 10_000);
    // Forward cannot hold them: the renderer says why.
    let fwd = with_path(&base, RenderPath::Forward);
    let ctx = common::context(common::backend());
    let err = gloss::renderer::render_scene(&ctx, &fwd, Output::Linear32F)
        .err()
        .expect("10,000 lights do not fit in a uniform block");
    assert!(
        format!("{err:#}").contains("fit in the lights uniform block"),
        "{err:#}"
    );

    let all = common::render_with(&ctx, &tiled(&base, 16, 16), Output::Linear32F);
    let mut sum = vec![0f32; all.linear.len()];
    for chunk in base.lights.chunks(1000) {
        let mut part = with_path(&base, RenderPath::Volumes);
        part.render.accumulation = Accumulation::Rgba32f;
        part.lights = chunk.to_vec();
        let r = common::render_with(&ctx, &part, Output::Linear32F);
        for (s, v) in sum.iter_mut().zip(&r.linear) {
            *s += v;
        }
    }
    let m = compare_f32(&all.linear, &sum, 4, 1.0 / 255.0);
    eprintln!("10,000 lights, tiled vs the sum of ten volume renders (linear): {m}");
    let brightest = sum.iter().cloned().fold(0.0, f32::max);
    assert!(brightest > 0.5, "the lights light the scene ({brightest})");
    // f32 sums in another order: a relative 1e-4 of the brightest pixel.
    if m.max_abs > 1e-4 * brightest as f64 + 1e-6 {
        for (name, v) in [("tiled", &all.linear), ("sum-of-parts", &sum)] {
            let path = common::out_dir().join(format!("ten-thousand-lights-{name}.png"));
            srgb_image(v, all.width, all.height)
                .save(&path)
                .expect("write");
            eprintln!("wrote {}", path.display());
        }
    }
    assert!(
        m.max_abs <= 1e-4 * brightest as f64 + 1e-6,
        "10,000 lights on the tiled path differ from the sum of their parts by {} (brightest {brightest})",
        m.max_abs
    );
}

/// Linear RGBA (bottom row first) as an 8-bit sRGB picture, for a failure.
fn srgb_image(linear: &[f32], w: u32, h: u32) -> image::RgbaImage {
    image::RgbaImage::from_fn(w, h, |x, y| {
        let i = (((h - 1 - y) * w + x) * 4) as usize;
        let c = |v: f32| (gloss::lighting::srgb_encode(v.clamp(0.0, 1.0)) * 255.0).round() as u8;
        image::Rgba([c(linear[i]), c(linear[i + 1]), c(linear[i + 2]), 255])
    })
}
