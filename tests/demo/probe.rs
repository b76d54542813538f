//! `gloss probe SCENE X Y` (src/renderer/probe.rs) against CPU twins: the
//! pixel is chosen from the scene's geometry (a world point projected by
//! the scene's camera), and what the probe prints is checked against what
//! the geometry says: the ray through the pixel's centre meets the floor
//! at the world point the depth rebuilds, the floor's normal is (0, 1, 0),
//! the window depth is the projected point's, and a floor point whose ray
//! to the light passes through the ball is in shadow while one whose ray
//! meets nothing is lit.

use glam::{Mat4, Vec3, Vec4};
use gloss::gl::program::Sources;
use gloss::renderer::{Output, Renderer};
use gloss::scene::{Pcf, RenderPath, Scene};
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
    if line.contains(": in shadow at the centre texel") {
        "in shadow"
    } else if line.contains(": lit at the centre texel") {
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

/// A scene of `name` lit by its casting light alone (no ambient, no other
/// light) at 320x180, its filter `pcf` on a 256-texel map, on `path`.
fn lit_by_the_caster(name: &str, pcf: Pcf, path: RenderPath) -> Scene {
    let mut s = crate::common::scene(name);
    s.lights.retain(|l| l.shadow.is_some());
    assert_eq!(s.lights.len(), 1, "{name}: one casting light");
    // A coarse map: its penumbrae span several pixels of the small frame.
    let shadow = s.lights[0].shadow.as_mut().unwrap();
    shadow.pcf = pcf;
    shadow.resolution = 256;
    s.render.ambient = Vec3::ZERO;
    s.render.size = (320, 180);
    s.render.path = path;
    s
}

/// The frame of `scene` as linear floats (bottom row first), and its renderer.
fn linear(ctx: &gloss::gl::Headless, scene: &Scene) -> (Vec<f32>, Renderer) {
    let (w, h) = scene.render.size;
    let mut r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Linear32F,
    )
    .unwrap();
    r.render(&scene.camera).unwrap();
    (r.read_linear(), r)
}

/// At penumbra pixels, the probe's filtered visibility (its PCF redone on
/// the CPU) is the shadow factor the frame applied: the light's value at
/// the pixel with the shadow over the light's value without it (only that
/// light, no ambient, so the ratio is the factor the shader multiplied by).
///
/// On the deferred path, where the probe reads the normal the shader read
/// (the G-buffer's) and rebuilds the point from the same depth. (On the
/// forward path the probe rebuilds the normal from the depths beside the
/// pixel while the shader interpolates the vertices' normal: the normal
/// offset then moves the lookup, and a 3x3 box was seen two taps off at a
/// penumbra pixel of shadows-spot.)
///
/// Bound, per pixel: for the box and disc kernels one tap's share
/// (1/taps) plus 0.02 (the shader's and the CPU's float arithmetic may put
/// one tap on either side of a texel's edge); for the bilinear `hardware`
/// lookup 0.03 (llvmpipe blends its four comparisons with 8-bit weights,
/// 1/256 steps). Mean over the
/// pixels: 0.02. The centre texel's verdict alone (0 or 1) would miss every
/// pixel chosen here by 0.15 at least (they are picked with factors in
/// 0.15..0.85), more than any bound here (the 3x3 box's is 0.131).
#[test]
fn the_filtered_visibility_at_penumbra_pixels_is_the_frames_shadow_factor() {
    let ctx = crate::common::context(crate::common::backend());
    let cases = [
        ("shadows-spot.toml", Pcf::Hardware, RenderPath::Deferred),
        ("shadows-spot.toml", Pcf::Box3, RenderPath::Deferred),
        ("shadows-spot.toml", Pcf::Box5, RenderPath::Deferred),
        ("shadows-spot.toml", Pcf::Poisson, RenderPath::Deferred),
        ("shadows-point.toml", Pcf::Box3, RenderPath::Deferred),
        ("shadows-point.toml", Pcf::Poisson, RenderPath::Deferred),
    ];
    for (name, pcf, path) in cases {
        let scene = lit_by_the_caster(name, pcf, path);
        let mut open = scene.clone();
        open.lights[0].shadow = None;
        let (with, r) = linear(&ctx, &scene);
        let (without, _) = linear(&ctx, &open);
        let (w, h) = scene.render.size;
        // Pixels (from the top left) with a penumbra's factor.
        let mut penumbra = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let i = (((h - 1 - y) * w + x) * 4) as usize;
                let c = (0..3).max_by(|&a, &b| without[i + a].total_cmp(&without[i + b]));
                let c = i + c.unwrap();
                if without[c] > 0.02 {
                    let factor = with[c] / without[c];
                    if (0.15..=0.85).contains(&factor) {
                        penumbra.push((x, y, factor));
                    }
                }
            }
        }
        assert!(
            penumbra.len() >= 10,
            "{name} {pcf:?}: {} penumbra pixels",
            penumbra.len()
        );
        let step = (penumbra.len() / 20).max(1);
        let (mut worst, mut sum, mut n) = (0f32, 0f32, 0);
        for &(x, y, factor) in penumbra.iter().step_by(step) {
            let p = r.probe(&scene.camera, x, y).unwrap();
            let s = (p.shadows.iter().find(|s| s.light == 0)).expect("the light's lookup");
            let bound = match pcf {
                Pcf::Hardware => 0.03,
                _ => 1.0 / s.filtered.taps.max(1) as f32 + 0.02,
            };
            let error = (s.filtered.visibility - factor).abs();
            assert!(
                error <= bound,
                "{name} {pcf:?} {path:?} pixel ({x}, {y}): the frame's factor {factor:.4}, the probe's {:.4} (bound {bound:.3})\n{p}",
                s.filtered.visibility
            );
            worst = worst.max(error);
            sum += error;
            n += 1;
        }
        let mean = sum / n as f32;
        eprintln!("{name} {pcf:?} {path:?}: {n} penumbra pixels, worst {worst:.4}, mean {mean:.4}");
        assert!(mean <= 0.02, "{name} {pcf:?}: mean error {mean}");
    }
}

