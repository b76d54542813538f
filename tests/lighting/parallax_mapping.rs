//! Parallax mapping (LearnOpenGL, Parallax Mapping; Tatarchuk 2006:
//! techniques/lighting/parallax_mapping.rs) against the CPU reference
//! `gloss::math::height_field`: the view ray traced through the same height
//! field in f64 (fine steps, then bisection) gives, for each pixel, the uv it
//! hits and whether the first light reaches that point. The pass's debug view
//! (`render.parallax_uv`) writes the uv it found and its verdict. Steep and
//! occlusion parallax stay within their layer's bound, occlusion beats steep,
//! both beat plain parallax at a grazing angle, and the shadow verdicts agree.

use crate::common;
use glam::{DVec2, DVec3, Vec4};
use gloss::math::height_field::HeightMap;
use gloss::renderer::Output;
use gloss::scene::{Parallax, Scene};
use std::f64::consts::TAU;

const TEXELS: usize = 64;
const SCALE: f64 = 0.1;
const SIZE: u32 = 256;
/// Toward the light (world space): 12 degrees above the plane, from +x and -z.
const LIGHT: [f64; 3] = [0.7, 0.21, -0.7];

/// Smooth hills: heights 0.05..0.95 over the 64 x 64 map (whole periods, so it tiles).
fn height(u: f64, v: f64) -> f64 {
    0.5 + 0.25 * (TAU * 2.0 * u).sin() * (TAU * 3.0 * v).cos() + 0.2 * (TAU * (u + 2.0 * v)).sin()
}

/// The map as 8-bit texels (image rows top first), written as a PNG, and
/// the same quantised heights as the CPU reference reads them.
fn height_map() -> (std::path::PathBuf, HeightMap) {
    let n = TEXELS;
    let mut bytes = vec![0u8; n * n];
    for row in 0..n {
        for i in 0..n {
            // Image row 0 is the top: v = 1 - (row + 0.5) / n.
            let (u, v) = (
                (i as f64 + 0.5) / n as f64,
                1.0 - (row as f64 + 0.5) / n as f64,
            );
            bytes[row * n + i] = (height(u, v).clamp(0.0, 1.0) * 255.0).round() as u8;
        }
    }
    let p = common::out_dir().join("parallax-hills.png");
    image::GrayImage::from_raw(n as u32, n as u32, bytes.clone())
        .unwrap()
        .save(&p)
        .unwrap();
    let rows: Vec<f64> = bytes.iter().map(|&b| f64::from(b) / 255.0).collect();
    (p, HeightMap::from_image_rows(n, n, &rows))
}

/// The 2 x 2 plane (u along +x, v along -z) seen from `angle` degrees off
/// its normal, 2.2 units away; the debug view writes the hit uv.
fn scene(map: &std::path::Path, angle: f64, method: Parallax, layers: u32) -> Scene {
    let a = angle.to_radians();
    let (y, z) = (2.2 * a.cos(), 2.2 * a.sin());
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, {y}, {z}]\ntarget = [0.0, 0.0, 0.0]\nfov_y = 40.0\n\
         near = 0.1\nfar = 20.0\n\
         [render]\nsize = [{SIZE}, {SIZE}]\nambient = [0.0, 0.0, 0.0]\nparallax = \"{method}\"\n\
         parallax_layers = {layers}\nparallax_uv = true\n\
         [[lights]]\ntype = \"directional\"\ndirection = [{}, {}, {}]\n\
         [materials.m]\nheight_map = \"{}\"\nheight_scale = {SCALE}\nfilter = \"bilinear\"\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\n",
        -LIGHT[0],
        -LIGHT[1],
        -LIGHT[2],
        map.display()
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// The pixels that see the plane away from its edges: (pixel index, the
/// uv the view ray enters at, the view direction in tangent space).
fn pixels(s: &Scene) -> Vec<(usize, DVec2, DVec3)> {
    let vp = (s.camera.projection(s.aspect()) * s.camera.view()).inverse();
    let eye = s.camera.eye.as_dvec3();
    let mut out = Vec::new();
    for y in (0..SIZE).step_by(2) {
        for x in (0..SIZE).step_by(2) {
            let ndc = |z: f32| {
                let p = vp
                    * Vec4::new(
                        2.0 * (x as f32 + 0.5) / SIZE as f32 - 1.0,
                        2.0 * (y as f32 + 0.5) / SIZE as f32 - 1.0,
                        z,
                        1.0,
                    );
                (p.truncate() / p.w).as_dvec3()
            };
            let (near, far) = (ndc(-1.0), ndc(1.0));
            let d = far - near;
            if d.y >= 0.0 {
                continue;
            }
            let p = near + d * (-near.y / d.y); // on y = 0
            let uv = DVec2::new(p.x / 2.0 + 0.5, 0.5 - p.z / 2.0);
            if !(0.02..0.98).contains(&uv.x) || !(0.02..0.98).contains(&uv.y) {
                continue;
            }
            // Tangent space on this plane: T = +x, B = -z, N = +y.
            let v = (eye - p).normalize();
            out.push(((y * SIZE + x) as usize, uv, DVec3::new(v.x, -v.z, v.y)));
        }
    }
    out
}

