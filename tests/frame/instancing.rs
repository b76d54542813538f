//! Instancing (LearnOpenGL, Instancing; src/techniques/vertex_geometry/instancing.rs):
//!
//! * one glDrawElementsInstanced gives the image of one draw per rock,
//!   pixel for pixel, on the shipped scene's 100 000 rocks and on every path;
//! * each instance k lands where its model matrix, projected on the CPU,
//!   says: the rock's pixels around the projected centre lie within the
//!   projected radius of its bounding sphere, and the centre pixel is lit;
//! * the plan has no pass without [instancing]; bad fields are errors.

use crate::common;
use glam::{Vec3, Vec4Swizzles};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};
use std::path::Path;

fn field_scene(path: RenderPath, extra: &str) -> Scene {
    let text = format!(
        r#"
name = "instancing test"
[camera]
eye = [0.0, 14.0, 14.0]
target = [0.0, 0.0, 0.0]
fov_y = 50.0
near = 0.5
far = 60.0
[render]
path = "{}"
size = [320, 240]
ambient = [0.2, 0.2, 0.2]
background = [0.0, 0.0, 0.0]
{extra}
[instancing]
count = 24
seed = 3
radius = 8.0
offset = 0.0
scale = [0.35, 0.6]
color = [0.8, 0.7, 0.6]
[[lights]]
type = "directional"
direction = [0.0, -1.0, 0.0]
color = [1.0, 1.0, 1.0]
"#,
        path.name()
    );
    Scene::parse(&text, Path::new("instancing-test.toml")).unwrap()
}

#[test]
fn one_instanced_draw_is_the_image_of_one_draw_per_rock() {
    let ctx = common::context(common::backend());
    let mut shipped = common::scene("instancing.toml");
    shipped.render.size = (320, 180);
    let mut cases = vec![shipped];
    for &path in RenderPath::ALL {
        cases.push(field_scene(path, ""));
    }
    for s in cases {
        assert!(s.render.instancing);
        let a = common::render_with(&ctx, &s, Output::Srgb8).image;
        let mut per_rock = s.clone();
        per_rock.render.instancing = false;
        let b = common::render_with(&ctx, &per_rock, Output::Srgb8).image;
        let lit = a.pixels().filter(|p| p[0] > 30).count();
        assert!(
            lit > 500,
            "{} ({}): only {lit} lit pixels",
            s.name,
            s.render.path.name()
        );
        let diff = (a.pixels().zip(b.pixels()))
            .flat_map(|(p, q)| (0..3).map(move |c| p[c].abs_diff(q[c])))
            .max()
            .unwrap();
        assert!(
            diff <= 1,
            "{} ({}): instanced and per-rock images differ by {diff}/255",
            s.name,
            s.render.path.name()
        );
    }
}

#[test]
fn each_instance_lands_where_its_model_matrix_projects() {
    let ctx = common::context(common::backend());
    for instanced in [true, false] {
        let mut s = field_scene(RenderPath::Forward, "");
        s.render.instancing = instanced;
        let img = common::render_with(&ctx, &s, Output::Srgb8).image;
        let (w, h) = (img.width() as f32, img.height() as f32);
        let vp = s.camera.projection(w / h) * s.camera.view();
        let right = s.camera.view().inverse().x_axis.xyz();
        let models = s.instancing.as_ref().unwrap().models();
        let to_pixel = |p: Vec3| {
            let c = vp * p.extend(1.0);
            let ndc = c.xyz() / c.w;
            ((ndc.x * 0.5 + 0.5) * w, (0.5 - ndc.y * 0.5) * h)
        };
        // The rock lies within 1.15 of its centre (src/geometry/rock.rs),
        // times its scale: its bounding sphere, projected.
        let mut owned = vec![0usize; models.len()];
        for (k, m) in models.iter().enumerate() {
            let centre = m.transform_point3(Vec3::ZERO);
            let scale = m.x_axis.truncate().length();
            let (cx, cy) = to_pixel(centre);
            let (ex, ey) = to_pixel(centre + right * 1.15 * scale);
            let r = ((ex - cx).powi(2) + (ey - cy).powi(2)).sqrt() + 1.5;
            let p = img.get_pixel(cx as u32, cy as u32);
            assert!(
                p[0] > 30,
                "instanced {instanced}: rock {k} is not at its projected centre ({cx:.1}, {cy:.1}): {p:?}"
            );
            // Every lit pixel near the rock is within its projected radius.
            for y in (cy - 3.0 * r) as i32..=(cy + 3.0 * r) as i32 {
                for x in (cx - 3.0 * r) as i32..=(cx + 3.0 * r) as i32 {
                    if x < 0 || y < 0 || x >= w as i32 || y >= h as i32 {
                        continue;
                    }
                    let q = img.get_pixel(x as u32, y as u32);
                    let d = ((x as f32 + 0.5 - cx).powi(2) + (y as f32 + 0.5 - cy).powi(2)).sqrt();
                    if q[0] > 30 && d <= r {
                        owned[k] += 1;
                    }
                    assert!(
                        q[0] <= 30 || d <= r || near_another(&models, k, x, y, &to_pixel, r),
                        "instanced {instanced}: a lit pixel ({x}, {y}) {d:.1} px from rock {k}, beyond its {r:.1} px"
                    );
                }
            }
        }
        assert!(owned.iter().all(|&n| n >= 4), "rocks' pixels {owned:?}");
    }
}

/// Whether pixel (x, y) is within `r` of another rock's projected centre.
fn near_another(
    models: &[glam::Mat4],
    k: usize,
    x: i32,
    y: i32,
    to_pixel: &dyn Fn(Vec3) -> (f32, f32),
    r: f32,
) -> bool {
    models.iter().enumerate().any(|(j, m)| {
        let (cx, cy) = to_pixel(m.transform_point3(Vec3::ZERO));
        j != k && ((x as f32 + 0.5 - cx).powi(2) + (y as f32 + 0.5 - cy).powi(2)).sqrt() <= 2.0 * r
    })
}

#[test]
fn no_pass_without_a_field_and_bad_fields_are_errors() {
    let s = field_scene(RenderPath::Forward, "");
    assert!(gloss::techniques::plan(&s).has_pass("instancing"));
    let mut none = s.clone();
    none.instancing = None;
    assert!(!gloss::techniques::plan(&none).has_pass("instancing"));
    let base = "[camera]\neye = [0.0, 0.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n";
    for (body, expect) in [
        (
            "[instancing]\ncount = 0\nradius = 1.0\n",
            "instancing.count: expected 1..=1000000",
        ),
        (
            "[instancing]\ncount = 2000000\nradius = 1.0\n",
            "instancing.count",
        ),
        (
            "[instancing]\ncount = 10\nradius = -1.0\n",
            "instancing.radius",
        ),
        (
            "[instancing]\ncount = 10\nradius = 1.0\nscale = [0.5, 0.1]\n",
            "instancing.scale",
        ),
        (
            "[instancing]\ncount = 10\nradius = 1.0\ncolor = [0.0, 2.0, 0.0]\n",
            "instancing.color",
        ),
    ] {
        let e = Scene::parse(&format!("{base}{body}"), Path::new("bad.toml")).unwrap_err();
        assert!(format!("{e:#}").contains(expect), "{e:#}");
    }
}
