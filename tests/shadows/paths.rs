//! The same shadows in every path. Bound: against the forward image, no
//! channel of any pixel differs by more than 8/255 and at most 0.1% of
//! pixels by more than 3/255. The deferred paths light from the G-buffer's
//! RGBA16F normal and reconstructed position, the forward path from its
//! interpolated inputs: a half-float normal moves the normal-offset lookup
//! by a few thousandths of a texel, which flips a PCF tap at the edge of a
//! shadow now and then.

use crate::common;
use gloss::frame::plan::FramePlan;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::renderer::Output;
use gloss::scene::{CubeRender, Pcf, RenderPath, Scene};
use gloss::techniques;

const SCENES: [&str; 5] = [
    "shadows-directional.toml",
    "shadows-spot.toml",
    "shadows-point.toml",
    "shadows-grazing.toml",
    "shadows-contact.toml",
];

fn small(name: &str) -> Scene {
    let mut s = common::scene(name);
    s.render.size = (320, 180);
    s
}

fn with_path(scene: &Scene, path: RenderPath, stencil: bool) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    s.render.stencil_volumes = stencil;
    s
}

fn tolerance() -> Tolerance {
    Tolerance {
        threshold: 3.0 / 255.0,
        max_frac_over: 0.001,
        max_abs: Some(8.0 / 255.0),
    }
}

#[test]
fn every_path_gives_the_forward_image() {
    let ctx = common::context(common::backend());
    for name in SCENES {
        let base = small(name);
        let forward = common::render_with(
            &ctx,
            &with_path(&base, RenderPath::Forward, false),
            Output::Srgb8,
        );
        for (path, stencil) in [
            (RenderPath::Deferred, false),
            (RenderPath::Volumes, false),
            (RenderPath::Volumes, true),
            (RenderPath::Prepass, false),
        ] {
            let s = with_path(&base, path, stencil);
            let img = common::render_with(&ctx, &s, Output::Srgb8).image;
            let label = format!(
                "shadows-{}-{}{}",
                s.name,
                path.name(),
                if stencil { "-stencil" } else { "" }
            );
            common::assert_close(&label, &img, &forward.image, &tolerance());
        }
    }
}

#[test]
fn six_passes_and_one_geometry_shader_pass_store_the_same_cube() {
    let ctx = common::context(common::backend());
    for pcf in [Pcf::None, Pcf::Box3] {
        let mut six = small("shadows-point.toml");
        let shadow = six.lights[0].shadow.as_mut().unwrap();
        shadow.pcf = pcf;
        shadow.cube = CubeRender::SixPasses;
        let mut one = six.clone();
        one.lights[0].shadow.as_mut().unwrap().cube = CubeRender::GeometryShader;
        let a = common::render_with(&ctx, &six, Output::Srgb8).image;
        let b = common::render_with(&ctx, &one, Output::Srgb8).image;
        let m = compare_rgba8(&a, &b, 0.0).unwrap();
        assert_eq!(
            m.max_abs, 0.0,
            "{pcf:?}: the same depths, the same image: {m}"
        );
    }
}

#[test]
fn the_plan_has_one_shadow_pass_per_casting_light_and_none_without() {
    let shadow_passes = |s: &Scene| -> Vec<String> {
        FramePlan::new(
            s,
            &gloss::frame::lights::FrameLights::new(s),
            techniques::ALL,
        )
        .passes
        .iter()
        .filter(|p| p.name == "shadow map")
        .map(|p| p.draws.clone())
        .collect()
    };
    let s = common::scene("shadows-directional.toml");
    let passes = shadow_passes(&s);
    assert_eq!(passes.len(), 1);
    assert!(
        passes[0].contains("2048 x 2048 DEPTH_COMPONENT32F"),
        "{passes:?}"
    );
    let p = common::scene("shadows-point.toml");
    let passes = shadow_passes(&p);
    assert!(passes[0].contains("cube 6 x 1024 x 1024"), "{passes:?}");
    // The first passes of the frame, before the lighting.
    let plan = techniques::plan(&s);
    assert_eq!(plan.passes[0].name, "shadow map");
    // No casting light: no shadow pass.
    let mut off = s.clone();
    off.lights[0].shadow = None;
    assert!(shadow_passes(&off).is_empty());
    assert!(shadow_passes(&common::scene("many-lights.toml")).is_empty());
    // Two casting lights: two passes, each its own size.
    let mut two = s.clone();
    let mut second = two.lights[0].clone();
    second.shadow.as_mut().unwrap().resolution = 512;
    two.lights.push(second);
    let passes = shadow_passes(&two);
    assert_eq!(passes.len(), 2);
    assert!(passes[1].contains("512 x 512"), "{passes:?}");
}

#[test]
fn every_shadow_pass_restores_the_gl_state() {
    let ctx = common::context(common::backend());
    for name in SCENES {
        for path in RenderPath::ALL {
            let s = with_path(&small(name), *path, false);
            let changed = common::state_left_changed(&ctx, &s, 160, 90);
            assert!(changed.is_empty(), "{name} {path:?}: {changed:?}");
        }
    }
    let mut gs = small("shadows-point.toml");
    gs.lights[0].shadow.as_mut().unwrap().cube = CubeRender::GeometryShader;
    gs.lights[0].shadow.as_mut().unwrap().cull_front = true;
    let changed = common::state_left_changed(&ctx, &gs, 160, 90);
    assert!(changed.is_empty(), "{changed:?}");
}

#[test]
fn editing_a_bias_keeps_the_maps_and_a_new_resolution_makes_them_anew() {
    let ctx = common::context(common::backend());
    let mut s = small("shadows-point.toml");
    let mut r = crate::hard_cases::renderer(&ctx, &s);
    let texture = r.shadows().maps[0].1.texture;
    // A bias and a PCF kernel: the same texture, read with the new knobs.
    let shadow = s.lights[0].shadow.as_mut().unwrap();
    shadow.bias = 0.2;
    shadow.pcf = Pcf::Box3;
    r.set_scene_values(&s).unwrap();
    let (caster, map) = &r.shadows().maps[0];
    assert_eq!(map.texture, texture);
    assert_eq!((caster.shadow.bias, caster.shadow.pcf), (0.2, Pcf::Box3));
    r.render(&s.camera.clone()).unwrap();
    let mut fresh = small("shadows-point.toml");
    fresh.lights[0].shadow = s.lights[0].shadow;
    let expected = common::render_with(&ctx, &fresh, Output::Srgb8).image;
    let m = compare_rgba8(&r.read_image(), &expected, 0.0).unwrap();
    assert_eq!(m.max_abs, 0.0, "kept maps draw what new ones would: {m}");
    // A new resolution: a new map of that size.
    s.lights[0].shadow.as_mut().unwrap().resolution = 256;
    r.set_scene_values(&s).unwrap();
    assert_eq!(r.shadows().maps[0].1.size, 256);
}