/// The shortest uv difference on the torus (the texture repeats).
fn wrapped(a: DVec2, b: DVec2) -> f64 {
    let d = a - b;
    let w = |x: f64| x - x.round();
    DVec2::new(w(d.x), w(d.y)).length()
}

struct Errors {
    /// |uv error| in texels, per pixel.
    texels: Vec<f64>,
    /// The bound for steep parallax, per pixel: one layer's uv shift, in texels.
    layer_bound: Vec<f64>,
    /// The fraction of pixels whose light verdict matches the reference's.
    shadow_agree: f64,
}

impl Errors {
    fn mean(&self) -> f64 {
        self.texels.iter().sum::<f64>() / self.texels.len() as f64
    }
    /// The fraction of pixels within one layer's shift (+ 0.1 texel) of the reference.
    fn within_a_layer(&self) -> f64 {
        let n = (self.texels.iter().zip(&self.layer_bound))
            .filter(|(e, b)| **e <= **b + 0.1)
            .count();
        n as f64 / self.texels.len() as f64
    }
    fn quantile(&self, q: f64) -> f64 {
        let mut v = self.texels.clone();
        v.sort_by(f64::total_cmp);
        v[((v.len() - 1) as f64 * q) as usize]
    }
}

fn measure(
    ctx: &gloss::gl::Headless,
    map: &(std::path::PathBuf, HeightMap),
    angle: f64,
    method: Parallax,
    layers: u32,
) -> Errors {
    let s = scene(&map.0, angle, method, layers);
    let r = common::render_with(ctx, &s, Output::Linear32F);
    let l = DVec3::from(LIGHT).normalize();
    let l_t = DVec3::new(l.x, -l.z, l.y);
    let (mut texels, mut layer_bound, mut agree, mut n) = (vec![], vec![], 0, 0);
    for (i, uv, v_t) in pixels(&s) {
        let px = &r.linear[i * 4..i * 4 + 4];
        let got = DVec2::new(f64::from(px[0]), f64::from(px[1]));
        let hit = map.1.trace(uv, v_t, SCALE);
        texels.push(wrapped(got, hit.uv) * TEXELS as f64);
        let shift = v_t.truncate().length() / v_t.z * SCALE;
        layer_bound.push(shift / f64::from(layers) * TEXELS as f64);
        let lit = map.1.lit(hit, l_t, SCALE);
        agree += usize::from((px[2] > 0.5) == lit);
        n += 1;
    }
    assert!(n > 1500, "only {n} pixels on the plane");
    println!("{angle} deg, {method} {layers}: {n} pixels");
    Errors {
        texels,
        layer_bound,
        shadow_agree: agree as f64 / n as f64,
    }
}

