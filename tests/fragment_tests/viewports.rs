//! Split viewports with scissored clears (src/techniques/fragment_tests/viewports.rs).
//!
//! Each quarter of scenes/viewports.toml must be exactly the scene drawn
//! alone from that view's camera at the quarter's size: glViewport maps the
//! view into its rectangle, and the scissored clears of later views leave
//! earlier ones alone (an unscissored clear would leave only the last view).
//! Bound: at most 0.1% of a quarter's pixels over 1/255 and none over 3/255.

use crate::common;
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

const EXACT: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.001,
    max_abs: Some(3.0 / 255.0),
};

/// The quarter of `image` that view `v` covers (fractions, y up), without
/// its one-pixel border.
fn crop(image: &image::RgbaImage, viewport: [f32; 4]) -> image::RgbaImage {
    let quarter = crop_whole(image, viewport);
    let (w, h) = quarter.dimensions();
    image::imageops::crop_imm(&quarter, 1, 1, w - 2, h - 2).to_image()
}

fn crop_whole(image: &image::RgbaImage, viewport: [f32; 4]) -> image::RgbaImage {
    let (w, h) = (image.width() as f32, image.height() as f32);
    let [x, y, vw, vh] = viewport;
    let (x0, x1) = ((x * w).round() as u32, ((x + vw) * w).round() as u32);
    // Image rows run top down; GL's y runs bottom up.
    let (y0, y1) = (
        ((1.0 - y - vh) * h).round() as u32,
        ((1.0 - y) * h).round() as u32,
    );
    image::imageops::crop_imm(image, x0, y0, x1 - x0, y1 - y0).to_image()
}

/// The scene alone from view `i`'s camera, at the view's size.
fn alone(scene: &Scene, i: usize) -> Scene {
    let v = &scene.views[i];
    let mut s = scene.clone();
    s.views.clear();
    if let Some(c) = &v.camera {
        s.camera = c.clone();
    }
    let (w, h) = scene.render.size;
    s.render.size = (
        (v.viewport[2] * w as f32).round() as u32,
        (v.viewport[3] * h as f32).round() as u32,
    );
    s
}

#[test]
fn each_view_is_the_scene_from_its_own_camera_in_its_own_rectangle() {
    let ctx = common::context(common::backend());
    let scene = common::scene("viewports.toml");
    assert_eq!(scene.views.len(), 4);
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Prepass,
    ] {
        let mut s = scene.clone();
        s.render.path = path;
        let frame = common::render_with(&ctx, &s, Output::Srgb8).image;
        for (i, v) in s.views.iter().enumerate() {
            let expected = common::render_with(&ctx, &alone(&s, i), Output::Srgb8).image;
            let (ew, eh) = expected.dimensions();
            let expected = image::imageops::crop_imm(&expected, 1, 1, ew - 2, eh - 2).to_image();
            let actual = crop(&frame, v.viewport);
            let name = format!("viewports-{}-{}", path.name(), v.name);
            common::assert_close(&name, &actual, &expected, &EXACT);
        }
    }
}

#[test]
fn the_plan_draws_the_world_once_per_view() {
    let scene = common::scene("viewports.toml");
    let plan = gloss::techniques::plan(&scene);
    assert_eq!(plan.views.len(), 4);
    let passes: Vec<(&str, usize)> = plan.passes.iter().map(|p| (p.name, p.view)).collect();
    assert_eq!(
        passes,
        [
            ("forward", 0),
            ("forward", 1),
            ("forward", 2),
            ("forward", 3),
            ("viewport borders", 0)
        ],
        "{plan}"
    );
    let text = plan.to_string();
    assert!(text.contains("'top' in [0, 0.5, 0.5, 0.5]"), "{text}");
    // Without [[views]], one view and no viewport.
    let plain = gloss::techniques::plan(&common::scene("default.toml"));
    assert_eq!(plain.views.len(), 1);
    assert!(plain.views[0].viewport.is_none());
}

#[test]
fn split_views_restore_the_scissor_test_in_every_path() {
    let ctx = common::context(common::backend());
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let mut scene = common::scene("viewports.toml");
        scene.render.path = path;
        let changed = common::state_left_changed(&ctx, &scene, 160, 90);
        assert!(changed.is_empty(), "{path}:\n  {}", changed.join("\n  "));
    }
}

#[test]
fn a_viewport_outside_the_frame_is_refused() {
    let base = std::fs::read_to_string(common::root().join("scenes/viewports.toml")).unwrap();
    for (bad, words) in [
        (
            "viewport = [0.0, 0.5, 0.5, 0.5]",
            "viewport = [0.6, 0.5, 0.5, 0.5]",
        ),
        (
            "viewport = [0.0, 0.5, 0.5, 0.5]",
            "viewport = [0.0, 0.5, 0.0, 0.5]",
        ),
    ] {
        let text = base.replacen(bad, words, 1);
        let e = Scene::parse(&text, &common::root().join("scenes/viewports.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("views[0].viewport"), "{e}");
    }
    let text = base.replacen("name = \"top\"", "name = \"top\"\nmirror = 1", 1);
    assert!(Scene::parse(&text, std::path::Path::new("v.toml")).is_err());
    let cam = base.replacen("half_height = 3.2", "half_height = -1.0", 1);
    let e = Scene::parse(&cam, std::path::Path::new("v.toml"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("views[0].camera.half_height"), "{e}");
}

#[test]
fn the_borders_are_one_pixel_scissored_clears() {
    let ctx = common::context(common::backend());
    let scene = common::scene("viewports.toml");
    let frame = common::render_with(&ctx, &scene, Output::Srgb8).image;
    let grey = (gloss::lighting::srgb_encode(0.5) * 255.0).round() as u8;
    for v in &scene.views {
        let q = crop_whole(&frame, v.viewport);
        let (w, h) = q.dimensions();
        // Every pixel of the quarter's outline is the border grey.
        for (x, y) in (0..w)
            .flat_map(|x| [(x, 0), (x, h - 1)])
            .chain((0..h).flat_map(|y| [(0, y), (w - 1, y)]))
        {
            let p = q.get_pixel(x, y).0;
            assert_eq!(&p[..3], &[grey; 3], "{} at ({x}, {y})", v.name);
        }
        // And the pixel inside it is not.
        assert_ne!(&q.get_pixel(1, 1).0[..3], &[grey; 3], "{}", v.name);
    }
}
