//! Analytic references: a rendered pixel equals the Phong formula (notes 01
//! §8.3 with notes 04's attenuation) evaluated on the CPU, within 1/255 per
//! channel after sRGB encoding. Includes the hard cases: Kq = 0, a sun at the
//! horizon, a spot light's cone edge, and a singular model matrix.

use crate::common;

use glam::Vec3;
use gloss::frame::lights::model_radius;
use gloss::lighting::{phong_light_with, srgb_encode};
use gloss::renderer::Output;
use gloss::scene::{Camera, Falloff, Projection, Scene, Shading};

/// The world point under the centre of pixel (px, py) (top row first) for
/// the top-down orthographic camera of scenes/plane.toml (up = -z).
fn world_at(cam: &Camera, w: u32, h: u32, px: u32, py: u32) -> Vec3 {
    let Projection::Orthographic { half_height } = cam.projection else {
        panic!("plane.toml uses an orthographic camera")
    };
    let half_width = half_height * w as f32 / h as f32;
    let ndc_x = (px as f32 + 0.5) / w as f32 * 2.0 - 1.0;
    let ndc_y = 1.0 - (py as f32 + 0.5) / h as f32 * 2.0;
    Vec3::new(
        cam.eye.x + ndc_x * half_width,
        0.0,
        cam.eye.z - ndc_y * half_height,
    )
}

/// Every 7th pixel in x and y is compared with the CPU's Phong; returns the
/// largest difference in 8-bit steps.
fn check_plane(scene: &Scene, label: &str) -> f32 {
    let r = common::render(scene, Output::Srgb8);
    let m = &scene.materials[scene.objects[0].material];
    // The windowed falloff ends each light at its radius at the cutoff; the
    // linear one at Lmax.
    let radii: Vec<Option<(Falloff, f32)>> = (scene.lights.iter())
        .map(|l| match scene.render.falloff {
            Falloff::Notes => None,
            f => model_radius(l, scene.render.cutoff, f).map(|r| (f, r)),
        })
        .collect();
    let mut worst = 0.0f32;
    for py in (0..r.height).step_by(7) {
        for px in (0..r.width).step_by(7) {
            let p = world_at(&scene.camera, r.width, r.height, px, py);
            let v = (scene.camera.eye - p).normalize();
            let mut c = scene.render.ambient * m.diffuse;
            for (l, &radius) in scene.lights.iter().zip(&radii) {
                let (d, s) = phong_light_with(l, p, Vec3::Y, v, m.shininess, radius);
                c += m.diffuse * d + m.specular * s;
            }
            let got = r.image.get_pixel(px, py);
            for ch in 0..3 {
                let want = srgb_encode(c[ch]) * 255.0;
                let diff = (got[ch] as f32 - want).abs();
                worst = worst.max(diff);
                assert!(
                    diff <= 1.0 + 1e-3,
                    "{label}: pixel ({px}, {py}) channel {ch}: rendered {}, Phong on the CPU gives {want:.2} (world {p})",
                    got[ch]
                );
            }
        }
    }
    worst
}

#[test]
fn lit_plane_equals_phong_formula_per_pixel() {
    let scene = common::scene("plane.toml");
    let worst = check_plane(&scene, "plane.toml");
    eprintln!("plane: worst difference {worst:.3}/255");
}

#[test]
fn gouraud_and_flat_on_a_single_quad_are_not_phong() {
    // A plane of two triangles: Gouraud interpolates the vertex colours and flat
    // lights each triangle at its centroid, so both must differ visibly from
    // the per-pixel formula somewhere near the light.
    for shading in [Shading::Gouraud, Shading::Flat] {
        let mut scene = common::scene("plane.toml");
        scene.render.shading = shading;
        let r = common::render(&scene, Output::Srgb8);
        let phong = common::render(&common::scene("plane.toml"), Output::Srgb8);
        let m = gloss::image_compare::compare_rgba8(&r.image, &phong.image, 2.0 / 255.0).unwrap();
        assert!(
            m.max_abs > 20.0 / 255.0,
            "{shading:?} looks like Phong: {m}"
        );
    }
}

#[test]
fn flat_shading_gives_one_colour_per_triangle() {
    let mut scene = common::scene("plane.toml");
    scene.render.shading = Shading::Flat;
    let r = common::render(&scene, Output::Srgb8);
    // The plane is two triangles: the image holds exactly two colours.
    let mut colours: Vec<[u8; 4]> = r.image.pixels().map(|p| p.0).collect();
    colours.sort();
    colours.dedup();
    assert_eq!(
        colours.len(),
        2,
        "flat shading of a two-triangle plane: {colours:?}"
    );
}

