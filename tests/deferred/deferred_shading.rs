//! src/techniques/deferred/deferred_shading.rs (with gbuffer.rs and composite.rs):
//! deferred shading gives the forward image within DEFERRED_BOUND.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::{DeferredLights, RenderPath};

#[test]
fn deferred_matches_forward_on_shipped_scenes() {
    for name in [
        "default.toml",
        "plane.toml",
        "mixed-lights.toml",
        "inside-volume.toml",
    ] {
        let base = common::scene(name);
        let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
        let def = common::render(&with_path(&base, RenderPath::Deferred), Output::Srgb8);
        let m = common::assert_close(
            &format!("deferred-vs-forward-{}", base.name),
            &def.image,
            &fwd.image,
            &DEFERRED_BOUND,
        );
        eprintln!("{name}: deferred vs forward: {m}");
    }
}

#[test]
fn one_pass_over_all_lights_matches_forward_and_the_per_light_passes() {
    // Notes 01 §8.6.2's loop in the shader (render.deferred_lights =
    // "single_pass") against forward (the deferred bound) and against notes
    // 04's pass per light: the same sum, made in f32 instead of by blending,
    // so within 1/255 everywhere of the passes blended into RGBA32F. (Into
    // RGBA16F, each of many-lights' 256 additions rounds to 11 bits: up to
    // 4/255 off on a quarter of the pixels.)
    for name in ["default.toml", "mixed-lights.toml", "many-lights.toml"] {
        let mut base = with_path(&common::scene(name), RenderPath::Deferred);
        base.render.size = (160, 90);
        let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
        let mut f32_sum = base.clone();
        f32_sum.render.accumulation = gloss::scene::Accumulation::Rgba32f;
        let per_light = common::render(&f32_sum, Output::Srgb8);
        let mut single = base.clone();
        single.render.deferred_lights = DeferredLights::SinglePass;
        let p = gloss::techniques::plan(&single);
        let pass = p.passes.iter().find(|q| q.name == "lighting").unwrap();
        assert!(
            pass.draws
                .starts_with("1 full-screen triangle, its shader looping over"),
            "{p}"
        );
        let one = common::render(&single, Output::Srgb8);
        let m = common::assert_close(
            &format!("single-pass-vs-forward-{}", base.name),
            &one.image,
            &fwd.image,
            &DEFERRED_BOUND,
        );
        eprintln!("{name}: single pass vs forward: {m}");
        let m = common::assert_close(
            &format!("single-pass-vs-per-light-{}", base.name),
            &one.image,
            &per_light.image,
            &Tolerance {
                threshold: 1.0 / 255.0,
                max_frac_over: 0.0,
                max_abs: Some(1.0 / 255.0),
            },
        );
        eprintln!("{name}: single pass vs per light: {m}");
    }
}
