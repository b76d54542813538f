//! src/techniques/blending/transparency.rs: the sort, the blend against a CPU
//! over-operator, the unsorted artefact, every path alike, the plan and the
//! GL state.

use crate::common;
use glam::{Mat4, Vec3};
use gloss::image_compare::Tolerance;
use gloss::lighting::{shade, srgb_encode};
use gloss::math::look_at;
use gloss::renderer::{Output, Renderer};
use gloss::scene::{RenderPath, Scene};
use gloss::techniques::blending::transparency::back_to_front;
use gloss::techniques::plan;
use std::path::Path;

/// The bound of tests/deferred/main.rs: the opaque image under the glass
/// differs between paths by at most this, and the glass only scales it down.
const DEFERRED_BOUND: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.005,
    max_abs: Some(6.0 / 255.0),
};

fn with_path(scene: &Scene, path: RenderPath) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    s
}

#[test]
fn sort_is_back_to_front_by_view_depth() {
    let view = look_at(Vec3::new(0.0, 0.0, 10.0), Vec3::ZERO, Vec3::Y);
    // Depths 10, 12, 5, 10 (a tie with the first), -3 (behind the eye).
    let centres = [
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(5.0, 1.0, -2.0),
        Vec3::new(-1.0, 0.0, 5.0),
        Vec3::new(3.0, -2.0, 0.0),
        Vec3::new(0.0, 0.0, 13.0),
    ];
    // Ties keep scene order; behind the eye comes last (nearest, and clipped).
    assert_eq!(back_to_front(&view, &centres), [1, 0, 3, 2, 4]);
    // Sideways offset does not count: depth is along the view direction.
    let far_side = [Vec3::new(100.0, 0.0, 1.0), Vec3::new(0.0, 0.0, 0.0)];
    assert_eq!(back_to_front(&view, &far_side), [1, 0]);
    assert!(back_to_front(&view, &[]).is_empty());
}

#[test]
fn sort_with_the_camera_inside_a_bounding_box() {
    // The eye inside a big glass box centred 1 behind it: the box's centre is
    // behind the eye, so the box sorts last, over a small pane in front of the
    // eye: one point per object cannot order a box around the eye (the
    // pane, seen through the box's far wall, should come first and does).
    let eye = Vec3::new(0.0, 0.0, 0.0);
    let view = look_at(eye, Vec3::new(0.0, 0.0, -1.0), Vec3::Y);
    let box_centre = Vec3::new(0.0, 0.0, 1.0);
    let pane = Vec3::new(0.0, 0.0, -2.0);
    assert_eq!(back_to_front(&view, &[box_centre, pane]), [1, 0]);
    // Same depth for every object: scene order, whatever the view.
    let view = Mat4::from_rotation_y(0.7) * view;
    let same = [Vec3::ZERO; 4];
    assert_eq!(back_to_front(&view, &same), [0, 1, 2, 3]);
}

/// Two panes facing the camera, `front` at z = 0 and `back` at z = -1, seen
/// head-on by an orthographic camera; one directional light, no specular
/// (each pane's colour is one value). `listed` is the file order of the panes.
fn panes(front: &str, back: &str, listed_front_first: bool, sort: bool) -> Scene {
    let pane = |name: &str, z: f32| {
        format!(
            "[[objects]]\nname = \"{name}\"\nmesh = \"plane\"\nmaterial = \"{name}\"\nposition = [0.0, 0.0, {z}]\nrotation = [90.0, 0.0, 0.0]\nscale = [2.0, 1.0, 2.0]\n"
        )
    };
    let (a, b) = (pane(front, 0.0), pane(back, -1.0));
    let objects = if listed_front_first { a + &b } else { b + &a };
    let text = format!(
        r#"
[camera]
projection = "orthographic"
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
half_height = 3.0
near = 1.0
far = 20.0

[render]
size = [64, 48]
ambient = [0.1, 0.1, 0.1]
background = [0.2, 0.3, 0.1]
sort_transparent = {sort}

[[lights]]
type = "directional"
direction = [0.3, -0.4, -1.0]
color = [0.9, 0.85, 0.8]

[materials.red]
diffuse = [0.9, 0.1, 0.05]
specular = [0.0, 0.0, 0.0]
opacity = 0.6

[materials.blue]
diffuse = [0.05, 0.2, 0.9]
specular = [0.0, 0.0, 0.0]
opacity = 0.35

{objects}"#
    );
    Scene::parse(&text, Path::new("panes.toml")).unwrap()
}

