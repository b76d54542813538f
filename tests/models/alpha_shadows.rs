//! Alpha-tested shadows (notes 05 "Alpha Test" with notes 01 §8.5): a quad
//! whose texture's alpha ramps from 0 at u = 0 to 1 at u = 1, alpha-tested
//! at 0.5 (an MTL map_Kd with alpha), hangs at y = 1 over a floor. The
//! test keeps the half x > 0, so the eye sees the quad on 0 < x < 1 and
//! its shadow, thrown sideways by a light at (2, 3, 0) (or a directional
//! light along (-1, -1, 0)), falls on -1 < x < 0: the cut edge x = 0 lands
//! at x = -1 for all three lights. A shadow pass without the alpha test
//! would cast the whole quad, darkening -2 < x < -1 too (-2.5 for the
//! lights at a point). The floor is also checked against the ray-traced
//! shadow reference (src/lighting/shadow_reference/cutouts.rs), which runs
//! the same alpha test on the CPU.

use crate::common;
use crate::{linear_at, temp_dir, write};
use gloss::lighting::shadow_reference::{LightRay, SceneTriangles};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::Path;

const QUAD: &str = "mtllib leaf.mtl
v -1 0 1
v 1 0 1
v 1 0 -1
v -1 0 -1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 1 0
usemtl leaf
f 1/1/1 2/2/1 3/3/1 4/4/1
";

fn scene(dir: &Path, light: &str) -> Scene {
    let text = format!(
        r#"
[camera]
projection = "orthographic"
eye = [0.0, 10.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
half_height = 3.0
near = 1.0
far = 20.0

[render]
size = [96, 96]
ambient = [0.1, 0.1, 0.1]

{light}

[materials.floor]
diffuse = [0.8, 0.8, 0.8]
specular = [0.0, 0.0, 0.0]

[[objects]]
name = "floor"
mesh = "plane"
material = "floor"
scale = [3.0, 1.0, 3.0]

[[objects]]
name = "leaf"
mesh = "leaf.obj"
position = [0.0, 1.0, 0.0]
"#
    );
    Scene::parse(&text, &dir.join("scene.toml")).expect("scene loads")
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Seen {
    Quad,
    Shadow,
    Lit,
}

fn seen(c: [f32; 3]) -> Seen {
    if c[0] > 0.15 && c[0] > 3.0 * c[1] {
        Seen::Quad
    } else if c[1] < 0.12 {
        Seen::Shadow
    } else {
        Seen::Lit
    }
}

/// What column `x` (world) should show: the kept half of the quad, the
/// shadow of its kept half, or lit floor.
fn predicted(x: f32) -> Seen {
    if (0.0..1.0).contains(&x) {
        Seen::Quad
    } else if (-1.0..0.0).contains(&x) {
        Seen::Shadow
    } else {
        Seen::Lit
    }
}

#[test]
fn an_alpha_cutoff_splits_the_quad_and_its_shadow_at_the_predicted_column() {
    let dir = temp_dir("alpha-shadows");
    write(&dir, "leaf.obj", QUAD);
    write(
        &dir,
        "leaf.mtl",
        "newmtl leaf\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd ramp.png\n",
    );
    let ramp = image::RgbaImage::from_fn(256, 4, |x, _| image::Rgba([255, 0, 0, x as u8]));
    ramp.save(dir.join("ramp.png")).unwrap();
    let directional =
        "[[lights]]\ntype = \"directional\"\ndirection = [-1.0, -1.0, 0.0]\nshadow = true";
    let spot = "[[lights]]\ntype = \"spot\"\nposition = [2.0, 3.0, 0.0]\ndirection = [-2.75, -3.0, 0.0]\nattenuation = [1.0, 0.0, 0.0]\ninner_angle = 60.0\nouter_angle = 70.0\nshadow = true";
    let point = |cube: &str| {
        format!(
            "[[lights]]\ntype = \"point\"\nposition = [2.0, 3.0, 0.0]\nattenuation = [1.0, 0.0, 0.0]\nshadow = {{ cube = \"{cube}\" }}"
        )
    };
    let ctx = common::context(common::backend());
    let cases = [
        ("directional", directional.to_string()),
        ("spot", spot.to_string()),
        ("point, six passes", point("six_passes")),
        ("point, geometry shader", point("geometry_shader")),
    ];
    for (name, light) in &cases {
        let s = scene(&dir, light);
        let leaf = s
            .materials
            .iter()
            .find(|m| m.name == "leaf.obj/leaf")
            .unwrap();
        assert_eq!(
            leaf.alpha_test,
            gloss::scene::AlphaTest::Gequal,
            "an alpha channel is a cut-out"
        );
        let occluders = SceneTriangles::new(&s).unwrap();
        for path in RenderPath::ALL {
            let mut s = s.clone();
            s.render.path = *path;
            let r = common::render_with(&ctx, &s, Output::Linear32F);
            let mut wrong = Vec::new();
            // Row 44 looks at z = -0.22, inside the quad and every shadow.
            for c in 0..96 {
                let x = (c as f32 + 0.5) / 16.0 - 3.0;
                // 1.5 pixels either side of an edge may go either way.
                let near_edge = [-1.0f32, 0.0, 1.0]
                    .iter()
                    .any(|e| (x - e).abs() < 1.5 / 16.0);
                let got = seen(linear_at(&r, c, 44));
                if !near_edge && got != predicted(x) {
                    wrong.push(format!(
                        "column {c} (x = {x:.2}): {got:?}, expected {:?}",
                        predicted(x)
                    ));
                }
            }
            assert!(wrong.is_empty(), "{name}, {path}:\n{}", wrong.join("\n"));
            // The same floor against the ray-traced reference, which runs
            // the leaf's alpha test at each hit (an independent answer to
            // the hand prediction above).
            let ray = LightRay::of(&s.lights[0]);
            for c in 0..96 {
                let x = (c as f32 + 0.5) / 16.0 - 3.0;
                let near_edge = [-1.0f32, 0.0, 1.0]
                    .iter()
                    .any(|e| (x - e).abs() < 1.5 / 16.0);
                if near_edge || predicted(x) == Seen::Quad {
                    continue;
                }
                let p = glam::Vec3::new(x, 0.0, -0.22);
                let want = if occluders.occluded(p, ray) {
                    Seen::Shadow
                } else {
                    Seen::Lit
                };
                let got = seen(linear_at(&r, c, 44));
                assert_eq!(
                    got, want,
                    "{name}, {path}: column {c} (x = {x:.2}) against the reference"
                );
            }
        }
    }
}
