//! Environment reflection (notes 03, Implementation: the skybox mirror
//! reflection, forward and deferred): a perfectly reflective sphere
//! (reflectivity 1, black diffuse and specular, no ambient, no lights) shows
//! the cube map sampled on the CPU (src/math/cube_map.rs, bilinear,
//! seamless) along the view ray reflected off the analytic sphere, on the
//! forward path and on every deferred path, and forward equals each; the
//! sky rendered into the cube map equals the CPU Preetham model in every
//! texel; a reflective material with no environment is refused; a changed
//! sky is drawn into the cube map again.

use crate::common;
use glam::{DVec3, Vec4};
use gloss::math::cube_map::{CubeImage, face_st};
use gloss::renderer::{Output, render_scene};
use gloss::scene::{RenderPath, Scene};

/// The world ray through pixel (x, y) (row 0 at the bottom) of `scene`'s camera: (origin, unit direction).
pub fn pixel_ray(scene: &Scene, x: usize, y: usize) -> (DVec3, DVec3) {
    let (w, h) = (scene.render.size.0 as usize, scene.render.size.1 as usize);
    let inverse = (scene.camera.projection(w as f32 / h as f32) * scene.camera.view()).inverse();
    let ndc = |a: usize, n: usize| 2.0 * (a as f32 + 0.5) / n as f32 - 1.0;
    let at = |z: f32| {
        let q = inverse * Vec4::new(ndc(x, w), ndc(y, h), z, 1.0);
        (q.truncate() / q.w).as_dvec3()
    };
    (at(-1.0), (at(1.0) - at(-1.0)).normalize())
}

/// Whether the directions `d` and its neighbours `around` fall on one face
/// within half a texel of each other: a sampler that picks its mip level
/// from the derivatives then reads level 0 (lambda < -1), as the CPU does.
pub fn magnified(cube: &CubeImage, d: DVec3, around: &[DVec3]) -> bool {
    let (f, s, t) = face_st(d);
    around.iter().all(|&a| {
        let (g, s2, t2) = face_st(a);
        let n = cube.size as f64;
        g == f && ((s2 - s).abs() * n) < 0.5 && ((t2 - t).abs() * n) < 0.5
    })
}

fn mirror_scene(path: &str) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\neye = [0.0, 0.3, 3.0]\ntarget = [0.0, 0.0, 0.0]\nfov_y = 50.0\n\
         [render]\nsize = [200, 200]\npath = \"{path}\"\nambient = [0.0, 0.0, 0.0]\n\
         [sky]\nsun = [0.6, 0.4, -1.0]\nturbidity = 3.0\nintensity = 0.5\n[skybox]\nsize = 16\n\
         [materials.mirror]\ndiffuse = [0.0, 0.0, 0.0]\nspecular = [0.0, 0.0, 0.0]\nreflectivity = 1.0\n\
         [[objects]]\nmesh = \"sphere\"\nmaterial = \"mirror\"\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// The reflected ray off the unit sphere at the origin through pixel (x, y).
fn reflected(scene: &Scene, x: usize, y: usize) -> Option<(DVec3, f64)> {
    let (e, d) = pixel_ray(scene, x, y);
    // |e + t d|^2 = 1.
    let b = e.dot(d);
    let disc = b * b - (e.length_squared() - 1.0);
    if disc <= 0.0 {
        return None;
    }
    let n = e + (-b - disc.sqrt()) * d;
    Some((d - 2.0 * d.dot(n) * n, -d.dot(n)))
}

