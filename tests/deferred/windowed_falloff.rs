//! src/lighting/window.rs: with `render.falloff = "windowed"` every light's
//! attenuation reaches 0 at its cutoff radius, and with `"linear"` (notes
//! 01's 1 - d / Lmax) at Lmax, which is its volume's radius; so light
//! volumes and tiled shading drop nothing: they equal forward rendering
//! (the same model) within the deferred bound. With the notes' falloff the same comparison
//! fails by the dropped tails, which is what makes the test able to fail.

use crate::common;
use crate::{DEFERRED_BOUND, with_path};
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Output;
use gloss::scene::{Accumulation, Falloff, RenderPath};

#[test]
fn the_volume_paths_are_exact_for_the_windowed_falloff() {
    for name in [
        "many-lights.toml",
        "mixed-lights.toml",
        "windowed-falloff.toml",
    ] {
        let mut base = common::scene(name);
        base.render.size = (240, 136);
        base.render.accumulation = Accumulation::Rgba32f;
        for falloff in [Falloff::Windowed, Falloff::Linear, Falloff::Notes] {
            base.render.falloff = falloff;
            let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
            for path in [RenderPath::Volumes, RenderPath::Tiled] {
                let img = common::render(&with_path(&base, path), Output::Srgb8);
                let label = format!("windowed-{}-{path:?}-{falloff:?}", base.name);
                if falloff != Falloff::Notes {
                    let m = common::assert_close(&label, &img.image, &fwd.image, &DEFERRED_BOUND);
                    eprintln!("{label}: vs forward {m}");
                } else if name == "many-lights.toml" {
                    let m = compare_rgba8(&img.image, &fwd.image, 1.0 / 255.0).unwrap();
                    assert!(
                        m.max_abs > 40.0 / 255.0,
                        "{label}: the cutoff drops the tails: {m}"
                    );
                }
            }
        }
    }
}
