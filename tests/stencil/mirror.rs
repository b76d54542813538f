//! Planar mirrors (src/techniques/stencil/mirror.rs) against independent
//! references. Bounds: inside a mirror's region (its one-pixel rim left out,
//! where the two rasterisations of the mirror's edge may differ), at most
//! 0.5% of pixels may differ from the reference by more than 3/255 and none
//! by more than 40/255: the reflected world and the reflected camera round
//! their vertex transforms differently, which moves a few silhouette and
//! checker-edge pixels by one pixel.

use crate::common;
use glam::{Mat3, Mat4};
use gloss::gl::program::Sources;
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Renderer;
use gloss::scene::{MirrorOrder, RenderPath, Scene};
use image::RgbaImage;

const THRESHOLD: f64 = 3.0 / 255.0;
const MAX_FRAC_OVER: f64 = 0.005;
const MAX_ABS: f64 = 40.0 / 255.0;

/// A frame and the stencil buffer after each of its passes.
struct Captured {
    image: RgbaImage,
    /// (pass name, view, stencil values top row first) after each pass.
    stencils: Vec<(String, usize, Vec<u8>)>,
    views: Vec<gloss::frame::views::View>,
    width: usize,
}

fn capture(ctx: &gloss::gl::Headless, scene: &Scene) -> Captured {
    let (w, h) = (scene.render.size.0 as i32, scene.render.size.1 as i32);
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, scene, &Sources::Embedded, w, h).unwrap();
    let fb = r.output().id;
    let mut stencils = Vec::new();
    r.render_inspected(&scene.camera, &mut |pass| {
        stencils.push((
            pass.name.to_string(),
            pass.view,
            gloss::gl::framebuffer::read_stencil_top_down(&ctx.gl, fb, w, h),
        ))
    })
    .unwrap_or_else(|e| panic!("{}: {e:#}", scene.name));
    // The stencil inspector reads the same buffer.
    assert_eq!(r.read_stencil(), stencils.last().unwrap().2);
    Captured {
        image: r.read_image(),
        stencils,
        views: r.plan.views.clone(),
        width: w as usize,
    }
}

/// Mirrors that reflect exactly (tint 1, reflectance 1), so that the
/// reflection can be compared with a reference.
fn plain_mirrors(mut scene: Scene) -> Scene {
    for o in &mut scene.objects {
        if let Some(m) = &mut o.mirror {
            m.tint = glam::Vec3::ONE;
            m.reflectance = 1.0;
        }
    }
    scene
}

/// The independent reference for a view that draws the world at `R * x`:
/// the scene without its mirrors (and without `hidden`), seen from the
/// camera reflected back (`R^-1 * eye`), flipped left-right when R mirrors.
fn reference(ctx: &gloss::gl::Headless, scene: &Scene, r: Mat4, hidden: &[&str]) -> RgbaImage {
    let mut s = scene.clone();
    assert!(s.objects.iter().all(|o| o.parent.is_none()));
    s.objects
        .retain(|o| o.mirror.is_none() && !hidden.contains(&o.name.as_str()));
    let back = r.inverse();
    s.camera.eye = back.transform_point3(scene.camera.eye);
    s.camera.target = back.transform_point3(scene.camera.target);
    s.camera.up = back.transform_vector3(scene.camera.up);
    let image = common::render_with(ctx, &s, gloss::renderer::Output::Srgb8).image;
    if Mat3::from_mat4(r).determinant() < 0.0 {
        image::imageops::flip_horizontal(&image)
    } else {
        image
    }
}