#[test]
fn a_perfect_mirror_shows_the_cube_map_along_the_reflected_ray_forward_and_deferred() {
    let ctx = common::context(common::backend());
    let mut forward: Vec<f32> = Vec::new();
    let mut interior: Vec<usize> = Vec::new();
    for path in ["forward", "deferred", "volumes", "tiled", "prepass"] {
        let scene = mirror_scene(path);
        let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
        let cube = r.draws().environment.cube.as_ref().unwrap().read_image();
        let got = r.read_linear();
        let (w, h) = (scene.render.size.0 as usize, scene.render.size.1 as usize);
        let (mut worst, mut checked) = (0.0f64, 0);
        for y in 1..h - 1 {
            for x in 1..w - 1 {
                let Some((rd, cos)) = reflected(&scene, x, y) else {
                    continue;
                };
                // Off the silhouette, where the 32 x 64 mesh's normals
                // are close to the sphere's, and where level 0 is read.
                let around: Vec<DVec3> = [(x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)]
                    .iter()
                    .filter_map(|&(a, b)| reflected(&scene, a, b).map(|r| r.0))
                    .collect();
                if cos < 0.5 || around.len() < 4 || !magnified(&cube, rd, &around) {
                    continue;
                }
                let want = cube.sample(rd, true);
                let i = (y * w + x) * 4;
                for c in 0..3 {
                    let err = (f64::from(got[i + c]) - want[c]).abs() / want[c].abs().max(0.05);
                    worst = worst.max(err);
                    assert!(
                        err < 0.02,
                        "{path}: pixel ({x}, {y}) channel {c}: {} against the CPU's {}",
                        got[i + c],
                        want[c]
                    );
                }
                checked += 1;
                if path == "forward" {
                    interior.push(i);
                }
            }
        }
        assert!(checked > 5000, "{path}: only {checked} pixels checked");
        println!("{path}: {checked} pixels, worst relative difference from the CPU {worst:.2e}");
        if path == "forward" {
            forward = got;
            continue;
        }
        // Forward == this deferred path, on the pixels checked above (at
        // the silhouette the mip level each picks from its 2x2 quad's
        // derivatives differs: the deferred quad straddles the background).
        let mut worst = 0.0f32;
        for &i in &interior {
            for c in 0..3 {
                worst =
                    worst.max((forward[i + c] - got[i + c]).abs() / forward[i + c].abs().max(0.05));
            }
        }
        println!("{path}: worst relative difference from forward {worst:.2e}");
        assert!(worst < 5e-3, "{path} differs from forward by {worst}");
    }
}

#[test]
fn the_sky_rendered_into_the_cube_map_is_the_cpu_preetham_sky_in_every_texel() {
    let ctx = common::context(common::backend());
    let scene = mirror_scene("forward");
    let sky = scene.sky.as_ref().unwrap().model();
    let r = render_scene(&ctx, &scene, Output::Linear32F).unwrap();
    let cube = r.draws().environment.cube.as_ref().unwrap().read_image();
    let n = cube.size;
    let mut worst = 0.0f64;
    for f in 0..6 {
        for j in 0..n {
            for i in 0..n {
                let d = gloss::math::cube_map::direction(
                    f,
                    (i as f64 + 0.5) / n as f64,
                    (j as f64 + 0.5) / n as f64,
                );
                let want = sky.radiance_rgb(d.normalize()).map(|c| 0.5 * c);
                let got = cube.texel(f, i, j);
                for c in 0..3 {
                    let err = (f64::from(got[c]) - want[c]).abs() / want[c].abs().max(0.02);
                    worst = worst.max(err);
                    assert!(
                        err < 3e-3,
                        "face {f} texel ({i}, {j}) channel {c}: {} against {}",
                        got[c],
                        want[c]
                    );
                }
            }
        }
    }
    println!("worst relative difference {worst:.2e} over 6 x {n} x {n} texels");
}

#[test]
fn the_plan_reflects_on_the_deferred_paths_and_a_material_with_no_environment_is_refused() {
    let names = |s: &Scene| -> Vec<&'static str> {
        gloss::techniques::plan(s)
            .passes
            .iter()
            .map(|p| p.name)
            .collect()
    };
    for path in [RenderPath::Deferred, RenderPath::Volumes, RenderPath::Tiled] {
        let mut s = mirror_scene("forward");
        s.render.path = path;
        assert!(names(&s).contains(&"skybox reflection"), "{path:?}");
    }
    let forward = names(&mirror_scene("forward"));
    assert!(!forward.contains(&"skybox reflection"));
    assert!(forward.contains(&"sky cube map") && forward.contains(&"skybox"));
    assert!(
        !forward.contains(&"sun-sky"),
        "the skybox draws the background"
    );
    let text = "name = \"t\"\n[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n\
                [materials.m]\nreflectivity = 0.5\n";
    let e = Scene::parse(text, &common::root().join("scenes/t.toml")).unwrap_err();
    let e = format!("{e:#}");
    assert!(
        e.contains("materials.m.reflectivity") && e.contains("[skybox]"),
        "{e}"
    );
    let e = Scene::parse(
        &text.replace("0.5", "1.5"),
        &common::root().join("scenes/t.toml"),
    );
    assert!(format!("{:#}", e.unwrap_err()).contains("0..=1"));
}