/// The lit colour of pane `name` (linear) and its opacity.
fn pane_colour(scene: &Scene, name: &str) -> (Vec3, f32) {
    let o = scene.objects.iter().find(|o| o.name == name).unwrap();
    let m = &scene.materials[o.material];
    let p = o.model.transform_point3(Vec3::ZERO);
    let c = shade(
        &scene.lights,
        scene.render.ambient,
        m,
        m.diffuse,
        p,
        Vec3::Z,
        scene.camera.eye,
    );
    (c, m.opacity)
}

/// Notes 01 §4.5 with F_source = alpha, F_dest = 1 - alpha: C over D.
fn over(c: Vec3, alpha: f32, d: Vec3) -> Vec3 {
    c * alpha + d * (1.0 - alpha)
}

/// The centre pixel (both panes cover it), linear floats and 8-bit sRGB.
fn centre(scene: &Scene) -> (Vec3, [u8; 3]) {
    let lin = common::render(scene, Output::Linear32F);
    let (w, h) = (lin.width as usize, lin.height as usize);
    let i = ((h / 2) * w + w / 2) * 4;
    let linear = Vec3::new(lin.linear[i], lin.linear[i + 1], lin.linear[i + 2]);
    let img = common::render(scene, Output::Srgb8).image;
    let p = img.get_pixel(w as u32 / 2, h as u32 / 2 - 1).0;
    (linear, [p[0], p[1], p[2]])
}

/// Drawn `first` then `second` over the background, in linear light and in
/// sRGB-encoded 8-bit values (what the blend sees in each output).
fn expected(scene: &Scene, first: &str, second: &str) -> (Vec3, Vec3) {
    let (c1, a1) = pane_colour(scene, first);
    let (c2, a2) = pane_colour(scene, second);
    let bg = scene.render.background;
    let linear = over(c2, a2, over(c1, a1, bg));
    let enc = |v: Vec3| v.map(srgb_encode);
    // The 8-bit target rounds the intermediate result too.
    let q = |v: Vec3| (v * 255.0).round() / 255.0;
    let encoded = over(enc(c2), a2, q(over(enc(c1), a1, q(enc(bg)))));
    (linear, encoded)
}

fn assert_pixel(label: &str, got: (Vec3, [u8; 3]), want: (Vec3, Vec3)) {
    let (lin, px) = got;
    assert!(
        (lin - want.0).abs().max_element() < 1e-4,
        "{label}: linear output {lin}, the over-operator on the CPU gives {}",
        want.0
    );
    for ch in 0..3 {
        let diff = (px[ch] as f32 - want.1[ch] * 255.0).abs();
        assert!(
            diff <= 2.0,
            "{label}: channel {ch}: 8-bit output {px:?}, the over-operator on sRGB values gives {:?}",
            want.1 * 255.0
        );
    }
}

#[test]
fn two_panes_blend_back_to_front_as_the_over_operator() {
    // Red in front of blue, then blue in front of red; listed either way.
    let mut results = Vec::new();
    for (front, back) in [("red", "blue"), ("blue", "red")] {
        for listed_front_first in [true, false] {
            let scene = panes(front, back, listed_front_first, true);
            let got = centre(&scene);
            let want = expected(&scene, back, front);
            assert_pixel(&format!("{front} in front of {back}"), got, want);
            results.push(got.0);
        }
    }
    // Order matters: the two arrangements differ by far more than the bound.
    let d = (results[0] - results[2]).abs().max_element();
    assert!(
        d > 0.05,
        "red over blue vs blue over red differ by only {d}"
    );
}