/// The pixels where view `k`'s reflection shows: the stencil holds the
/// view's value right after its world was drawn, minus the regions of
/// mirrors seen inside it (the next value up, marked later), minus the rim.
fn region(c: &Captured, k: usize) -> Vec<bool> {
    let value = c.views[k]
        .stencil
        .expect("a reflected view has a stencil value");
    let after_world = c
        .stencils
        .iter()
        .position(|(name, view, _)| *view == k && name != "mirror mark")
        .expect("the view's world pass ran");
    let mut inside: Vec<bool> = c.stencils[after_world]
        .2
        .iter()
        .map(|&s| s == value)
        .collect();
    for (_, _, s) in &c.stencils[after_world..] {
        for (i, &v) in s.iter().enumerate() {
            if v == value + 1 {
                inside[i] = false;
            }
        }
    }
    let w = c.width;
    let h = inside.len() / w;
    (0..inside.len())
        .map(|i| {
            let (x, y) = (i % w, i / w);
            x > 0
                && y > 0
                && x + 1 < w
                && y + 1 < h
                && [
                    i - 1,
                    i + 1,
                    i - w,
                    i + w,
                    i - w - 1,
                    i - w + 1,
                    i + w - 1,
                    i + w + 1,
                ]
                .iter()
                .all(|&j| inside[j])
        })
        .collect()
}

/// Keep only the masked pixels of `image` (others black).
fn masked(image: &RgbaImage, mask: &[bool]) -> RgbaImage {
    let mut out = image.clone();
    for (i, p) in out.pixels_mut().enumerate() {
        if !mask[i] {
            *p = image::Rgba([0, 0, 0, 255]);
        }
    }
    out
}

/// Compare every reflected view of `scene` with its reference; returns the
/// size of each view's region. `hidden`: objects behind the mirrors that
/// the clip plane keeps out of the reflections.
fn check_reflections(name: &str, scene: &Scene, hidden: &[&str]) -> Vec<usize> {
    let ctx = common::context(common::backend());
    let c = capture(&ctx, scene);
    let mut sizes = Vec::new();
    for k in 1..c.views.len() {
        let mask = region(&c, k);
        let n = mask.iter().filter(|&&b| b).count();
        sizes.push(n);
        let expected = reference(&ctx, scene, c.views[k].reflection, hidden);
        let (actual, expected) = (masked(&c.image, &mask), masked(&expected, &mask));
        let m = compare_rgba8(&actual, &expected, THRESHOLD).unwrap();
        // frac_over is over the whole image: scale it to the region.
        let frac = m.frac_over * mask.len() as f64 / n.max(1) as f64;
        if frac > MAX_FRAC_OVER || m.max_abs > MAX_ABS {
            let dir = common::out_dir();
            let stem = format!("{name}-view{k}");
            actual.save(dir.join(format!("{stem}.actual.png"))).unwrap();
            expected
                .save(dir.join(format!("{stem}.reference.png")))
                .unwrap();
            gloss::image_compare::diff_image(&actual, &expected)
                .save(dir.join(format!("{stem}.diff.png")))
                .unwrap();
            panic!(
                "{name}: view {k} ({}) differs from the reflected camera's image: {:.3}% of {n} pixels over 3/255, max {:.1}/255; see {}/{stem}.{{actual,reference,diff}}.png",
                c.views[k].name,
                frac * 100.0,
                m.max_abs * 255.0,
                dir.display()
            );
        }
    }
    sizes
}

#[test]
fn a_mirror_shows_what_the_reflected_camera_sees() {
    let scene = plain_mirrors(common::scene("mirror-normal-first.toml"));
    let sizes = check_reflections("mirror", &scene, &["behind"]);
    assert_eq!(sizes.len(), 1);
    assert!(sizes[0] > 10_000, "the mirror covers {} pixels", sizes[0]);
}

#[test]
fn recursive_mirrors_match_the_reflected_camera_at_every_depth() {
    for depth in 1..=3 {
        let mut scene = plain_mirrors(common::scene("mirrors-recursive.toml"));
        scene.render.mirror_depth = depth;
        let sizes = check_reflections(&format!("recursive-{depth}"), &scene, &[]);
        // One view a level: the camera sees the back mirror only (the
        // front one is behind it), and each reflection the other mirror
        // (src/scene/mirror_views.rs follows no mirror that cannot show;
        // without that test the front mirror's chain added `depth` views
        // of no pixel).
        assert_eq!(sizes.len(), depth as usize, "{sizes:?}");
        assert!(sizes.iter().all(|&n| n > 0), "{sizes:?}");
        // The back mirror's chain is in view down to the last level.
        let deepest = sizes[depth as usize - 1];
        assert!(deepest > 500, "depth {depth}: region sizes {sizes:?}");
    }
}

