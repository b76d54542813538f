//! Notes 01 §3.3, user clip planes (src/scene/clip_planes.rs,
//! glsl/common/view.glsl `write_clip_distances`): a plane removes what lies
//! on its far side, several planes keep only what every one keeps, on the
//! forward and deferred paths alike; the planes are checked, and GL's
//! GL_MAX_CLIP_DISTANCES is reported.

use crate::common;
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

/// A unit cube (side 2) seen straight on from +z, lit, with `planes`.
fn cube(planes: &str, path: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.0, 6.0]\ntarget = [0.0, 0.0, 0.0]\nfov_y = 40.0\n\
         [render]\nsize = [160, 120]\npath = \"{path}\"\nbackground = [0.0, 0.0, 1.0]\nambient = [1.0, 1.0, 1.0]\n\
         [materials.red]\ndiffuse = [1.0, 0.0, 0.0]\nspecular = [0.0, 0.0, 0.0]\n\
         [[objects]]\nmesh = \"cube\"\nmaterial = \"red\"\n{planes}"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

const KEEP_LEFT: &str = "[[clip_planes]]\nnormal = [-1.0, 0.0, 0.0]\n";
const KEEP_LOW: &str = "[[clip_planes]]\nnormal = [0.0, -1.0, 0.0]\npoint = [0.0, 0.0, 0.0]\n";

fn is_cube(p: &image::Rgba<u8>) -> bool {
    p[0] > 200 && p[2] < 50
}
fn is_background(p: &image::Rgba<u8>) -> bool {
    p[0] < 50 && p[2] > 200
}

#[test]
fn each_plane_removes_its_far_side_and_several_keep_what_all_keep() {
    for path in ["forward", "deferred"] {
        let whole = common::render(&cube("", path), Output::Srgb8).image;
        let left = common::render(&cube(KEEP_LEFT, path), Output::Srgb8).image;
        let quarter = common::render(
            &cube(&format!("{KEEP_LEFT}{KEEP_LOW}"), path),
            Output::Srgb8,
        )
        .image;
        // The cube covers the middle; four points in its four quarters
        // (image y grows downwards).
        let (cx, cy, d) = (80, 60, 15);
        let [ul, ur, ll, lr] = [
            (cx - d, cy - d),
            (cx + d, cy - d),
            (cx - d, cy + d),
            (cx + d, cy + d),
        ];
        for &(x, y) in &[ul, ur, ll, lr] {
            assert!(is_cube(whole.get_pixel(x, y)), "{path}: the cube is whole");
        }
        // x > 0 is cut: the right half shows the background (the cube's
        // inside faces away, and back faces are culled).
        assert!(
            is_cube(left.get_pixel(ul.0, ul.1)) && is_cube(left.get_pixel(ll.0, ll.1)),
            "{path}"
        );
        assert!(
            is_background(left.get_pixel(ur.0, ur.1)) && is_background(left.get_pixel(lr.0, lr.1)),
            "{path}"
        );
        // And y > 0: only the lower left quarter is left.
        assert!(is_cube(quarter.get_pixel(ll.0, ll.1)), "{path}");
        for &(x, y) in &[ul, ur, lr] {
            assert!(is_background(quarter.get_pixel(x, y)), "{path}: ({x}, {y})");
        }
    }
}

#[test]
fn the_cross_section_is_the_same_forward_and_deferred() {
    let s = common::scene("cross-section.toml");
    assert_eq!(s.clip_planes.len(), 2);
    let mut small = s.clone();
    small.render.size = (320, 180);
    let forward = common::render(&small, Output::Srgb8).image;
    small.render.path = RenderPath::Deferred;
    let deferred = common::render(&small, Output::Srgb8).image;
    let tol = Tolerance {
        threshold: 2.0 / 255.0,
        max_frac_over: 0.002,
        max_abs: None,
    };
    let m = common::assert_close("cross-section-deferred", &deferred, &forward, &tol);
    eprintln!("cross-section, deferred vs forward: {m}");
    // The planes cut something: without them the image differs.
    small.render.path = RenderPath::Forward;
    small.clip_planes.clear();
    let whole = common::render(&small, Output::Srgb8).image;
    let d = gloss::image_compare::compare_rgba8(&whole, &forward, 8.0 / 255.0).unwrap();
    assert!(d.frac_over > 0.05, "{d}");
}

#[test]
fn clip_planes_are_checked_and_the_limit_is_reported() {
    let parse = |planes: &str| {
        let text = format!(
            "name = \"t\"\n[camera]\neye = [0.0, 0.0, 6.0]\ntarget = [0.0, 0.0, 0.0]\n{planes}"
        );
        Scene::parse(&text, &common::root().join("scenes/t.toml")).map(|_| ())
    };
    let e = format!("{:#}", parse(&KEEP_LEFT.repeat(8)).unwrap_err());
    assert!(e.contains("clip_planes: 8 planes, at most 7"), "{e}");
    assert!(parse(&KEEP_LEFT.repeat(7)).is_ok());
    let e = format!(
        "{:#}",
        parse("[[clip_planes]]\nnormal = [0.0, 0.0, 0.0]\n").unwrap_err()
    );
    assert!(e.contains("clip_planes[0].normal: must not be zero"), "{e}");
    let e = format!(
        "{:#}",
        parse("[[clip_planes]]\nnormal = [1.0, 0.0, 0.0]\nside = 1\n").unwrap_err()
    );
    assert!(e.contains("unknown field `side`"), "{e}");
    let ctx = common::context(common::backend());
    assert!(ctx.info.max_clip_distances >= 8, "GL 3.3 promises 8");
    assert!(
        ctx.info
            .to_string()
            .contains(&format!("clip distances {}", ctx.info.max_clip_distances))
    );
}
