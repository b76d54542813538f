//! `gloss probe SCENE X Y` (src/renderer/probe.rs) against CPU twins: the
//! pixel is chosen from the scene's geometry (a world point projected by
//! the scene's camera), and what the probe prints is checked against what
//! the geometry says: the ray through the pixel's centre meets the floor
//! at the world point the depth rebuilds, the floor's normal is (0, 1, 0),
//! the window depth is the projected point's, and a floor point whose ray
//! to the light passes through the ball is in shadow while one whose ray
//! meets nothing is lit.

use glam::{Mat4, Vec3, Vec4};
use std::process::Command;

const GLOSS: &str = env!("CARGO_BIN_EXE_gloss");

/// shadows-directional.toml's camera, light and objects.
const EYE: Vec3 = Vec3::new(0.0, 6.0, 10.0);
const TARGET: Vec3 = Vec3::new(0.0, 0.5, 0.0);
const FOV_Y: f32 = 50.0;
const NEAR: f32 = 0.2;
const FAR: f32 = 60.0;
const SIZE: (u32, u32) = (960, 540);
const LIGHT_DIR: Vec3 = Vec3::new(-0.5, -1.0, -0.35);
/// The ball (a unit sphere scaled by 0.8), and bounding spheres of the box
/// (half-size 0.75, its corners at 0.75 sqrt 3) and the ring (a torus of
/// outer radius 1.5 scaled by 0.9).
const BALL: (Vec3, f32) = (Vec3::new(1.5, 1.2, 0.5), 0.8);
const BOUNDS: [(Vec3, f32); 3] = [
    BALL,
    (Vec3::new(-1.5, 0.75, 0.0), 0.75 * 1.7321),
    (Vec3::new(0.5, 2.2, -2.0), 0.9 * 1.5),
];

/// gluPerspective times gluLookAt, written out.
fn view_projection() -> Mat4 {
    let aspect = SIZE.0 as f32 / SIZE.1 as f32;
    let f = 1.0 / (FOV_Y.to_radians() * 0.5).tan();
    let projection = Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, (FAR + NEAR) / (NEAR - FAR), -1.0),
        Vec4::new(0.0, 0.0, 2.0 * FAR * NEAR / (NEAR - FAR), 0.0),
    );
    let forward = (TARGET - EYE).normalize();
    let side = forward.cross(Vec3::Y).normalize();
    let up = side.cross(forward);
    let view = Mat4::from_cols(
        Vec4::new(side.x, up.x, -forward.x, 0.0),
        Vec4::new(side.y, up.y, -forward.y, 0.0),
        Vec4::new(side.z, up.z, -forward.z, 0.0),
        Vec4::new(-side.dot(EYE), -up.dot(EYE), forward.dot(EYE), 1.0),
    );
    projection * view
}

/// The pixel (from the top left) that world point `p` projects into.
fn pixel_of(p: Vec3) -> (u32, u32) {
    let c = view_projection() * p.extend(1.0);
    let ndc = c.truncate() / c.w;
    let x = (ndc.x + 1.0) * 0.5 * SIZE.0 as f32;
    let y = (1.0 - ndc.y) * 0.5 * SIZE.1 as f32;
    (x.floor() as u32, y.floor() as u32)
}

/// Where the ray through pixel (`x`, `y`)'s centre meets the floor
/// (y = 0), and that point's window depth.
fn floor_hit(x: u32, y: u32) -> (Vec3, f32) {
    let inverse = view_projection().inverse();
    let ndc = |z: f32| {
        Vec4::new(
            2.0 * (x as f32 + 0.5) / SIZE.0 as f32 - 1.0,
            1.0 - 2.0 * (y as f32 + 0.5) / SIZE.1 as f32,
            z,
            1.0,
        )
    };
    let unproject = |v: Vec4| {
        let w = inverse * v;
        w.truncate() / w.w
    };
    let (a, b) = (unproject(ndc(-1.0)), unproject(ndc(1.0)));
    let t = a.y / (a.y - b.y);
    let p = a + (b - a) * t;
    let c = view_projection() * p.extend(1.0);
    (p, (c.z / c.w + 1.0) * 0.5)
}