#[test]
fn several_mirrors_each_have_their_own_stencil_value() {
    let scene = plain_mirrors(common::scene("mirrors-several.toml"));
    let sizes = check_reflections("several", &scene, &[]);
    assert_eq!(sizes.len(), 2);
    let ctx = common::context(common::backend());
    let c = capture(&ctx, &scene);
    let stencil = &c.stencils.last().unwrap().2;
    // mirror_depth 1: values 1 (left) and 1 + 2 = 3 (right), one level inside each.
    for (value, mirror) in [(1u8, "left"), (3, "right")] {
        let n = stencil.iter().filter(|&&s| s == value).count();
        assert!(
            n > 5_000,
            "{mirror} mirror: {n} pixels hold stencil {value}"
        );
    }
}

#[test]
fn both_orders_of_the_slides_give_the_same_image() {
    let ctx = common::context(common::backend());
    let normal = common::scene("mirror-normal-first.toml");
    let reflected = common::scene("mirror-reflected-first.toml");
    assert_eq!(reflected.render.mirror_order, MirrorOrder::ReflectedFirst);
    let a = common::render_with(&ctx, &normal, gloss::renderer::Output::Srgb8);
    let b = common::render_with(&ctx, &reflected, gloss::renderer::Output::Srgb8);
    // The orders differ only where the reflection shows the clear colour,
    // which one order clears to and the other paints (1/255 of rounding).
    common::assert_close(
        "mirror-orders",
        &b.image,
        &a.image,
        &gloss::image_compare::Tolerance {
            threshold: 1.0 / 255.0,
            max_frac_over: 0.001,
            max_abs: Some(3.0 / 255.0),
        },
    );
}

/// The mirror region of `scene`'s first reflection against the reference
/// without the cone behind the mirror: (pixels over 8/255, region size).
fn mirror_error(scene: &Scene) -> (usize, usize) {
    let ctx = common::context(common::backend());
    let c = capture(&ctx, scene);
    let mask = region(&c, 1);
    let n = mask.iter().filter(|&&b| b).count();
    let expected = reference(&ctx, scene, c.views[1].reflection, &["behind"]);
    let m = compare_rgba8(
        &masked(&c.image, &mask),
        &masked(&expected, &mask),
        8.0 / 255.0,
    )
    .unwrap();
    ((m.frac_over * mask.len() as f64).round() as usize, n)
}

#[test]
fn the_clip_plane_keeps_what_lies_behind_the_mirror_out_of_it() {
    let mut scene = plain_mirrors(common::scene("mirror-normal-first.toml"));
    let (with_clip, n) = mirror_error(&scene);
    assert!(
        with_clip * 200 < n,
        "{with_clip} of {n} pixels off with the clip plane"
    );
    // Without it, the cone behind the mirror appears in front of it.
    scene.render.mirror_clip = false;
    let (without, _) = mirror_error(&scene);
    assert!(
        without > 300,
        "only {without} pixels show the cone behind the mirror"
    );
}

#[test]
fn without_the_winding_fix_the_reflection_shows_back_faces() {
    let mut scene = plain_mirrors(common::scene("mirror-normal-first.toml"));
    scene.render.mirror_winding = false;
    let (wrong, n) = mirror_error(&scene);
    assert!(
        wrong * 20 > n,
        "only {wrong} of {n} pixels change without glFrontFace(GL_CW)"
    );
}

#[test]
fn every_mirror_pass_restores_the_gl_state() {
    let ctx = common::context(common::backend());
    for name in [
        "mirror-normal-first.toml",
        "mirror-reflected-first.toml",
        "mirrors-recursive.toml",
    ] {
        let mut scene = common::scene(name);
        scene.render.size = (96, 54);
        let changed = common::state_left_changed(&ctx, &scene, 96, 54);
        assert!(changed.is_empty(), "{name}:\n  {}", changed.join("\n  "));
    }
}

