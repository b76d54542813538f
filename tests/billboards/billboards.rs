//! The three modes on scenes/billboards-forest.toml, against each other.
//!
//! The soft-edge mask: the pixels where the alpha-test image changes when
//! its reference goes from 0.02 to 0.98, i.e. where some sprite's filtered
//! alpha lies strictly between the two (the sprites' soft edges, and every
//! texel that mipmapping blurred).
//!
//! * alpha_test against blend_sorted: the same image except at the soft
//!   edges. Where the filtered alpha a is between 0 and 1, blending gives
//!   a S + (1 - a) D and the alpha test S (a >= 0.5) or D (a < 0.5); outside
//!   the mask a is 0 or 1 (within 0.02) and both give the same colour. So
//!   no pixel outside the mask differs by more than EDGE_THRESHOLD (0.02 of
//!   the full range, plus a step of rounding), except where two quads
//!   intersect (a tree's upright quad and a grass tuft's tilted one): no
//!   order of whole quads is right there, while the alpha test lets the
//!   depth test order every pixel. At most INTERSECTING_MAX_FRAC of the
//!   pixels (26 in this scene).
//! * blend (unsorted) against blend_sorted: the notes' "big problem". Where a
//!   near billboard was drawn first, its transparent texels wrote depth and
//!   the billboard behind is depth-rejected there: the sky or ground shows
//!   through a tree. At least HOLES_MIN_FRAC of the pixels, outside the soft
//!   edges, differ by more than HOLE_THRESHOLD.

use crate::common;
use gloss::image_compare::{Tolerance, compare_rgba8};
use gloss::renderer::{Output, Renderer};
use gloss::scene::{BillboardMode, RenderPath, Scene};
use gloss::techniques::plan;
use glow::HasContext;
use image::RgbaImage;

/// Outside the soft edges, alpha test and sorted blending agree within this.
const EDGE_THRESHOLD: u8 = 7;
/// Pixels where intersecting quads make any sort order wrong.
const INTERSECTING_MAX_FRAC: f64 = 0.0002;
/// A hole: off by more than this (any channel, 8-bit sRGB). The sky and
/// ground differ from the foliage by far more.
const HOLE_THRESHOLD: u8 = 64;
/// The unsorted image has at least this fraction of holes.
const HOLES_MIN_FRAC: f64 = 0.02;

/// The largest channel difference at each pixel.
fn diff(a: &RgbaImage, b: &RgbaImage) -> Vec<u8> {
    a.pixels()
        .zip(b.pixels())
        .map(|(p, q)| (0..3).map(|c| p.0[c].abs_diff(q.0[c])).max().unwrap())
        .collect()
}

fn forest(mode: BillboardMode) -> Scene {
    let mut s = common::scene("billboards-forest.toml");
    s.render.billboards = mode;
    s
}

fn save(name: &str, img: &RgbaImage) -> String {
    let p = common::out_dir().join(format!("{name}.png"));
    img.save(&p).expect("write test image");
    p.display().to_string()
}

