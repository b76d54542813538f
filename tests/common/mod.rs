//! Shared by the image tests: a headless context with GL debug output on,
//! rendering a scene, and comparing images with files written on failure.
#![allow(dead_code)]

use gloss::gl::{Backend, Headless};
use gloss::image_compare::{self, Metrics, Tolerance};
use gloss::renderer::{Output, render_scene};
use gloss::scene::Scene;
use image::RgbaImage;
use std::path::{Path, PathBuf};

pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

pub fn scene(name: &str) -> Scene {
    Scene::load(&root().join("scenes").join(name)).expect("shipped scene loads")
}

/// Where failing tests write actual/expected/diff images.
pub fn out_dir() -> PathBuf {
    let d = root().join("target/test-output");
    std::fs::create_dir_all(&d).expect("create target/test-output");
    d
}

/// The backend the tests use: EGL unless GLOSS_TEST_BACKEND=osmesa.
pub fn backend() -> Backend {
    match std::env::var("GLOSS_TEST_BACKEND").as_deref() {
        Ok("osmesa") => Backend::Osmesa,
        _ => Backend::Egl,
    }
}

/// A context with debug output on: every render checks for GL errors.
pub fn context(backend: Backend) -> Headless {
    let ctx = Headless::new(backend, true).expect("headless GL context");
    assert!(ctx.debug.enabled);
    ctx
}

pub struct Rendered {
    pub image: RgbaImage,
    /// Linear RGBA, bottom row first (only with Output::Linear32F).
    pub linear: Vec<f32>,
    pub width: u32,
    pub height: u32,
}

/// Render `scene` at its size and read it back. Panics with the GL error
/// messages if the frame raised any.
pub fn render_with(ctx: &Headless, scene: &Scene, output: Output) -> Rendered {
    let r = render_scene(ctx, scene, output)
        .unwrap_or_else(|e| panic!("rendering {}: {e:#}", scene.name));
    let (width, height) = scene.render.size;
    Rendered {
        image: r.read_image(),
        linear: if output == Output::Linear32F {
            r.read_linear()
        } else {
            Vec::new()
        },
        width,
        height,
    }
}

pub fn render(scene: &Scene, output: Output) -> Rendered {
    let ctx = context(backend());
    render_with(&ctx, scene, output)
}

/// Compare two rendered images; on failure write actual, expected and diff
/// under target/test-output and panic naming them.
pub fn assert_close(
    name: &str,
    actual: &RgbaImage,
    expected: &RgbaImage,
    tol: &Tolerance,
) -> Metrics {
    let dir = out_dir();
    let expected_path = dir.join(format!("{name}.reference.png"));
    expected
        .save(&expected_path)
        .expect("write reference image");
    image_compare::check_golden(name, actual, &expected_path, &dir, tol)
        .unwrap_or_else(|e| panic!("{e:#}"))
}

/// Compare against tests/golden/<name>.png (GLOSS_UPDATE_GOLDEN=1 rewrites it).
pub fn assert_golden(name: &str, actual: &RgbaImage, tol: &Tolerance) -> Metrics {
    let golden: &Path = &root().join("tests/golden").join(format!("{name}.png"));
    image_compare::check_golden(name, actual, golden, &out_dir(), tol)
        .unwrap_or_else(|e| panic!("{e:#}"))
}