#[test]
fn the_plan_has_stencil_passes_only_with_a_mirror() {
    let plain = gloss::techniques::plan(&common::scene("default.toml"));
    assert_eq!(plain.views.len(), 1);
    assert!(!plain.passes.iter().any(|p| p.name.starts_with("mirror")));
    // Reflected first: the reflected world, the stencil pass, the scene.
    let rf = gloss::techniques::plan(&common::scene("mirror-reflected-first.toml"));
    let names: Vec<(&str, usize)> = rf.passes.iter().map(|p| (p.name, p.view)).collect();
    assert_eq!(
        names,
        [
            ("forward", 1),
            ("mirror stencil", 0),
            ("forward", 0),
            ("mirror surface", 0)
        ]
    );
    // Normal first, three deep: the camera's world and one reflection a
    // level (the front mirror is behind the camera: it is marked, and
    // followed no further). The chain back, front, back is unmarked at
    // levels 2 and 3, and the front mirror seen at level 4 once more.
    let mut s = common::scene("mirrors-recursive.toml");
    s.render.mirror_depth = 3;
    let nf = gloss::techniques::plan(&s);
    assert_eq!(nf.views.len(), 4);
    assert_eq!(nf.passes.iter().filter(|p| p.name == "forward").count(), 4);
    assert_eq!(
        nf.passes
            .iter()
            .filter(|p| p.name == "mirror unmark")
            .count(),
        3
    );
    // The deferred paths draw each reflection through their own passes.
    s.render.path = RenderPath::Deferred;
    let d = gloss::techniques::plan(&s);
    assert_eq!(d.passes.iter().filter(|p| p.name == "gbuffer").count(), 4);
}

#[test]
fn mirrors_look_the_same_in_every_lighting_path() {
    // The bound of tests/deferred, the G-buffer's precision: at most 0.5% of
    // pixels over 1/255, none over 6/255.
    let tol = gloss::image_compare::Tolerance {
        threshold: 1.0 / 255.0,
        max_frac_over: 0.005,
        max_abs: Some(6.0 / 255.0),
    };
    let ctx = common::context(common::backend());
    for name in [
        "mirror-normal-first.toml",
        "mirror-reflected-first.toml",
        "mirrors-several.toml",
        "mirrors-recursive.toml",
    ] {
        let forward = common::scene(name);
        let expected = common::render_with(&ctx, &forward, gloss::renderer::Output::Srgb8);
        for path in [
            RenderPath::Deferred,
            RenderPath::Volumes,
            RenderPath::Prepass,
        ] {
            let mut s = forward.clone();
            s.render.path = path;
            let actual = common::render_with(&ctx, &s, gloss::renderer::Output::Srgb8);
            let stem = format!("{}-{}", name.trim_end_matches(".toml"), path.name());
            common::assert_close(&stem, &actual.image, &expected.image, &tol);
        }
    }
}

#[test]
fn the_stencil_inspector_shows_each_level_after_any_pass() {
    let dir = common::out_dir();
    let out = dir.join("stencil-inspector.png");
    let run = |after: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
            .args([
                "render",
                "scenes/mirrors-recursive.toml",
                "--size",
                "320x180",
            ])
            .args(["--inspect", "stencil", "--after", after, "-o"])
            .arg(&out)
            .current_dir(common::root())
            .output()
            .unwrap()
    };
    // Pass 9 of the plan marks the third level (the plan test above lists it).
    let ok = run("9");
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let img = image::open(&out).unwrap().to_rgba8();
    for v in 0..=3u8 {
        let c = gloss::renderer::stencil_color(v);
        let n = img.pixels().filter(|p| p.0 == c).count();
        assert!(
            n > 100,
            "stencil value {v}: {n} pixels of its colour in {}",
            out.display()
        );
    }
    let c4 = gloss::renderer::stencil_color(4);
    assert!(
        !img.pixels().any(|p| p.0 == c4),
        "level 4 is not drawn at depth 3"
    );
    let bad = run("999");
    assert!(!bad.status.success());
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(
        err.contains("--after 999") && err.contains("gloss plan"),
        "{err}"
    );
}

