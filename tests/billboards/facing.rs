//! Which way billboards turn, checked on the pixels: a spherical billboard
//! lies in the image plane, so under any camera it is an axis-aligned
//! rectangle whose size is its size projected at its depth; a cylindrical
//! one stays upright, foreshortened by the camera's pitch. And the CPU sort.

use crate::{bounds, common, lit_pixels, solid_sprite, temp_dir};
use glam::{Vec2, Vec3};
use gloss::renderer::Output;
use gloss::scene::{Billboard, BillboardKind, Scene};
use gloss::techniques::billboards::billboards::back_to_front;

/// A scene with one billboard of a solid white sprite, unlit (ambient 1) on black.
fn one_billboard(test: &str, camera: &str, kind: &str, center: [f32; 3], size: [f32; 2]) -> Scene {
    let dir = temp_dir(test);
    solid_sprite(&dir, "white.png", 8, 8);
    let text = format!(
        r#"
[camera]
{camera}

[render]
size = [200, 200]
ambient = [1.0, 1.0, 1.0]
background = [0.0, 0.0, 0.0]

[[billboards]]
sprite = "white.png"
center = {center:?}
size = {size:?}
kind = "{kind}"
"#
    );
    Scene::parse(&text, &dir.join("scene.toml")).expect("scene loads")
}

/// Every lit pixel fills its bounding box: an axis-aligned rectangle. Returns its size.
fn rectangle(name: &str, img: &image::RgbaImage) -> (u32, u32) {
    let lit = lit_pixels(img);
    let (x0, x1, y0, y1) = bounds(&lit);
    let (w, h) = (x1 - x0 + 1, y1 - y0 + 1);
    assert_eq!(
        lit.len() as u32,
        w * h,
        "{name}: the lit pixels do not fill their {w}x{h} bounding box: not an axis-aligned rectangle"
    );
    (w, h)
}

#[test]
fn a_spherical_billboard_is_a_screen_rectangle_of_the_predicted_size() {
    // A camera turned and tilted, the billboard off the view axis: a quad
    // that did not face the camera would be a skewed quadrilateral.
    let camera = r#"eye = [3.0, 4.0, 9.0]
target = [0.0, 0.0, 0.0]
fov_y = 60.0"#;
    let (center, size) = ([1.0, 0.5, -1.0], [2.0, 1.5]);
    let scene = one_billboard("spherical", camera, "spherical", center, size);
    let r = common::render(&scene, Output::Srgb8);
    let (w, h) = rectangle("spherical", &r.image);
    // Predicted: the corners centre +- size/2 in view space, projected.
    let view = scene.camera.view();
    let proj = scene.camera.projection(1.0);
    let c = view.transform_point3(Vec3::from(center));
    let px = |p: Vec3| {
        let ndc = proj.project_point3(p);
        Vec2::new((ndc.x + 1.0) * 100.0, (ndc.y + 1.0) * 100.0)
    };
    let s = Vec2::from(size) * 0.5;
    let lo = px(c - s.extend(0.0));
    let hi = px(c + s.extend(0.0));
    let (pw, ph) = (hi.x - lo.x, hi.y - lo.y);
    eprintln!("spherical: {w}x{h} pixels, predicted {pw:.2}x{ph:.2}");
    // Rasterisation covers a pixel whose centre is inside: within 1 pixel.
    assert!((w as f32 - pw).abs() <= 1.0, "width {w}, predicted {pw}");
    assert!((h as f32 - ph).abs() <= 1.0, "height {h}, predicted {ph}");
}