/// The sky cube map is drawn again when the sky changes (the demo's panel
/// edits it through `set_scene_values`): the reflections then equal those
/// of a renderer made with the new sky from the start, and differ from the
/// old sky's.
#[test]
fn the_sky_cube_map_follows_a_changed_sky() {
    use gloss::gl::program::Sources;
    use gloss::renderer::Renderer;
    let ctx = common::context(common::backend());
    let mut scene = common::scene("assignment-bunny.toml");
    scene.render.size = (160, 90);
    scene.post.clear();
    let make = |s: &Scene| {
        let mut r = Renderer::new(&ctx.gl, &ctx.debug, s, &Sources::Embedded, 160, 90).unwrap();
        r.render(&s.camera).unwrap();
        r
    };
    let mut live = make(&scene);
    let before = live.read_image();
    let mut changed = scene.clone();
    let sky = changed.sky.as_mut().expect("the scene has a [sky]");
    sky.sun = glam::Vec3::new(0.3, 0.8, 0.5).normalize();
    sky.turbidity = 6.0;
    live.set_scene_values(&changed).unwrap();
    live.render(&changed.camera).unwrap();
    let after = live.read_image();
    let fresh = make(&changed).read_image();
    let (mut moved, mut worst) = (0, 0u8);
    for ((a, f), b) in after.pixels().zip(fresh.pixels()).zip(before.pixels()) {
        for k in 0..3 {
            worst = worst.max(a.0[k].abs_diff(f.0[k]));
        }
        moved += usize::from((0..3).any(|k| a.0[k].abs_diff(b.0[k]) > 8));
    }
    assert_eq!(
        worst, 0,
        "the changed renderer's image against a fresh one's"
    );
    assert!(
        moved > 500,
        "the new sky changes the picture ({moved} pixels)"
    );
    // Where the ball is: its reflection follows the sky, not only the
    // background the sun-sky pass draws per pixel.
    let ball = ball_pixels(&changed);
    let reflected = (ball.iter())
        .filter(|&&(x, y)| {
            let (a, b) = (after.get_pixel(x, y).0, before.get_pixel(x, y).0);
            (0..3).any(|k| a[k].abs_diff(b[k]) > 8)
        })
        .count();
    assert!(
        reflected * 2 > ball.len(),
        "{reflected} of the ball's {} pixels changed with the sky",
        ball.len()
    );
}

/// The pixels (x, y from the top) well inside the silhouette of the
/// scene's "ball" (a sphere at its object's position, its scale the
/// radius), which stands clear of the bunny.
fn ball_pixels(scene: &Scene) -> Vec<(u32, u32)> {
    let ball = scene.objects.iter().find(|o| o.name == "ball").unwrap();
    let (c, r) = (ball.position.as_dvec3(), f64::from(ball.scale.x));
    let (w, h) = scene.render.size;
    let mut v = Vec::new();
    for y in 0..h as usize {
        for x in 0..w as usize {
            let (o, d) = pixel_ray(scene, x, y);
            let oc = o - c;
            let b = oc.dot(d);
            // Well inside the silhouette: a margin of 10% of the radius.
            if b * b - (oc.length_squared() - 0.81 * r * r) > 0.0 && b < 0.0 {
                v.push((x as u32, h - 1 - y as u32));
            }
        }
    }
    assert!(v.len() > 50, "the ball covers {} pixels", v.len());
    v
}
