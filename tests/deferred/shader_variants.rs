//! src/frame/variant.rs with src/techniques/deferred/deferred_shading.rs:
//! the lighting shaders specialised to the frame.
//!
//! * each variant gives the general shader's image within 1/255, for both
//!   forms of the deferred pass, the forward pass and tiled shading, on scenes that hold every light type,
//!   shadows of each kind, the windowed and linear falloffs and microfacet
//!   materials; and the plan names the variant;
//! * a variant keeps every light type its scene holds: each of
//!   mixed-lights' light types alone gives forward's image, and lights the
//!   surface (a variant that dropped the type would give the ambient alone);
//! * the renderer builds a new variant when a settings or scene change
//!   changes it, and takes the old one back from its cache.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::frame::lights::FrameLights;
use gloss::frame::variant::LightingVariant;
use gloss::gl::program::Sources;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::renderer::{Output, Renderer, render_scene};
use gloss::scene::{DeferredLights, LightKind, RenderPath, Scene};

const WITHIN_1: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.0,
    max_abs: Some(1.0 / 255.0),
};

fn small_deferred(name: &str, form: DeferredLights) -> Scene {
    let mut s = with_path(&common::scene(name), RenderPath::Deferred);
    s.render.size = (192, 108);
    s.render.deferred_lights = form;
    s
}

fn variant(s: &Scene) -> LightingVariant {
    LightingVariant::of(s, &FrameLights::new(s))
}

#[test]
fn each_variant_gives_the_general_image_and_the_plan_names_it() {
    let ctx = common::context(common::backend());
    for name in [
        "mixed-lights.toml",
        "shadows-directional.toml",
        "shadows-point.toml",
        "shadows-spot.toml",
        "assignment-bunny.toml",
        "microfacet.toml",
        "windowed-falloff.toml",
        "linear-falloff.toml",
    ] {
        for (path, form) in [
            (RenderPath::Deferred, DeferredLights::SinglePass),
            (RenderPath::Deferred, DeferredLights::PerLight),
            (RenderPath::Forward, DeferredLights::PerLight),
            (RenderPath::Tiled, DeferredLights::PerLight),
        ] {
            let special = with_path(&small_deferred(name, form), path);
            let pass_name = if path == RenderPath::Forward {
                "forward"
            } else {
                "lighting"
            };
            let mut general = special.clone();
            general.render.specialize = false;
            let v = variant(&special);
            assert_ne!(v, LightingVariant::GENERAL, "{name}: nothing left out");
            assert_eq!(variant(&general), LightingVariant::GENERAL);
            for (s, words) in [
                (&special, v.describe()),
                (&general, LightingVariant::GENERAL.describe()),
            ] {
                let plan = gloss::techniques::plan(s);
                let pass = (plan.passes.iter())
                    .find(|p| p.name == pass_name)
                    .unwrap_or_else(|| panic!("{name}: no lighting pass\n{plan}"));
                assert_eq!(pass.variant.as_deref(), Some(words.as_str()), "{plan}");
                assert!(plan.to_string().contains(&words), "{plan}");
            }
            let a = render_scene(&ctx, &special, Output::Srgb8).expect("specialised");
            let b = render_scene(&ctx, &general, Output::Srgb8).expect("general");
            assert_eq!(a.variant(), v);
            let m = common::assert_close(
                &format!("variant-vs-general-{}-{path:?}-{form:?}", special.name),
                &a.read_image(),
                &b.read_image(),
                &WITHIN_1,
            );
            eprintln!("{name} {path:?} {form:?} [{}]: {m}", v.describe());
        }
    }
}

#[test]
fn a_variant_keeps_every_light_type_its_scene_holds() {
    let base = small_deferred("mixed-lights.toml", DeferredLights::SinglePass);
    let v = variant(&base);
    assert!(v.directional && v.point && v.spot, "{v:?}");
    let ctx = common::context(common::backend());
    let mut unlit = base.clone();
    unlit.lights.clear();
    let ambient = render_scene(&ctx, &with_path(&unlit, RenderPath::Forward), Output::Srgb8)
        .expect("ambient")
        .read_image();
    for kind in [LightKind::Directional, LightKind::Point, LightKind::Spot] {
        let mut one = base.clone();
        one.lights.retain(|l| l.kind == kind);
        assert!(!one.lights.is_empty(), "mixed-lights has a {kind:?} light");
        let v = variant(&one);
        assert_eq!(
            (v.directional, v.point, v.spot),
            (
                kind == LightKind::Directional,
                kind == LightKind::Point,
                kind == LightKind::Spot
            )
        );
        let fwd = render_scene(&ctx, &with_path(&one, RenderPath::Forward), Output::Srgb8)
            .expect("forward")
            .read_image();
        let def = render_scene(&ctx, &one, Output::Srgb8)
            .expect("specialised deferred")
            .read_image();
        common::assert_close(
            &format!("variant-one-type-{kind:?}"),
            &def,
            &fwd,
            &DEFERRED_BOUND,
        );
        // The light reaches the surface: the image is not the ambient alone.
        let lit = compare_rgba8(&def, &ambient, 1.0 / 255.0).expect("same size");
        assert!(
            lit.max_abs > 20.0 / 255.0,
            "{kind:?} alone adds nothing: {lit}"
        );
    }
}

#[test]
fn a_settings_change_that_changes_the_variant_rebuilds_and_reuses_the_programs() {
    let ctx = common::context(common::backend());
    let scene = small_deferred("mixed-lights.toml", DeferredLights::SinglePass);
    let (w, h) = scene.render.size;
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        &scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Srgb8,
    )
    .expect("renderer");
    let special = variant(&scene);
    assert_eq!(r.variant(), special);
    r.render(&scene.camera).expect("frame");
    let first = r.read_image();

    let mut settings = scene.render.clone();
    settings.specialize = false;
    r.set_render_settings(settings).expect("general");
    assert_eq!(r.variant(), LightingVariant::GENERAL);
    r.render(&scene.camera).expect("frame");
    let general = r.read_image();
    common::assert_close("variant-switch-general", &general, &first, &WITHIN_1);

    // Without its spot lights the scene needs another variant.
    let mut no_spots = scene.clone();
    no_spots.lights.retain(|l| l.kind != LightKind::Spot);
    r.set_scene_values(&no_spots).expect("no spots");
    assert!(!r.variant().spot && r.variant().point, "{:?}", r.variant());
    r.render(&scene.camera).expect("frame");

    // And back: the first variant, its image.
    r.set_scene_values(&scene).expect("back");
    assert_eq!(r.variant(), special);
    r.render(&scene.camera).expect("frame");
    let m = compare_rgba8(&r.read_image(), &first, 0.0).expect("same size");
    assert_eq!(m.max_abs, 0.0, "{m}");
}
