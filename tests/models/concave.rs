//! Concave faces (src/geometry/polygons.rs): one OBJ face shaped as a ring
//! (outer square 0..4, hole 1..3, joined by a slit, as exporters write a
//! face with a hole) and one shaped as a C. A fan from the first corner
//! (tobj's triangulation) fills the hole and the notch; ear clipping must
//! leave them showing the background.

use crate::common;
use crate::{temp_dir, write};
use gloss::renderer::Output;
use gloss::scene::Scene;

const RING_AND_C: &str = "# a ring: outer square, slit at x = 1, inner square backwards
v 1 1 0
v 1 0 0
v 4 0 0
v 4 4 0
v 0 4 0
v 0 0 0
v 1 0 0
v 1 1 0
v 1 3 0
v 3 3 0
v 3 1 0
# a C, 3 x 3 at x = 5..8, its notch x = 6..8, y = 1..2 open to the right
v 5 0 0
v 8 0 0
v 8 1 0
v 6 1 0
v 6 2 0
v 8 2 0
v 8 3 0
v 5 3 0
vn 0 0 1
f 1//1 2//1 3//1 4//1 5//1 6//1 7//1 8//1 9//1 10//1 11//1
f 12//1 13//1 14//1 15//1 16//1 17//1 18//1 19//1
";

#[test]
fn a_ring_and_a_c_keep_their_hole_and_notch() {
    let dir = temp_dir("concave");
    write(&dir, "faces.obj", RING_AND_C);
    // x from -0.5 to 8.5 over 90 pixels: 10 pixels a unit; y likewise.
    let text = r#"
[camera]
projection = "orthographic"
eye = [4.0, 2.0, 5.0]
target = [4.0, 2.0, 0.0]
up = [0.0, 1.0, 0.0]
half_height = 2.5
near = 1.0
far = 10.0

[render]
size = [90, 50]
ambient = [1.0, 1.0, 1.0]
background = [0.0, 0.0, 1.0]

[[objects]]
mesh = "faces.obj"
"#;
    let s = Scene::parse(text, &dir.join("scene.toml")).expect("scene loads");
    let r = common::render(&s, Output::Srgb8);
    // (x, y) in world units -> the pixel, y counted from the top.
    let at = |x: f32, y: f32| {
        let p = r
            .image
            .get_pixel((x * 10.0 + 5.0) as u32, ((4.5 - y) * 10.0) as u32);
        p.0[2] > 200 && p.0[0] < 50 // the blue background
    };
    assert!(at(2.0, 2.0), "the ring's hole is filled");
    assert!(
        at(1.5, 1.5) && at(2.5, 2.5),
        "the ring's hole is partly filled"
    );
    assert!(
        !at(0.5, 2.0) && !at(3.5, 2.0) && !at(2.0, 0.5) && !at(2.0, 3.5),
        "the ring is missing"
    );
    assert!(at(7.0, 1.5), "the C's notch is filled");
    assert!(
        !at(5.5, 1.5) && !at(7.0, 0.5) && !at(7.0, 2.5),
        "the C is missing"
    );
}