#[test]
fn unsorted_blending_has_holes_and_the_alpha_test_has_none() {
    let ctx = common::context(common::backend());
    let render = |mode, alpha_ref| {
        let mut s = forest(mode);
        s.render.billboard_alpha_ref = alpha_ref;
        common::render_with(&ctx, &s, Output::Srgb8).image
    };
    let sorted = render(BillboardMode::BlendSorted, 0.5);
    let unsorted = render(BillboardMode::Blend, 0.5);
    let tested = render(BillboardMode::AlphaTest, 0.5);
    let edge: Vec<bool> = diff(
        &render(BillboardMode::AlphaTest, 0.02),
        &render(BillboardMode::AlphaTest, 0.98),
    )
    .iter()
    .map(|&d| d > 0)
    .collect();
    let n = edge.len() as f64;
    let edges = edge.iter().filter(|&&e| e).count();
    let off_edge = |d: &[u8], t: u8| d.iter().zip(&edge).filter(|(d, e)| **d > t && !**e).count();
    let tested_off = off_edge(&diff(&tested, &sorted), EDGE_THRESHOLD);
    let holes = off_edge(&diff(&unsorted, &sorted), HOLE_THRESHOLD);
    eprintln!(
        "soft edges {:.2}% of pixels; off the edges: alpha test {tested_off} pixels off by > {EDGE_THRESHOLD}/255, unsorted {:.2}% off by > {HOLE_THRESHOLD}/255",
        edges as f64 / n * 100.0,
        holes as f64 / n * 100.0
    );
    let names = || {
        let mask = RgbaImage::from_fn(sorted.width(), sorted.height(), |x, y| {
            let e = edge[(y * sorted.width() + x) as usize];
            image::Rgba(if e { [255; 4] } else { [0, 0, 0, 255] })
        });
        let d = gloss::image_compare::diff_image;
        format!(
            "images: {}, {}, {}, {}, {}, {}",
            save("billboards-sorted", &sorted),
            save("billboards-unsorted", &unsorted),
            save("billboards-alpha-test", &tested),
            save("billboards-soft-edges", &mask),
            save("billboards-unsorted.diff", &d(&unsorted, &sorted)),
            save("billboards-alpha-test.diff", &d(&tested, &sorted)),
        )
    };
    assert!(
        tested_off as f64 / n <= INTERSECTING_MAX_FRAC,
        "the alpha test should differ from sorted blending only at soft edges: {tested_off} pixels off them; {}",
        names()
    );
    assert!(
        holes as f64 / n >= HOLES_MIN_FRAC,
        "unsorted blending should show holes: only {holes} pixels; {}",
        names()
    );
    // The mask is the edges (the thin grass blades are mostly edge), not the image.
    assert!(
        edges as f64 / n < 0.4,
        "soft edges cover {edges} pixels; {}",
        names()
    );
}

#[test]
fn sorted_blending_does_not_depend_on_the_scene_order() {
    let ctx = common::context(common::backend());
    for (mode, same) in [
        (BillboardMode::BlendSorted, true),
        (BillboardMode::Blend, false),
    ] {
        let scene = forest(mode);
        let mut reversed = scene.clone();
        reversed.billboards.reverse();
        let a = common::render_with(&ctx, &scene, Output::Srgb8);
        let b = common::render_with(&ctx, &reversed, Output::Srgb8);
        let m = compare_rgba8(&a.image, &b.image, 1.0 / 255.0).unwrap();
        eprintln!("{mode}: scene order against reversed: {m}");
        if same {
            // Ties in view depth keep the scene's order: none in this scene.
            assert_eq!(m.frac_over, 0.0, "{mode}: {m}");
        } else {
            assert!(
                m.frac_over > 0.005,
                "{mode}: reversing should move the holes: {m}"
            );
        }
    }
}

#[test]
fn the_deferred_paths_draw_the_billboards_against_the_scene_depth() {
    // The billboards are drawn forward over every path's opaque image, after
    // the G-buffer's depth is copied into the output: the same billboards,
    // hidden by the same rock, as in the forward path.
    let ctx = common::context(common::backend());
    let forward = common::render_with(&ctx, &forest(BillboardMode::AlphaTest), Output::Srgb8);
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let mut scene = forest(BillboardMode::AlphaTest);
        scene.render.path = path;
        let r = common::render_with(&ctx, &scene, Output::Srgb8);
        // The deferred bound of tests/deferred/main.rs (G-buffer precision).
        let bound = Tolerance {
            threshold: 1.0 / 255.0,
            max_frac_over: 0.005,
            max_abs: Some(8.0 / 255.0),
        };
        common::assert_close(
            &format!("billboards-{path}"),
            &r.image,
            &forward.image,
            &bound,
        );
    }
}