#[test]
fn linear_attenuation_only_kq_zero() {
    let mut scene = common::scene("plane.toml");
    scene.lights[0].kq = 0.0;
    scene.lights[0].kl = 0.35;
    check_plane(&scene, "Kq = 0");
}

#[test]
fn a_light_on_the_plane_with_kc_0_is_a_small_sphere() {
    // N.L = 0 for a point on the plane; the light is a sphere of radius
    // 0.01 (src/math/sphere_light.rs), half above the plane, and the
    // CPU's Phong with the same sphere gives every pixel, the one under
    // the light (attenuation at d = 0.01, not 1/0) included.
    for (y, k) in [
        (0.0, [0.0, 0.09, 0.032]),
        (0.0, [0.0, 0.0, 1.0]),
        (0.005, [0.0, 1.0, 0.0]),
    ] {
        let mut scene = common::scene("plane.toml");
        let l = &mut scene.lights[0];
        l.position = Vec3::new(0.0, y, 0.0);
        (l.kc, l.kl, l.kq) = (k[0], k[1], k[2]);
        check_plane(&scene, &format!("light at height {y}, attenuation {k:?}"));
    }
}

#[test]
fn constant_attenuation_only_kl_kq_zero() {
    let mut scene = common::scene("plane.toml");
    scene.lights[0].kq = 0.0;
    scene.lights[0].kl = 0.0;
    scene.lights[0].kc = 4.0;
    check_plane(&scene, "Kl = Kq = 0");
}

#[test]
fn sun_at_the_horizon_adds_nothing() {
    // A directional light exactly along the plane: N . L = 0, so only the
    // other light and the ambient term remain; and one a hair above it.
    for y in [0.0f32, -1e-3] {
        let mut scene = common::scene("plane.toml");
        let mut sun = scene.lights[0].clone();
        sun.kind = gloss::scene::LightKind::Directional;
        sun.direction = Vec3::new(1.0, y, 0.0).normalize();
        sun.intensity = 3.0;
        scene.lights.push(sun);
        check_plane(&scene, &format!("sun at the horizon (y = {y})"));
    }
}

#[test]
fn spot_light_cone_edge() {
    let mut scene = common::scene("plane.toml");
    let l = &mut scene.lights[0];
    l.kind = gloss::scene::LightKind::Spot;
    l.position = Vec3::new(0.5, 3.0, 0.0);
    l.direction = Vec3::new(0.2, -1.0, 0.1).normalize();
    l.inner_angle = 15.0;
    l.outer_angle = 30.0;
    l.intensity = 4.0;
    check_plane(&scene, "spot light");
}

#[test]
fn singular_model_matrix_flattened_sphere_is_lit_like_the_plane() {
    // A sphere scaled to zero height is a disc in y = 0 whose normals are +y
    // (cofactor normal matrix) on its top half; where the top half is drawn,
    // it must look exactly like the plane. No NaN, no GL error.
    let mut scene = common::scene("plane.toml");
    let text = std::fs::read_to_string(common::root().join("scenes/plane.toml")).unwrap();
    let text = text
        .replace("mesh = \"plane\"", "mesh = \"sphere\"")
        .replace("scale = [10.0, 1.0, 10.0]", "scale = [10.0, 0.0, 10.0]");
    let flat = Scene::parse(&text, &common::root().join("scenes/plane.toml")).unwrap();
    scene.objects = flat.objects;
    let nm = gloss::frame::draw_list::normal_matrix(&scene.objects[0].model);
    assert!(nm.is_finite());
    let n = (nm * Vec3::new(0.3, 0.8, 0.1)).normalize();
    assert!((n - Vec3::Y).length() < 1e-6, "flattened normal {n}");
    check_plane(&scene, "flattened sphere");
}

#[test]
fn a_lit_plane_under_the_windowed_falloff_equals_the_cpu_formula() {
    // A cutoff of 0.2 puts the radius inside the picture: the light ends
    // in a visible circle, which the notes' model does not have.
    let mut scene = common::scene("plane.toml");
    scene.render.cutoff = 0.2;
    scene.render.falloff = Falloff::Windowed;
    let worst = check_plane(&scene, "windowed");
    eprintln!("windowed plane: worst difference {worst:.3}/255");
    let windowed = common::render(&scene, Output::Srgb8);
    scene.render.falloff = Falloff::Notes;
    let notes = common::render(&scene, Output::Srgb8);
    let m =
        gloss::image_compare::compare_rgba8(&windowed.image, &notes.image, 1.0 / 255.0).unwrap();
    assert!(
        m.max_abs > 10.0 / 255.0,
        "the window changes the image: {m}"
    );
}

