//! src/techniques/deferred/deferred_shading.rs (with gbuffer.rs and composite.rs):
//! deferred shading gives the forward image within DEFERRED_BOUND.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::renderer::Output;
use gloss::scene::RenderPath;

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
