//! scenes/z-fighting.toml and src/math/depth.rs: the depth-precision formula
//! predicts the image. The quads are 0.002 apart along their normal, 40 to 60
//! units away: with near = 0.01 the 24-bit buffer resolves ~0.01 there
//! (several times the quads' separation), with near = 1.0 ~0.0002 (ten
//! times less than it).

use crate::common;
use glam::Vec3;
use gloss::math::depth::{DEPTH_BITS, resolvable_difference};
use gloss::renderer::Output;
use gloss::scene::{DepthFunc, Scene};

/// Pixels showing the back (red) quad, and pixels showing either quad; the
/// image is written under target/test-output as `name`.
fn wrong_pixels(scene: &Scene, name: &str) -> (usize, usize, String) {
    let img = common::render(scene, Output::Srgb8).image;
    let path = common::out_dir().join(format!("{name}.png"));
    img.save(&path).expect("write the image");
    let (mut red, mut any) = (0, 0);
    for p in img.pixels() {
        let (r, g) = (p[0] as i32, p[1] as i32);
        if r > g + 40 {
            red += 1;
            any += 1;
        } else if g > r + 40 {
            any += 1;
        }
    }
    (red, any, path.display().to_string())
}

/// The quads' eye-space depth difference along the view axis, and the
/// nearest and farthest eye distance of the back quad's corners.
fn geometry(scene: &Scene) -> (f64, f64, f64) {
    let (back, front) = (&scene.objects[0], &scene.objects[1]);
    let view = scene.camera.view();
    let normal = back.model.transform_vector3(Vec3::Y).normalize();
    let dir = (scene.camera.target - scene.camera.eye).normalize();
    // Along a ray, parallel planes s apart are s / |n . dir| apart.
    let s = normal
        .dot(front.model.transform_point3(Vec3::ZERO) - back.model.transform_point3(Vec3::ZERO));
    let along = (s / normal.dot(dir).abs()) as f64;
    let corners = [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)];
    let z: Vec<f64> = corners
        .iter()
        .map(|&(x, zl)| {
            let w = back.model.transform_point3(Vec3::new(x, 0.0, zl));
            -(view.transform_point3(w).z) as f64
        })
        .collect();
    let z_min = z.iter().cloned().fold(f64::INFINITY, f64::min);
    let z_max = z.iter().cloned().fold(0.0, f64::max);
    (along, z_min, z_max)
}

#[test]
fn far_quads_z_fight_with_near_0_01_and_not_with_near_1() {
    let base = common::scene("z-fighting.toml");
    let (s, z_min, z_max) = geometry(&base);
    assert!(
        (s - 0.002 / 0.8660254).abs() < 1e-4,
        "separation along the view {s}"
    );
    assert!(z_min > 35.0 && z_max < 65.0, "{z_min}..{z_max}");
    let far = base.camera.far as f64;
    for (near, fights) in [(0.01f32, true), (1.0, false)] {
        let mut scene = base.clone();
        scene.camera.near = near;
        let n = near as f64;
        let (dz_min, dz_max) = (
            resolvable_difference(z_min, n, far, DEPTH_BITS),
            resolvable_difference(z_max, n, far, DEPTH_BITS),
        );
        let (red, any, path) = wrong_pixels(&scene, &format!("z-fighting-near-{near}"));
        let frac = red as f64 / any as f64;
        eprintln!(
            "near {near}: separation {s:.2e}, dz {dz_min:.2e}..{dz_max:.2e}; {red} of {any} quad pixels show the back quad ({:.2}%)",
            frac * 100.0
        );
        assert!(any > 50_000, "{path}: the quads cover only {any} pixels");
        if fights {
            // The formula: the separation is below one depth step everywhere.
            assert!(s < dz_min, "near {near}: separation {s} >= dz {dz_min}");
            assert!(
                frac > 0.01,
                "{path}: near {near}: only {red} of {any} pixels show the back quad; the 24-bit buffer cannot separate the quads"
            );
        } else {
            // The formula: several depth steps between the quads everywhere.
            assert!(
                s > 3.0 * dz_max,
                "near {near}: separation {s} <= 3 dz {dz_max}"
            );
            assert_eq!(red, 0, "{path}: near {near}: the back quad shows through");
        }
    }
}