#[test]
fn the_notes_linear_attenuation_per_pixel() {
    // Notes 01 §8.3: a = 1 - L / Lmax, 0 beyond. With Lmax = 2.5 the light's
    // reach ends inside the picture: every pixel, lit or only ambient, is
    // the CPU's Phong with that attenuation.
    let mut scene = common::scene("plane.toml");
    scene.render.falloff = Falloff::Linear;
    scene.lights[0].range = Some(2.5);
    check_plane(&scene, "linear, Lmax 2.5");
    let r = common::render(&scene, Output::Srgb8);
    let m = &scene.materials[scene.objects[0].material];
    let ambient = (scene.render.ambient * m.diffuse).map(srgb_encode) * 255.0;
    let dark = (r.image.pixels())
        .filter(|p| (0..3).all(|c| (p[c] as f32 - ambient[c]).abs() <= 1.0))
        .count();
    assert!(
        dark > 100,
        "beyond Lmax only the ambient light is left ({dark} pixels)"
    );
}

#[test]
fn a_lights_range_is_checked_and_warned_about_where_it_does_nothing() {
    let text = |range: &str, falloff: &str| {
        format!(
            "name = \"t\"\n[camera]\neye = [0.0, 1.0, 5.0]\ntarget = [0.0, 0.0, 0.0]\n[render]\nfalloff = \"{falloff}\"\n[[lights]]\ntype = \"point\"\nposition = [0.0, 1.0, 0.0]\nrange = {range}\n"
        )
    };
    let path = common::root().join("scenes/t.toml");
    for bad in ["-1.0", "0.0", "1e9"] {
        let e = format!(
            "{:#}",
            Scene::parse(&text(bad, "linear"), &path).unwrap_err()
        );
        assert!(
            e.contains("lights[0].range: expected a distance in (0, 1e6]"),
            "{e}"
        );
    }
    let s = Scene::parse(&text("4.0", "notes"), &path).unwrap();
    assert!(
        s.warnings()
            .iter()
            .any(|w| w.contains("lights[0].range has no effect with render.falloff = \"notes\"")),
        "{:?}",
        s.warnings()
    );
    let s = Scene::parse(&text("4.0", "linear"), &path).unwrap();
    assert!(s.warnings().is_empty(), "{:?}", s.warnings());
    // Its volume is exactly Lmax.
    let lights = gloss::frame::lights::FrameLights::new(&s);
    assert_eq!(lights.lights[0].radius, Some(4.0));
}

/// The forward programs specialised to the frame (src/frame/variant.rs: the
/// glTF material code left out where no material has a glTF map or
/// emits) draw the same bytes as the general shader (`render.specialize =
/// false`), on the texture scenes whose forward pass that code slowed, in
/// both per-fragment and per-vertex shading, and with a material that emits.
#[test]
fn specialised_forward_programs_draw_what_the_general_shader_draws() {
    let mut cases = Vec::new();
    for name in [
        "texture-filtering.toml",
        "texture-atlas.toml",
        "shading-gouraud.toml",
        "shading-phong.toml",
    ] {
        cases.push((name, common::scene(name)));
    }
    let mut emits = common::scene("texture-atlas.toml");
    emits.materials[emits.objects[0].material].pbr.emissive = Vec3::new(0.3, 0.1, 0.0);
    cases.push(("texture-atlas.toml, emissive", emits));
    for (name, base) in cases {
        for shading in [Shading::Phong, Shading::Gouraud] {
            let mut s = base.clone();
            s.render.shading = shading;
            s.render.size = (160, 90);
            let special = common::render(&s, Output::Srgb8);
            s.render.specialize = false;
            let general = common::render(&s, Output::Srgb8);
            let differ = (special.image.pixels().zip(general.image.pixels()))
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(
                differ, 0,
                "{name} ({shading:?}): {differ} pixels differ, specialised against general"
            );
            // Not an empty frame: the textures show.
            let first = special.image.get_pixel(0, 0);
            assert!(
                special.image.pixels().any(|p| p != first),
                "{name} ({shading:?}): a flat image"
            );
        }
    }
}
