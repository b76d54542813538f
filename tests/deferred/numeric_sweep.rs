//! A sweep of the scene's numeric keys to their limits: for each key, the
//! values 0, a denormal, 1e-30, 1e30, f32::MAX and negatives, through every
//! render path. The outcome is either a clear error naming the key, or
//! images on which every path agrees with forward within DEFERRED_BOUND
//! (the light volumes with a cutoff of 1e-6, where they are within 1/255 of
//! full-screen lighting), with no NaN or inf in the float output.

use crate::DEFERRED_BOUND;
use crate::common;
use gloss::image_compare::compare_rgba8;
use gloss::lighting::srgb_encode;
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene};
use image::RgbaImage;
use std::path::Path;

/// A plane and a sphere; a point, a spot and a directional light; seen in
/// perspective. Every key the sweep changes is written here.
const SCENE: &str = r#"
name = "sweep"
[camera]
eye = [0.0, 4.0, 6.0]
target = [0.0, 0.5, 0.0]
fov_y = 45.0
near = 0.1
far = 50.0
[render]
size = [48, 36]
ambient = [0.05, 0.05, 0.05]
cutoff = 1e-6
[[lights]]
type = "point"
position = [1.0, 1.5, 0.5]
color = [1.0, 0.9, 0.8]
intensity = 1.5
attenuation = [1.0, 0.09, 0.032]
[[lights]]
type = "spot"
position = [-1.5, 3.0, 1.0]
direction = [0.4, -1.0, -0.2]
color = [0.6, 0.7, 1.0]
intensity = 2.0
attenuation = [1.0, 0.09, 0.032]
inner_angle = 15.0
outer_angle = 25.0
[[lights]]
type = "directional"
direction = [-0.3, -1.0, -0.4]
color = [0.3, 0.3, 0.25]
intensity = 1.0
[materials.floor]
diffuse = [0.7, 0.5, 0.3]
specular = [0.5, 0.5, 0.5]
shininess = 24.0
[materials.ball]
diffuse = [0.2, 0.4, 0.8]
specular = [0.8, 0.8, 0.8]
shininess = 64.0
[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [10.0, 1.0, 10.0]
[[objects]]
name = "ball"
mesh = "sphere"
material = "ball"
position = [0.0, 0.7, 0.0]
scale = [0.7, 0.7, 0.7]
"#;

/// The keys swept, each with how a value is written for it (`{}` the value).
const KEYS: &[(&str, &str)] = &[
    ("camera.near", "{}"),
    ("camera.far", "{}"),
    ("camera.fov_y", "{}"),
    ("camera.eye", "[0.0, {}, 6.0]"),
    ("render.ambient", "[{}, {}, {}]"),
    ("render.cutoff", "{}"),
    ("lights[0].intensity", "{}"),
    ("lights[0].color", "[{}, 0.9, 0.8]"),
    ("lights[0].position", "[1.0, {}, 0.5]"),
    ("lights[0].attenuation", "[{}, 0.09, 0.032]"),
    ("lights[0].attenuation", "[0.0, {}, 0.032]"),
    ("lights[0].attenuation", "[0.0, 0.0, {}]"),
    ("lights[1].inner_angle", "{}"),
    ("lights[1].outer_angle", "{}"),
    ("lights[1].direction", "[{}, -1.0, -0.2]"),
    ("lights[2].intensity", "{}"),
    ("lights[2].direction", "[-0.3, {}, -0.4]"),
    ("materials.floor.diffuse", "[{}, 0.5, 0.3]"),
    ("materials.ball.specular", "[{}, 0.8, 0.8]"),
    ("materials.ball.shininess", "{}"),
    ("objects[1].scale", "[{}, 0.7, 0.7]"),
    ("objects[1].scale", "[{}, {}, {}]"),
    ("objects[1].position", "[0.0, {}, 0.0]"),
    ("objects[1].rotation", "[{}, 0.0, 0.0]"),
];

/// At and near the limits of an f32.
const VALUES: &[&str] = &[
    "0.0",
    "1e-45",
    "1e-38",
    "1e-30",
    "1e-7",
    "1e30",
    "3.4028235e38",
    "-1.0",
    "-1e30",
];

/// The float output as an 8-bit sRGB image, after checking that every
/// channel is finite.
fn finite_image(linear: &[f32], w: u32, h: u32, what: &str) -> RgbaImage {
    let bad = linear.iter().position(|v| !v.is_finite());
    assert!(
        bad.is_none(),
        "{what}: a NaN or inf reaches the output: {} at channel {}",
        linear[bad.unwrap_or(0)],
        bad.unwrap_or(0)
    );
    let mut img = RgbaImage::new(w, h);
    for (i, p) in img.pixels_mut().enumerate() {
        // Bottom row first in `linear`; the comparison does not care.
        let c = &linear[i * 4..i * 4 + 4];
        let e = |v: f32| (srgb_encode(v) * 255.0).round() as u8;
        *p = image::Rgba([e(c[0]), e(c[1]), e(c[2]), 255]);
    }
    img
}

#[test]
fn every_numeric_key_at_its_limits_is_refused_or_agrees_on_every_path() {
    let ctx = common::context(common::backend());
    let (mut refused, mut drawn) = (0, 0);
    for &(key, form) in KEYS {
        for &v in VALUES {
            let set = format!("{key}={}", form.replace("{}", v));
            let what = format!("--set {set}");
            let scene =
                match Scene::parse_with(SCENE, Path::new("sweep.toml"), std::slice::from_ref(&set))
                {
                    Ok(s) => s,
                    Err(e) => {
                        let msg = format!("{e:#}");
                        // It names the key, or the table it is in ("camera.up:
                        // must not be parallel to the view direction").
                        let table = key.rsplit_once('.').unwrap().0;
                        assert!(
                            msg.contains(table),
                            "{what}: the error does not name the key: {msg}"
                        );
                        assert!(msg.len() < 2100, "{what}: {} characters", msg.len());
                        refused += 1;
                        continue;
                    }
                };
            let mut images = Vec::new();
            for &path in RenderPath::ALL {
                let mut s = scene.clone();
                s.render.path = path;
                let r = match render_scene(&ctx, &s, Output::Linear32F) {
                    Ok(r) => r,
                    Err(e) => panic!("{what}: loads but {path} cannot render it: {e:#}"),
                };
                let (w, h) = s.render.size;
                let img = finite_image(&r.read_linear(), w, h, &format!("{what} on {path}"));
                images.push((path, img));
            }
            let forward = images[0].1.clone();
            for (path, img) in &images[1..] {
                // A swept cutoff is the volumes' own bound: only finiteness.
                if key == "render.cutoff"
                    && matches!(path, RenderPath::Volumes | RenderPath::Prepass)
                {
                    continue;
                }
                let m = compare_rgba8(img, &forward, DEFERRED_BOUND.threshold).unwrap();
                assert!(
                    DEFERRED_BOUND.accepts(&m),
                    "{what}: {path} differs from forward: {m}"
                );
            }
            drawn += 1;
        }
    }
    eprintln!("numeric sweep: {refused} refused, {drawn} drawn on every path and agreeing");
    assert!(refused > 0 && drawn > 0);
}