#[test]
fn the_formula_separates_fighting_from_clean_across_near_planes() {
    // Where the quads are more than 3 depth steps apart everywhere the image
    // is clean, always; where they are less than one step apart, most near
    // planes fight (which pixels do depends on how the rasteriser rounds the
    // two nearly equal depths, so not every one must).
    let base = common::scene("z-fighting.toml");
    let (s, z_min, z_max) = geometry(&base);
    let far = base.camera.far as f64;
    let (mut below, mut fought) = (0, 0);
    for near in [1.0f32, 0.5, 0.3, 0.02, 0.01, 0.005, 0.003, 0.001] {
        let mut scene = base.clone();
        scene.camera.near = near;
        let n = near as f64;
        let (red, any, path) = wrong_pixels(&scene, &format!("z-fighting-sweep-{near}"));
        let ratio = (
            s / resolvable_difference(z_max, n, far, DEPTH_BITS),
            s / resolvable_difference(z_min, n, far, DEPTH_BITS),
        );
        eprintln!(
            "near {near}: separation / dz {:.2}..{:.2}: {red} of {any} pixels wrong",
            ratio.0, ratio.1
        );
        if ratio.0 > 3.0 {
            assert_eq!(
                red, 0,
                "{path}: near {near}: separation / dz >= {:.2}, yet the back quad shows",
                ratio.0
            );
        } else if ratio.1 < 1.0 {
            below += 1;
            if red as f64 > 0.01 * any as f64 {
                fought += 1;
            }
        }
    }
    assert!(
        below >= 5,
        "the sweep has {below} near planes below one step"
    );
    assert!(
        fought * 2 > below,
        "only {fought} of {below} near planes below one step fight"
    );
}

#[test]
fn camera_near_is_a_knob_on_the_command_line() {
    let path = common::root().join("scenes/z-fighting.toml");
    let s = Scene::load_with(&path, &["camera.near=1.0".to_string()]).unwrap();
    assert_eq!(s.camera.near, 1.0);
    let e = Scene::load_with(&path, &["camera.near=-1".to_string()]).unwrap_err();
    assert!(format!("{e:#}").contains("camera.near/far"), "{e:#}");
    // gloss plan prints the depth precision of the camera it was given.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["plan", "scenes/z-fighting.toml", "--set", "camera.near=1.0"])
        .current_dir(common::root())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("depth precision (24-bit"), "{text}");
    assert!(text.contains("near 1, far 100"), "{text}");
    let dz = resolvable_difference(50.0, 1.0, 100.0, 24);
    assert!(
        text.contains(&format!("{dz:.3e}")),
        "{text}\nwants dz(50) = {dz:.3e}"
    );
}

#[test]
fn with_lequal_the_quad_drawn_second_wins_the_ties() {
    // The scene's lequal variant (`--set render.depth_func=lequal`), near
    // 0.01: the quads share depth values over most of the image (above).
    // Under GL_LESS the red quad, drawn first, keeps every tie and shows in
    // stripes; under GL_LEQUAL the green quad, drawn second and in front,
    // passes wherever its depth is not greater than the red one's, which
    // the geometry says is everywhere: no red pixel.
    let mut base = common::scene("z-fighting.toml");
    base.camera.near = 0.01;
    let mut counts = Vec::new();
    for func in [DepthFunc::Less, DepthFunc::Lequal] {
        let mut scene = base.clone();
        scene.render.depth_func = func;
        let (red, any, path) = wrong_pixels(&scene, &format!("z-fighting-{func}"));
        eprintln!("{func}: {red} of {any} quad pixels show the back quad");
        assert!(any > 50_000, "{path}: the quads cover only {any} pixels");
        counts.push((red, any, path));
    }
    let (less, lequal) = (&counts[0], &counts[1]);
    assert!(
        less.0 * 100 > less.1,
        "{}: under GL_LESS only {} of {} pixels show the back quad",
        less.2,
        less.0,
        less.1
    );
    assert_eq!(
        lequal.0, 0,
        "{}: under GL_LEQUAL the back quad shows",
        lequal.2
    );
}
