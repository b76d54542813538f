//! The shipped model scenes on every render path: forward is the reference,
//! the deferred paths agree within the bound the deferred tests use.

use crate::common;
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::RenderPath;

/// tests/deferred's DEFERRED_BOUND: 8-bit rounding, and at most 0.5 % of
/// the pixels up to 6/255 off (the G-buffer's 8-bit albedo and specular).
const DEFERRED_BOUND: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.005,
    max_abs: Some(6.0 / 255.0),
};

#[test]
fn the_model_scenes_agree_on_every_path() {
    let ctx = common::context(common::backend());
    for name in ["model-loading.toml", "atrium.toml"] {
        let mut s = common::scene(name);
        // Small, so that every path runs in the suite's time.
        s.render.size = (320, 180);
        // As tests/deferred compares many lights: the sum in f32 (in RGBA16F
        // each of 128 additions rounds to 11 bits), and a cutoff so small
        // that no light volume or tile list drops a light forward keeps
        // (src/lighting/attenuation.rs: the error is at most the cutoff).
        s.render.accumulation = gloss::scene::Accumulation::Rgba32f;
        s.render.cutoff = 1.0 / 4096.0;
        s.render.path = RenderPath::Forward;
        let forward = common::render_with(&ctx, &s, Output::Srgb8);
        for path in RenderPath::ALL
            .iter()
            .filter(|p| **p != RenderPath::Forward)
        {
            let mut p = s.clone();
            p.render.path = *path;
            let r = common::render_with(&ctx, &p, Output::Srgb8);
            let label = format!("{name}-{path}-vs-forward");
            let m = if *path == RenderPath::Prepass {
                // tests/deferred/deferred_lighting.rs's bound: the light
                // pre-pass's combine pass meets the G-buffer's depth with
                // GL_EQUAL, and where two surfaces tie (a capital on its
                // column) a few pixels take the other: no max_abs, and at most
                // 0.02 % of the pixels more than 8/255 off.
                let ties = Tolerance {
                    threshold: 8.0 / 255.0,
                    max_frac_over: 0.0002,
                    max_abs: None,
                };
                common::assert_close(&label, &r.image, &forward.image, &ties);
                let loose = Tolerance {
                    max_abs: None,
                    ..DEFERRED_BOUND
                };
                common::assert_close(&label, &r.image, &forward.image, &loose)
            } else {
                common::assert_close(&label, &r.image, &forward.image, &DEFERRED_BOUND)
            };
            eprintln!("{name}: {path} vs forward: {m}");
        }
    }
}
