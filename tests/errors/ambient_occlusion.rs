//! `[ambient_occlusion]` (src/scene/ambient_occlusion.rs): unknown keys,
//! out-of-range counts, NaN, negative and too large distances are errors
//! naming the key and what it takes; on the forward path the table is a
//! warning (SSAO needs a G-buffer).

use crate::scene::scene_fails;
use crate::{BASE, temp_dir, write};
use gloss::scene::{RenderPath, Scene};

fn with_ao(table: &str) -> String {
    format!("{BASE}\n[ambient_occlusion]\n{table}\n")
}

#[test]
fn ambient_occlusion_unknown_key() {
    scene_fails(
        "ambient_occlusion_unknown_key",
        &with_ao("radius = 0.5\nsamples_per_pixel = 8"),
        &["samples_per_pixel", "samples", "radius", "bias", "blur"],
    );
}

#[test]
fn ambient_occlusion_bad_values() {
    for (table, words, test) in [
        (
            "samples = 0",
            &["ambient_occlusion.samples", "1..=64", "found 0"][..],
            "ao_samples_zero",
        ),
        (
            "samples = 65",
            &["ambient_occlusion.samples", "1..=64", "found 65"],
            "ao_samples_many",
        ),
        (
            "radius = nan",
            &["ambient_occlusion.radius", "distance > 0", "NaN"],
            "ao_radius_nan",
        ),
        (
            "radius = -0.5",
            &["ambient_occlusion.radius", "distance > 0", "-0.5"],
            "ao_radius_negative",
        ),
        (
            "radius = 0.0",
            &["ambient_occlusion.radius", "distance > 0", "found 0"],
            "ao_radius_zero",
        ),
        (
            "bias = -0.01",
            &["ambient_occlusion.bias", "0..radius", "-0.01"],
            "ao_bias_negative",
        ),
        (
            "bias = nan",
            &["ambient_occlusion.bias", "0..radius", "NaN"],
            "ao_bias_nan",
        ),
        (
            "radius = 0.5\nbias = 0.5",
            &["ambient_occlusion.bias", "0..radius (0.5)", "found 0.5"],
            "ao_bias_radius",
        ),
        (
            "samples = -3",
            &["samples = -3", "expected u32"],
            "ao_samples_negative",
        ),
    ] {
        scene_fails(test, &with_ao(table), words);
    }
}

#[test]
fn ambient_occlusion_on_the_forward_path_is_a_warning() {
    let path = write(
        &temp_dir("ao_forward_warning"),
        "scene.toml",
        with_ao("radius = 0.5"),
    );
    let mut scene = Scene::load(&path).unwrap();
    let w = scene.warnings();
    assert!(
        w.iter()
            .any(|l| l.starts_with("ambient_occlusion has no effect on the forward path")),
        "{w:?}"
    );
    scene.render.path = RenderPath::Deferred;
    assert!(
        scene
            .warnings()
            .iter()
            .all(|l| !l.contains("ambient_occlusion"))
    );
}