/// Does the ray from `p` towards the light meet the sphere (`c`, `r`)?
fn ray_meets(p: Vec3, (c, r): (Vec3, f32)) -> bool {
    let to_light = -LIGHT_DIR.normalize();
    let along = (c - p).dot(to_light);
    along > 0.0 && (c - p - to_light * along).length() < r
}

fn probe(x: u32, y: u32, extra: &[&str]) -> String {
    let out = Command::new(GLOSS)
        .args(["--debug", "probe", "shadows-directional"])
        .args([x.to_string(), y.to_string()])
        .args(extra)
        .output()
        .expect("could not run gloss");
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "gloss probe failed:\n{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    text
}

/// The three numbers after `label` in the probe's text.
fn vec_after(text: &str, label: &str) -> Vec3 {
    let line = (text.lines())
        .find(|l| l.trim_start().starts_with(label))
        .unwrap_or_else(|| panic!("no {label:?} in\n{text}"));
    let inner = &line[line.find('(').unwrap() + 1..line.find(')').unwrap()];
    let v: Vec<f32> = inner
        .split(',')
        .map(|s| s.trim().parse().unwrap())
        .collect();
    Vec3::new(v[0], v[1], v[2])
}

fn depth_of(text: &str) -> f32 {
    let line = (text.lines())
        .find(|l| l.trim_start().starts_with("depth:"))
        .unwrap_or_else(|| panic!("no depth in\n{text}"));
    line.trim_start()["depth:".len()..].trim().parse().unwrap()
}

/// The verdict of light 0's shadow lookup.
fn verdict(text: &str) -> &'static str {
    let line = (text.lines())
        .find(|l| l.trim_start().starts_with("shadow of light 0"))
        .unwrap_or_else(|| panic!("no shadow lookup in\n{text}"));
    if line.contains(": in shadow (") {
        "in shadow"
    } else if line.contains(": lit (") {
        "lit"
    } else {
        panic!("no verdict in {line}")
    }
}

/// A floor point in front of every object, lit: its ray to the light
/// meets none of their bounding spheres.
const OPEN_FLOOR: Vec3 = Vec3::new(-0.5, 0.0, 3.5);

#[test]
fn a_floor_pixel_rebuilds_its_point_and_normal_on_both_paths() {
    let (x, y) = pixel_of(OPEN_FLOOR);
    let (hit, depth) = floor_hit(x, y);
    for (path, normal_tolerance) in [("deferred", 1e-3), ("forward", 5e-3)] {
        let text = probe(x, y, &["--path", path]);
        let p = vec_after(&text, "world position:");
        assert!(
            (p - hit).length() < 2e-3 * (hit - EYE).length(),
            "{path}: the probe rebuilt {p}, the ray meets the floor at {hit}\n{text}"
        );
        let n = vec_after(&text, "normal:");
        assert!(
            (n - Vec3::Y).length() < normal_tolerance,
            "{path}: the floor's normal is {n}\n{text}"
        );
        let d = depth_of(&text);
        assert!(
            (d - depth).abs() < 2e-5,
            "{path}: depth {d}, the projected point's {depth}\n{text}"
        );
    }
}

#[test]
fn the_floor_under_the_ball_is_in_shadow_and_the_open_floor_lit() {
    // The ball's centre taken along the light to the floor: the ray from
    // there to the light passes through the ball's centre.
    let (c, _) = BALL;
    let d = LIGHT_DIR;
    let under = c - d * (c.y / d.y);
    assert!(ray_meets(under, BALL));
    assert!(BOUNDS.iter().all(|&b| !ray_meets(OPEN_FLOOR, b)));
    for (point, expected) in [(under, "in shadow"), (OPEN_FLOOR, "lit")] {
        let (x, y) = pixel_of(point);
        let text = probe(x, y, &[]);
        // The pixel shows the floor there (nothing in front of it).
        let p = vec_after(&text, "world position:");
        assert!(
            (p - point).length() < 0.05,
            "pixel ({x}, {y}) shows {p}, not the floor point {point}\n{text}"
        );
        assert_eq!(verdict(&text), expected, "at {point}:\n{text}");
    }
}

#[test]
fn a_pixel_outside_the_frame_is_refused_with_the_frame_size() {
    let out = Command::new(GLOSS)
        .args(["probe", "shadows-directional", "960", "0"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("(960, 0)") && err.contains("960x540"), "{err}");
}