#[test]
fn parallax_uv_against_the_ray_traced_height_field() {
    let ctx = common::context(common::backend());
    let map = height_map();
    let mut table = String::from(
        "| view | method | layers | mean texels | 95% texels | max texels | within a layer | light verdicts agree |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for angle in [45.0, 80.0] {
        let plain = measure(&ctx, &map, angle, Parallax::Plain, 1);
        let mut row = |m: &str, n: u32, e: &Errors| {
            table += &format!(
                "| {angle} deg | {m} | {n} | {:.3} | {:.3} | {:.3} | {:.1} % | {:.1} % |\n",
                e.mean(),
                e.quantile(0.95),
                e.quantile(1.0),
                100.0 * e.within_a_layer(),
                100.0 * e.shadow_agree
            );
        };
        row("plain", 1, &plain);
        for layers in [8, 16, 32, 64, 128] {
            let steep = measure(&ctx, &map, angle, Parallax::Steep, layers);
            let pom = measure(&ctx, &map, angle, Parallax::Occlusion, layers);
            row("steep", layers, &steep);
            row("occlusion", layers, &pom);
            let at = format!("{angle} deg, {layers} layers");
            // Steep parallax's hit is the first layer below the surface: the
            // true hit lies within the last layer's shift, unless the ray
            // skipped a crossing between two layers (a hilltop it grazes,
            // which the rarer the more layers). Interpolating (occlusion)
            // lands closer than steep.
            let skipped = if angle < 60.0 { 0.001 } else { 0.03 };
            assert!(
                steep.within_a_layer() >= 1.0 - skipped,
                "{at}: steep within a layer for {:.2} % of pixels",
                100.0 * steep.within_a_layer()
            );
            assert!(
                pom.mean() < 0.5 * steep.mean(),
                "{at}: occlusion {:.3} texels, steep {:.3}",
                pom.mean(),
                steep.mean()
            );
            // The hard case, the grazing view: every march beats plain
            // parallax, whose one shift ignores the relief along the ray.
            assert!(
                angle < 60.0
                    || steep.mean() < 0.5 * plain.mean()
                        && steep.quantile(0.95) < plain.quantile(0.95),
                "{at}: steep {:.3} texels, plain {:.3}",
                steep.mean(),
                plain.mean()
            );
            if layers >= 32 {
                // Occlusion's interpolated hit: under a fifth of a texel for
                // 95 % of the pixels, even at 80 degrees; the light verdicts
                // from it agree for 95 % (they differ at the shadows' edges).
                assert!(
                    pom.quantile(0.95) < 0.2,
                    "{at}: occlusion 95 % at {:.3} texels",
                    pom.quantile(0.95)
                );
                assert!(
                    pom.shadow_agree > 0.95,
                    "{at}: light verdicts agree for {:.1} %",
                    100.0 * pom.shadow_agree
                );
            }
        }
        assert!(
            plain.shadow_agree < 0.6,
            "{angle} deg: plain agrees too well?"
        );
    }
    println!("{table}");
}

fn parse(render: &str, material: &str) -> Result<Scene, String> {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 2.0, 2.0]\ntarget = [0.0, 0.0, 0.0]\n\
         [render]\nsize = [32, 32]\n{render}\n[materials.m]\n{material}\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).map_err(|e| format!("{e:#}"))
}

#[test]
fn bad_parallax_keys_are_refused_and_unused_height_maps_named() {
    let map = "height_map = \"assets/bricks-height.png\"";
    for (render, material, want) in [
        (
            "",
            &format!("{map}\nheight_scale = 2.0")[..],
            "materials.m.height_scale",
        ),
        (
            "",
            "height_map = \"assets/none.png\"",
            "materials.m.height_map",
        ),
        (
            "parallax_layers = 0",
            map,
            "render.parallax_layers: expected 1..=256",
        ),
        (
            "parallax = \"deep\"",
            map,
            "expected off, plain, steep or occlusion",
        ),
    ] {
        let e = parse(render, material).expect_err(want);
        assert!(e.contains(want), "{want}: {e}");
    }
    // Parallax runs on the forward path with Phong shading; elsewhere the
    // scene says the height map does nothing.
    for render in ["path = \"deferred\"", "shading = \"gouraud\""] {
        let w = parse(render, map).unwrap().warnings().join("\n");
        assert!(
            w.contains("materials.m.height_map has no effect"),
            "{render}: {w}"
        );
    }
    assert!(parse("", map).unwrap().warnings().is_empty());
    let w = parse("parallax = \"steep\"", "")
        .unwrap()
        .warnings()
        .join("\n");
    assert!(w.contains("render.parallax has no effect"), "{w}");
}