#[test]
fn unsorted_panes_blend_in_the_wrong_order_and_it_shows() {
    // Listed front first and not sorted: the back pane is blended over the
    // front one (depth writes are off, so it is not hidden).
    let sorted = panes("red", "blue", true, true);
    let unsorted = panes("red", "blue", true, false);
    let right = centre(&sorted);
    let wrong = centre(&unsorted);
    assert_pixel("unsorted", wrong, expected(&unsorted, "red", "blue"));
    let diff = (0..3)
        .map(|c| (right.1[c] as i32 - wrong.1[c] as i32).abs())
        .max()
        .unwrap();
    assert!(
        diff >= 20,
        "sorting should change the pixel by far more than 2/255: {:?} vs {:?}",
        right.1,
        wrong.1
    );
    // The shipped scene lists its panes nearest first: unsorted, its image
    // differs over a measurable area.
    let scene = common::scene("transparency.toml");
    let mut off = scene.clone();
    off.render.sort_transparent = false;
    let a = common::render(&scene, Output::Srgb8).image;
    let b = common::render(&off, Output::Srgb8).image;
    let changed = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| (0..3).any(|c| (p[c] as i32 - q[c] as i32).abs() > 8))
        .count();
    let frac = changed as f64 / (a.width() * a.height()) as f64;
    eprintln!(
        "transparency.toml unsorted: {:.2}% of pixels off by > 8/255",
        frac * 100.0
    );
    assert!(
        frac > 0.01,
        "unsorted changed only {:.3}% of pixels",
        frac * 100.0
    );
}

#[test]
fn glass_looks_the_same_in_every_path() {
    let base = common::scene("transparency.toml");
    let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let other = common::render(&with_path(&base, path), Output::Srgb8);
        let m = common::assert_close(
            &format!("transparency-{}-vs-forward", path.name()),
            &other.image,
            &fwd.image,
            &DEFERRED_BOUND,
        );
        eprintln!("transparency.toml {path:?} vs forward: {m}");
    }
}

#[test]
fn the_pass_is_planned_only_for_transparent_materials_and_runs_last() {
    let glass = common::scene("transparency.toml");
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let p = plan(&with_path(&glass, path));
        assert_eq!(p.passes.last().unwrap().name, "transparency", "{p}");
        assert!(
            p.passes
                .last()
                .unwrap()
                .draws
                .contains("5 transparent objects"),
            "{p}"
        );
        // The opaque passes count only the objects they draw.
        assert!(p.passes[0].draws.starts_with("3 objects"), "{p}");
        let opaque = plan(&with_path(&common::scene("default.toml"), path));
        assert!(!opaque.has_pass("transparency"), "{opaque}");
    }
    // Opacity 1 is opaque: no pass.
    let mut solid = glass.clone();
    for m in &mut solid.materials {
        m.opacity = 1.0;
    }
    assert!(!plan(&solid).has_pass("transparency"));
}

#[test]
fn the_pass_restores_the_gl_state_in_every_path() {
    let ctx = common::context(common::backend());
    for path in [
        RenderPath::Forward,
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let scene = with_path(&common::scene("transparency.toml"), path);
        let changed = common::state_left_changed(&ctx, &scene, 96, 54);
        assert!(changed.is_empty(), "{path:?}:\n  {}", changed.join("\n  "));
    }
}

#[test]
fn a_material_made_transparent_live_renders_as_if_loaded_so() {
    // The demo's panel edits opacity; the renderer takes it through
    // set_scene_values: the plan gains the pass, the draw list the flag, and
    // the image equals a renderer built from the edited scene.
    let ctx = common::context(common::backend());
    let mut scene = with_path(&common::scene("default.toml"), RenderPath::Deferred);
    scene.render.size = (160, 90);
    let new = |s: &Scene| {
        Renderer::new(
            &ctx.gl,
            &ctx.debug,
            s,
            &gloss::gl::program::Sources::Embedded,
            160,
            90,
        )
        .unwrap()
    };
    let mut live = new(&scene);
    live.render(&scene.camera).unwrap();
    let before = live.read_image();
    assert!(!live.plan.has_pass("transparency"));
    let red = scene
        .materials
        .iter()
        .position(|m| m.name == "red")
        .unwrap();
    scene.materials[red].opacity = 0.4;
    live.set_scene_values(&scene).unwrap();
    assert!(live.plan.has_pass("transparency"), "{}", live.plan);
    live.render(&scene.camera).unwrap();
    let edited = live.read_image();
    let mut fresh = new(&scene);
    fresh.render(&scene.camera).unwrap();
    assert!(edited.as_raw() == fresh.read_image().as_raw());
    assert!(edited.as_raw() != before.as_raw());
}