/// `scene` rendered as it is and with `change` applied must give the same
/// image (the bound of the two orders).
fn same_image(name: &str, scene: &Scene, change: impl Fn(&mut Scene)) {
    let ctx = common::context(common::backend());
    let a = common::render_with(&ctx, scene, gloss::renderer::Output::Srgb8);
    let mut other = scene.clone();
    change(&mut other);
    let b = common::render_with(&ctx, &other, gloss::renderer::Output::Srgb8);
    common::assert_close(
        name,
        &a.image,
        &b.image,
        &gloss::image_compare::Tolerance {
            threshold: 1.0 / 255.0,
            max_frac_over: 0.001,
            max_abs: Some(3.0 / 255.0),
        },
    );
}

fn has_stencil_pass(scene: &Scene) -> bool {
    gloss::techniques::plan(scene)
        .passes
        .iter()
        .any(|p| p.name == "mirror stencil")
}

#[test]
fn an_infinite_mirror_needs_no_stencil_pass() {
    let lake = common::scene("mirror-infinite.toml");
    assert!(!has_stencil_pass(&lake));
    let bounded = |s: &mut Scene| s.objects[0].mirror.as_mut().unwrap().infinite = false;
    let mut check = lake.clone();
    bounded(&mut check);
    assert!(has_stencil_pass(&check));
    // The lake reaches past the far plane: the stencil would mark every
    // pixel below the horizon, so it changes nothing.
    same_image("mirror-infinite-vs-bounded", &lake, bounded);
    same_image("mirror-infinite-vs-normal-first", &lake, |s| {
        s.render.mirror_order = MirrorOrder::NormalFirst
    });
}

#[test]
fn a_mirror_covered_by_a_wall_needs_no_stencil_pass() {
    let wall = common::scene("mirror-covered.toml");
    assert!(!has_stencil_pass(&wall));
    let mirror = wall
        .objects
        .iter()
        .position(|o| o.mirror.is_some())
        .unwrap();
    same_image("mirror-covered-vs-stencil", &wall, |s| {
        s.objects[mirror].mirror.as_mut().unwrap().covered = false
    });
}

#[test]
fn the_roughening_texture_multiplies_the_reflection() {
    // A uniform grey roughening texture of linear value 0.5: every pixel of
    // the mirror is the bare reflection times 0.5, encoded (the blend
    // multiplies encoded values: see docs/stencil/mirror.md), within 2/255.
    let dir = common::out_dir().join("roughness");
    std::fs::create_dir_all(&dir).unwrap();
    let grey = dir.join("grey.png");
    image::RgbImage::from_pixel(8, 8, image::Rgb([128, 128, 128]))
        .save(&grey)
        .unwrap();
    let plain = plain_mirrors(common::scene("mirror-normal-first.toml"));
    let mut rough = plain.clone();
    let m = rough
        .objects
        .iter()
        .position(|o| o.mirror.is_some())
        .unwrap();
    rough.objects[m].mirror.as_mut().unwrap().roughness = Some(grey);
    let ctx = common::context(common::backend());
    let a = capture(&ctx, &plain);
    let b = capture(&ctx, &rough);
    let mask = region(&a, 1);
    let factor = gloss::lighting::srgb_encode(128.0 / 255.0);
    let (mut n, mut worst) = (0, 0.0f32);
    for (i, inside) in mask.iter().enumerate() {
        if !inside {
            continue;
        }
        let (x, y) = ((i % a.width) as u32, (i / a.width) as u32);
        for c in 0..3 {
            let bare = f32::from(a.image.get_pixel(x, y)[c]);
            let got = f32::from(b.image.get_pixel(x, y)[c]);
            worst = worst.max((got - bare * factor).abs());
        }
        n += 1;
    }
    assert!(n > 10_000, "{n} pixels in the mirror");
    assert!(worst <= 2.0, "a pixel is {worst}/255 from bare x {factor}");
}

