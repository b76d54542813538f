//! src/techniques/deferred/stencil_light_volumes.rs: the two-sided stencil
//! test gives the plain volumes' image.

use crate::common;
use crate::light_volumes::volumes_vs_fullscreen;
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Output;

#[test]
fn stencil_volume_test_gives_the_same_image() {
    volumes_vs_fullscreen("mixed-lights.toml", true);
    volumes_vs_fullscreen("inside-volume.toml", true);
    let mut a = common::scene("mixed-lights.toml");
    let plain = common::render(&a, Output::Srgb8);
    a.render.stencil_volumes = true;
    let stencil = common::render(&a, Output::Srgb8);
    let m = compare_rgba8(&stencil.image, &plain.image, 1.0 / 255.0).unwrap();
    assert!(
        m.max_abs <= 1.0 / 255.0,
        "stencil volumes vs plain volumes: {m}"
    );
}
