//! Golden images: every scene in scenes/ rendered headless (EGL, GL debug
//! output on) at half its size, against tests/golden/<scene>.png.
//!
//! Metric and tolerance: at most 0.1% of pixels may differ by more than
//! 2/255 in any channel (the same Mesa on another CPU may round a few
//! pixels differently). On failure the actual, expected and diff (x8)
//! images are written under target/test-output and named in the message.
//! `GLOSS_UPDATE_GOLDEN=1 cargo test --release --test golden` rewrites them.

mod common;

use gloss::image_compare::Tolerance;
use gloss::renderer::Output;

const GOLDEN: Tolerance = Tolerance {
    threshold: 2.0 / 255.0,
    max_frac_over: 0.001,
    max_abs: None,
};

fn shipped_scenes() -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(common::root().join("scenes"))
        .unwrap()
        .filter_map(|e| {
            let n = e.ok()?.file_name().into_string().ok()?;
            n.ends_with(".toml").then_some(n)
        })
        .collect();
    v.sort();
    v
}

#[test]
fn every_shipped_scene_matches_its_golden_image() {
    let scenes = shipped_scenes();
    assert!(scenes.len() >= 8, "scenes/: {scenes:?}");
    let ctx = common::context(common::backend());
    let mut failures = Vec::new();
    for name in &scenes {
        let mut scene = common::scene(name);
        let (w, h) = scene.render.size;
        scene.render.size = ((w / 2).max(1), (h / 2).max(1));
        let r = common::render_with(&ctx, &scene, Output::Srgb8);
        let stem = name.trim_end_matches(".toml");
        let golden = common::root()
            .join("tests/golden")
            .join(format!("{stem}.png"));
        match gloss::image_compare::check_golden(
            stem,
            &r.image,
            &golden,
            &common::out_dir(),
            &GOLDEN,
        ) {
            Ok(m) => eprintln!("{stem}: {m}"),
            Err(e) => failures.push(format!("{e:#}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_scene_renders_through_every_path_without_gl_errors() {
    let ctx = common::context(common::backend());
    for name in shipped_scenes() {
        for path in [
            gloss::scene::RenderPath::Forward,
            gloss::scene::RenderPath::Deferred,
            gloss::scene::RenderPath::Volumes,
            gloss::scene::RenderPath::Prepass,
        ] {
            let mut scene = common::scene(&name);
            scene.render.path = path;
            scene.render.size = (160, 90);
            let r = common::render_with(&ctx, &scene, Output::Srgb8);
            assert!(
                r.image.pixels().any(|p| p.0[..3] != [0, 0, 0]),
                "{name} {path:?} is black"
            );
        }
    }
}