/// On the tiled path the probe names the pixel's cluster as the shader
/// finds it (its tile from the pixel, its slice from the view depth) and
/// reads that cluster's list from what the tiled pass uploaded this frame;
/// the list is conservative: every light whose radius holds the point is on
/// it, or shaded at every pixel.
#[test]
fn on_the_tiled_path_the_probe_reads_the_pixels_cluster_list() {
    let ctx = crate::common::context(crate::common::backend());
    let mut scene = crate::common::scene("many-lights.toml");
    scene.render.size = (320, 180);
    scene.render.path = RenderPath::Tiled;
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 320, 180).unwrap();
    r.render(&scene.camera).unwrap();
    let (grid, bins) = r.tiled_lists().expect("the tiled pass kept its lists");
    let mut probed = 0;
    for (x, y) in [(160, 120), (40, 150), (300, 170), (200, 100)] {
        let p = r.probe(&scene.camera, x, y).unwrap();
        let (Some(v), Some(world)) = (p.view_position, p.world_position) else {
            continue;
        };
        let t = p.tile.as_ref().expect("a tile on the tiled path");
        // The shader's cluster: gl_FragCoord's tile, the slice of -z.
        let tile = (x / grid.tile_size, (179 - y) / grid.tile_size);
        assert_eq!(t.tile, tile);
        assert_eq!(t.slice, grid.slice_of(-v.z));
        let [offset, count] = bins.clusters[grid.index(tile.0, tile.1, t.slice)];
        let uploaded: Vec<usize> = bins.indices[offset as usize..(offset + count) as usize]
            .iter()
            .map(|&i| i as usize)
            .collect();
        assert_eq!(t.listed, uploaded, "pixel ({x}, {y})");
        let global = bins.indices[..bins.global as usize].iter();
        assert_eq!(t.global, global.map(|&i| i as usize).collect::<Vec<_>>());
        // Conservative: a light whose radius holds the point is listed.
        let mut within = 0;
        for (i, l) in scene.lights.iter().enumerate() {
            let (cutoff, falloff) = (scene.render.cutoff, scene.render.falloff);
            let radius = gloss::frame::lights::model_radius(l, cutoff, falloff);
            if radius.is_some_and(|rad| (world - l.position).length() < rad * 0.999) {
                within += 1;
                assert!(
                    t.listed.contains(&i),
                    "light {i} reaches ({x}, {y}), not listed: {t}"
                );
            }
        }
        // The lights the probe says reach the point are among the lists.
        for i in p.reached.as_ref().unwrap() {
            assert!(t.listed.contains(i) || t.global.contains(i) || t.casters.contains(i));
        }
        assert!(p.to_string().contains("the tiled pass listed"), "{p}");
        eprintln!(
            "({x}, {y}): {within} lights within their radius, {} listed",
            t.listed.len()
        );
        probed += 1;
    }
    assert!(probed >= 2, "most probed pixels show the floor");
}