#[test]
fn a_cylindrical_billboard_stays_upright_and_a_spherical_one_does_not() {
    // An orthographic camera looking down at 60 degrees, 50 pixels a unit.
    let pitch = 60f32.to_radians();
    let camera = format!(
        r#"projection = "orthographic"
eye = [0.0, {:.6}, {:.6}]
target = [0.0, 0.0, 0.0]
half_height = 2.0
near = 1.0
far = 30.0"#,
        10.0 * pitch.sin(),
        10.0 * pitch.cos()
    );
    let size = [2.0, 2.0];
    let spherical = one_billboard("cyl-s", &camera, "spherical", [0.0; 3], size);
    let cylindrical = one_billboard("cyl-c", &camera, "cylindrical", [0.0; 3], size);
    let (sw, sh) = rectangle(
        "spherical",
        &common::render(&spherical, Output::Srgb8).image,
    );
    let (cw, ch) = rectangle(
        "cylindrical",
        &common::render(&cylindrical, Output::Srgb8).image,
    );
    eprintln!("spherical {sw}x{sh}, cylindrical {cw}x{ch}");
    // Facing the camera: the full 2 x 2 units = 100 x 100 pixels.
    assert!(sw.abs_diff(100) <= 1 && sh.abs_diff(100) <= 1);
    // Upright: its height is seen at cos(60°) = 1/2, its width in full.
    assert!(cw.abs_diff(100) <= 1, "cylindrical width {cw}");
    assert!(
        ch.abs_diff(50) <= 1,
        "cylindrical height {ch}, expected 2 x 50 x cos 60° = 50"
    );
}

fn at(z: f32) -> Billboard {
    Billboard {
        center: Vec3::new(0.0, 0.0, z),
        size: Vec2::ONE,
        sprite: 0,
        kind: BillboardKind::Spherical,
    }
}

#[test]
fn back_to_front_draws_the_farthest_first() {
    let b = [at(-1.0), at(-5.0), at(-3.0), at(2.0)];
    // Looking down -z from z = 10: farthest is z = -5.
    let view = gloss::math::look_at(Vec3::new(0.0, 0.0, 10.0), Vec3::ZERO, Vec3::Y);
    assert_eq!(back_to_front(&b, &view), vec![1, 2, 0, 3]);
    // From the other side the order reverses.
    let view = gloss::math::look_at(Vec3::new(0.0, 0.0, -10.0), Vec3::ZERO, Vec3::Y);
    assert_eq!(back_to_front(&b, &view), vec![3, 0, 2, 1]);
    // Equal depths keep the scene's order; sideways offsets do not count.
    let mut side = at(-2.0);
    side.center.x = 5.0;
    let b = [at(-2.0), side, at(-4.0)];
    let view = gloss::math::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), Vec3::Y);
    assert_eq!(back_to_front(&b, &view), vec![2, 0, 1]);
    assert!(back_to_front(&[], &view).is_empty());
}

#[test]
fn each_billboard_shows_its_own_sprite_from_the_sheet() {
    // Two sprites of different sizes (the second is resized to the first's
    // size in the sheet): white 8x8 on the left, red 4x16 on the right.
    let dir = temp_dir("two-sprites");
    solid_sprite(&dir, "white.png", 8, 8);
    image::RgbaImage::from_pixel(4, 16, image::Rgba([255, 0, 0, 255]))
        .save(dir.join("red.png"))
        .unwrap();
    let text = r#"
[camera]
projection = "orthographic"
eye = [0.0, 0.0, 10.0]
target = [0.0, 0.0, 0.0]
half_height = 2.0
near = 1.0
far = 20.0

[render]
size = [200, 100]
ambient = [1.0, 1.0, 1.0]

[[billboards]]
sprite = "white.png"
center = [-2.0, 0.0, 0.0]
size = [1.0, 1.0]

[[billboards]]
sprite = "red.png"
center = [2.0, 0.0, 0.0]
size = [1.0, 1.0]
"#;
    let scene = Scene::parse(text, &dir.join("scene.toml")).unwrap();
    assert_eq!(scene.sprites.len(), 2);
    let img = common::render(&scene, Output::Srgb8).image;
    // 25 pixels a unit: the quads are 25x25 about x = 50 and x = 150.
    let (left, right) = (img.get_pixel(50, 50).0, img.get_pixel(150, 50).0);
    assert_eq!(left[..3], [255, 255, 255], "left billboard: {left:?}");
    assert_eq!(right[..3], [255, 0, 0], "right billboard: {right:?}");
    // Each is one solid rectangle of its own colour, no neighbour bled in.
    for (x0, colour) in [(38u32, [255u8, 255, 255]), (138, [255, 0, 0])] {
        for y in 40..60 {
            for x in x0..x0 + 24 {
                let p = img.get_pixel(x, y).0;
                assert!(
                    p[..3] == colour || x == x0 || x == x0 + 23,
                    "pixel ({x}, {y}) is {p:?}, expected {colour:?}"
                );
            }
        }
    }
    assert_eq!(lit_pixels(&img).len().abs_diff(2 * 25 * 25), 0);
}
