//! src/techniques/deferred/deferred_lighting.rs: the light pre-pass gives the
//! forward image within DEFERRED_BOUND, plus depth ties.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::RenderPath;

#[test]
fn prepass_matches_forward_on_shipped_scenes() {
    let ties = Tolerance {
        threshold: 8.0 / 255.0,
        max_frac_over: 0.0002,
        max_abs: None,
    };
    for name in [
        "default.toml",
        "plane.toml",
        "mixed-lights.toml",
        "inside-volume.toml",
    ] {
        let mut base = common::scene(name);
        // Compare with no cutoff, so the only difference is precision.
        base.render.cutoff = 1e-6;
        let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
        let pre = common::render(&with_path(&base, RenderPath::Prepass), Output::Srgb8);
        let label = format!("prepass-vs-forward-{}", base.name);
        let loose = Tolerance {
            max_abs: None,
            ..DEFERRED_BOUND
        };
        let m = common::assert_close(&label, &pre.image, &fwd.image, &loose);
        common::assert_close(&label, &pre.image, &fwd.image, &ties);
        eprintln!("{name}: prepass vs forward: {m}");
    }
}