#[test]
fn a_curved_mirror_shows_a_point_where_its_cpu_twin_puts_it() {
    // A small green marker as far from the ball's centre as the eye is:
    // there the image (reflected about its own tangent plane) is exact, and
    // the GPU must draw it where `curved_image` projects.
    let path = common::root().join("scenes/mirror-curved.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let base = Scene::parse(&text, &path).unwrap();
    let ball = base.objects.iter().find(|o| o.mirror.is_some()).unwrap();
    let sphere = ball.curved_mirror().expect("a curved mirror");
    let (c, r) = (sphere.truncate(), sphere.w);
    let eye = base.camera.eye;
    let marker = c + glam::Vec3::new(1.0, 0.3, 0.8).normalize() * (eye - c).length();
    let text = format!(
        "{text}\n[materials.marker]\ndiffuse = [0.0, 1.0, 0.0]\nspecular = [0.0, 0.0, 0.0]\n\n[[objects]]\nname = \"marker\"\nmesh = \"sphere\"\nmaterial = \"marker\"\nposition = [{}, {}, {}]\nscale = [0.12, 0.12, 0.12]\n",
        marker.x, marker.y, marker.z
    );
    let mut scene = plain_mirrors(Scene::parse(&text, &path).unwrap());
    scene.render.ambient = glam::Vec3::splat(1.0);
    scene.render.size = (1280, 720);
    let ctx = common::context(common::backend());
    let cap = capture(&ctx, &scene);
    let inside = region(&cap, 1);
    let (w, h) = (cap.width, inside.len() / cap.width);
    // The marker's pixels inside the ball: green well above red and blue.
    let (mut n, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for (i, p) in cap.image.pixels().enumerate() {
        let [r8, g8, b8, _] = p.0;
        if inside[i] && g8 > 120 && u32::from(r8) + u32::from(b8) < u32::from(g8) {
            n += 1.0;
            sx += (i % w) as f32 + 0.5;
            sy += (i / w) as f32 + 0.5;
        }
    }
    assert!(n >= 3.0, "the marker's image covers {n} pixels of the ball");
    let image = gloss::frame::views::curved_image(marker, c, r, eye);
    let clip =
        scene.camera.projection(w as f32 / h as f32) * scene.camera.view() * image.extend(1.0);
    let ndc = clip.truncate() / clip.w;
    let (px, py) = (
        (ndc.x + 1.0) * 0.5 * w as f32,
        (1.0 - ndc.y) * 0.5 * h as f32,
    );
    let (gx, gy) = (sx / n, sy / n);
    let off = ((gx - px).powi(2) + (gy - py).powi(2)).sqrt();
    assert!(
        off < 1.5,
        "drawn at ({gx:.1}, {gy:.1}), predicted ({px:.1}, {py:.1}): {off:.2} px apart"
    );
}

#[test]
fn a_curved_mirror_must_be_a_sphere() {
    let path = common::root().join("scenes/mirror-curved.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let flat = text.replacen(
        "mesh = \"sphere\"\nposition = [0.0, 0.9, 0.0]",
        "mesh = \"plane\"\nposition = [0.0, 0.9, 0.0]",
        1,
    );
    let e = Scene::parse(&flat, &path).unwrap_err().to_string();
    assert!(e.contains("mirror.curved") && e.contains("sphere"), "{e}");
    let squashed = text.replacen("scale = [0.9, 0.9, 0.9]", "scale = [0.9, 0.5, 0.9]", 1);
    let e = Scene::parse(&squashed, &path).unwrap_err().to_string();
    assert!(e.contains("scaled alike on every axis"), "{e}");
    let plan = gloss::techniques::plan(&Scene::parse(&text, &path).unwrap());
    assert_eq!(plan.views.len(), 2);
    assert!(
        plan.views[1].curved.is_some() && plan.views[1].flip_winding,
        "{plan}"
    );
}