#[test]
fn the_plan_has_a_billboard_pass_only_for_scenes_with_billboards() {
    let scene = forest(BillboardMode::AlphaTest);
    let p = plan(&scene);
    let pass = p
        .passes
        .iter()
        .find(|p| p.name == "billboards")
        .expect("a billboards pass");
    assert_eq!(pass.target, "output");
    assert!(pass.draws.starts_with("500 billboards"), "{}", pass.draws);
    assert!(pass.draws.contains("alpha test"), "{}", pass.draws);
    // Drawn last, over the finished opaque image, in every path.
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let mut s = scene.clone();
        s.render.path = path;
        let p = plan(&s);
        assert_eq!(p.passes.last().unwrap().name, "billboards", "{path}:\n{p}");
    }
    let mut sorted = scene.clone();
    sorted.render.billboards = BillboardMode::BlendSorted;
    assert!(
        plan(&sorted)
            .passes
            .last()
            .unwrap()
            .draws
            .contains("sorted back to front")
    );
    for name in ["default.toml", "mixed-lights.toml", "plane.toml"] {
        let p = plan(&common::scene(name));
        assert!(!p.has_pass("billboards"), "{name}:\n{p}");
    }
}

/// State beyond tests/common's list that this pass touches.
fn extra_state(gl: &glow::Context) -> Vec<(&'static str, i64)> {
    unsafe {
        vec![
            (
                "BLEND_SRC_ALPHA",
                gl.get_parameter_i32(glow::BLEND_SRC_ALPHA) as i64,
            ),
            (
                "BLEND_DST_ALPHA",
                gl.get_parameter_i32(glow::BLEND_DST_ALPHA) as i64,
            ),
            (
                "ARRAY_BUFFER_BINDING",
                gl.get_parameter_i32(glow::ARRAY_BUFFER_BINDING) as i64,
            ),
        ]
    }
}

#[test]
fn every_mode_and_path_restores_the_gl_state_with_no_gl_error() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let fresh = (common::gl_state(gl), extra_state(gl));
    for mode in BillboardMode::ALL {
        for path in [
            RenderPath::Forward,
            RenderPath::Deferred,
            RenderPath::Volumes,
            RenderPath::Prepass,
        ] {
            let mut scene = forest(*mode);
            scene.render.path = path;
            let mut r = Renderer::new(
                gl,
                &ctx.debug,
                &scene,
                &gloss::gl::program::Sources::Embedded,
                160,
                90,
            )
            .unwrap();
            let mut changed = Vec::new();
            // A GL error or a feedback loop fails render_inspected.
            r.render_inspected(&scene.camera, &mut |pass| {
                let now = (common::gl_state(gl), extra_state(gl));
                if now != fresh {
                    changed.push(format!("{} changed the GL state: {:?}", pass.name, now));
                }
            })
            .unwrap_or_else(|e| panic!("{mode} {path}: {e:#}"));
            assert!(changed.is_empty(), "{mode} {path}: {}", changed.join("\n"));
            assert!(r.plan.has_pass("billboards"));
        }
    }
}

#[test]
fn a_saved_forest_loads_to_the_same_billboards() {
    // "Save as" away from the assets rewrites the sprite paths.
    let dir = crate::temp_dir("save");
    let scene = forest(BillboardMode::BlendSorted);
    let dest = dir.join("saved.toml");
    scene.save_as(&dest).unwrap();
    let saved = Scene::load(&dest).unwrap();
    assert_eq!(saved.billboards, scene.billboards);
    assert_eq!(saved.render.billboards, BillboardMode::BlendSorted);
    assert_eq!(saved.sprites.len(), 2);
    for s in &saved.sprites {
        assert!(gloss::assets::is_file(s), "{}", s.display());
    }
}

#[test]
fn gloss_plan_prints_the_billboard_pass() {
    let run = |scene: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .arg("plan")
            .arg(common::root().join("scenes").join(scene))
            .output()
            .expect("run gloss plan");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let forest = run("billboards-forest.toml");
    let line = forest
        .lines()
        .find(|l| l.contains("billboards") && l.contains("-> output"))
        .unwrap_or_else(|| panic!("no billboards pass:\n{forest}"));
    assert!(line.contains("500 billboards, 1 instanced quad"), "{line}");
    assert!(
        line.contains("src/techniques/billboards/billboards.rs"),
        "{line}"
    );
    let plain = run("default.toml");
    assert!(!plain.contains("billboards"), "{plain}");
}
