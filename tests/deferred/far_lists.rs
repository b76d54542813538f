//! src/techniques/deferred/far_lists.rs (`render.far_radius = a`): a pixel
//! no far-field sample stands for sums its cluster's far list (the lights
//! within 2 a r, binned per cluster) and takes the rest, the coarse part,
//! from a sample's order-1 harmonics. Checked: the lists hold every light
//! within 2 a r of a point of their cluster (world points projected by hand,
//! not by the binning) and not every light; the image against forward and
//! against the exact far part (k = 1, the same G-buffer) within each pixel's
//! printed bound, on the knot and spheres of many-lights, the curved field
//! of spheres and a light just past the second radius.

use super::far_field;
use crate::common;
use crate::with_path;
use glam::Vec3;
use gloss::frame::clusters::Grid;
use gloss::frame::lights::FrameLights;
use gloss::image_compare::Tolerance;
use gloss::renderer::Output;
use gloss::scene::{Light, RenderPath, Scene};
use gloss::techniques::deferred::{far_lists, tiled_shading};

fn far(scene: &Scene, k: u32, a: f32) -> Scene {
    let mut s = far_field::far(scene, k);
    s.render.far_radius = a as u32;
    s
}

/// The far lists of `scene`'s camera view, binned as tiled shading bins
/// them (16-pixel tiles, 16 slices), with the grid.
fn lists(scene: &Scene) -> (Grid, gloss::frame::clusters::Bins) {
    let (w, h) = scene.render.size;
    let c = &scene.camera;
    let grid = Grid::new(w, h, 16, 16, c.near, c.far);
    let lights = FrameLights::new(scene);
    let bounds = far_lists::far_bounds(scene, &lights, &[], tiled_shading::bounding_sphere);
    let projection = c.projection(w as f32 / h as f32);
    let bins = far_lists::bin(&grid, c.view(), projection, (w, h), &bounds);
    (grid, bins)
}

#[test]
fn far_lists_hold_every_light_within_their_radius_and_not_all() {
    let mut base = common::scene("many-lights.toml");
    base.render.size = (640, 360);
    let (w, h) = base.render.size;
    let c = base.camera.clone();
    let (view, projection) = (c.view(), c.projection(w as f32 / h as f32));
    let lights = FrameLights::new(&base);
    let n = base.lights.len();
    for a in [1.0f32, 2.0] {
        let s = far(&base, 4, a);
        let (grid, bins) = lists(&s);
        // Points on the floor (y = 0) and above it, where the objects stand.
        let mut checked = 0;
        for iz in -24..=24 {
            for ix in -24..=24 {
                for y in [0.0, 1.0, 2.5] {
                    let p = Vec3::new(ix as f32 * 0.5, y, iz as f32 * 0.5);
                    let e = view * p.extend(1.0);
                    let depth = -e.z;
                    let clip = projection * e;
                    if depth <= c.near || depth >= c.far || clip.w <= 0.0 {
                        continue;
                    }
                    let ndc = clip.truncate() / clip.w;
                    let px = (ndc.x * 0.5 + 0.5) * w as f32;
                    let py = (ndc.y * 0.5 + 0.5) * h as f32;
                    if !(0.0..w as f32).contains(&px) || !(0.0..h as f32).contains(&py) {
                        continue;
                    }
                    let tile = |v: f32| (v / grid.tile_size as f32) as u32;
                    let cluster = grid.index(tile(px), tile(py), grid.slice_of(depth));
                    let [offset, count] = bins.clusters[cluster];
                    let list = &bins.indices[offset as usize..(offset + count) as usize];
                    for (i, (l, f)) in s.lights.iter().zip(&lights.lights).enumerate() {
                        let r = f.radius.unwrap();
                        if l.position.distance(p) < 2.0 * a * r * 0.999 {
                            assert!(
                                list.contains(&(i as u32)),
                                "a = {a}: light {i} at {} within 2 a r = {} of {p} is not in cluster {cluster}'s far list",
                                l.position.distance(p),
                                2.0 * a * r
                            );
                        }
                    }
                    checked += 1;
                }
            }
        }
        assert!(checked > 500, "only {checked} points in view");
        let longest = bins.max_per_cluster();
        eprintln!(
            "a = {a}: far lists {:.1} lights a cluster on average, {longest} at most, of {n}",
            bins.mean_per_cluster()
        );
        if a == 1.0 {
            assert!(
                (longest as usize) < n,
                "a = {a}: a far list holds every light ({longest} of {n})"
            );
        }
    }
    // At a = 1 a list holds well under half the lights.
    let (_, bins) = lists(&far(&base, 4, 1.0));
    assert!(
        bins.mean_per_cluster() < 0.5 * n as f32,
        "{}",
        bins.mean_per_cluster()
    );
}

/// The image within each pixel's printed bound of the exact far part
/// (k = 1), plus 1/255 for the two images' 8-bit rounding.
/// `tolerance`: RenderSettings::far_coarse_tolerance (infinite: every
/// pixel no sample stands for takes a coarse part within reach).
fn within_bound(label: &str, scene: &Scene, a: f32, tolerance: f32) -> f64 {
    let ctx = common::context(common::backend());
    let (w, _) = scene.render.size;
    let exact = common::render_with(&ctx, &far(scene, 1, 0.0), Output::Srgb8).image;
    let mut s = far(scene, 4, a);
    s.render.far_coarse_tolerance = tolerance;
    let image = common::render_with(&ctx, &s, Output::Srgb8).image;
    let bound = gloss::bench::bound::far_field_pixels(&ctx, &s, &image)
        .unwrap()
        .unwrap();
    let (mut outside, mut worst) = (Vec::new(), 0.0f64);
    for (i, (p, e)) in image.pixels().zip(exact.pixels()).enumerate() {
        let d = (0..3)
            .map(|c| (f64::from(p[c]) - f64::from(e[c])).abs() / 255.0)
            .fold(0.0, f64::max);
        worst = worst.max(d);
        if d > bound[i] + 1.0 / 255.0 {
            outside.push((i as u32 % w, i as u32 / w, d * 255.0, bound[i] * 255.0));
        }
    }
    assert!(
        outside.is_empty(),
        "{label}, a = {a}: {} pixels outside their bound (x, y, error, bound x255): {:?}",
        outside.len(),
        &outside[..outside.len().min(10)]
    );
    eprintln!(
        "{label}, a = {a}, tolerance {tolerance}: every pixel within its bound; largest error {:.1}/255",
        worst * 255.0
    );
    worst
}

#[test]
fn far_lists_stay_within_their_bound_on_curved_surfaces_and_edges() {
    for (name, size) in [
        ("many-lights.toml", (320, 180)),
        ("far-field-spheres.toml", (320, 180)),
    ] {
        let mut base = common::scene(name);
        base.render.size = size;
        for a in [1.0, 2.0] {
            within_bound(name, &base, a, 0.5 / 255.0);
            // Every such pixel on the coarse part: large errors, still bounded.
            let worst = within_bound(name, &base, a, f32::INFINITY);
            if name == "many-lights.toml" {
                // The coarse part is taken (the knot's pixels are off by
                // more than the acceptance allows): the check checks it.
                assert!(worst > 2.0 / 255.0, "{name}, a = {a}: {worst}");
            }
        }
    }
}

/// A point light with the LearnOpenGL-like falloff (Kc 1, Kl 0.7, Kq 1.8).
fn point(position: Vec3) -> Light {
    far_field::point(position, [1.0, 0.7, 1.8])
}

/// A light just past the second radius of the knot's and the sphere's
/// pixels (coarse for them, listed for the floor below), and one on the
/// edge between listed and coarse: against forward and within the bound.
#[test]
fn far_lists_hard_cases() {
    let mut base = common::scene("default.toml");
    base.render.size = (256, 192);
    base.render.cutoff = 5.0 / 256.0;
    let lights = FrameLights::new(&{
        let mut s = base.clone();
        s.lights = vec![point(Vec3::ZERO)];
        s
    });
    let r = lights.lights[0].radius.unwrap();
    let a = 1.0;
    let fwd_tol = Tolerance {
        threshold: 2.0 / 255.0,
        max_frac_over: 0.01,
        max_abs: Some(10.0 / 255.0),
    };
    for (label, d) in [("past-2ar", 2.0 * a * r + 0.05), ("at-ar", a * r * 1.5)] {
        let mut s = base.clone();
        s.lights = (0..8)
            .map(|i| {
                let t = i as f32 / 8.0 * std::f32::consts::TAU;
                point(Vec3::new(d * t.cos(), 0.8, d * t.sin()))
            })
            .collect();
        within_bound(label, &s, a, f32::INFINITY);
        let fwd = common::render(&with_path(&s, RenderPath::Forward), Output::Srgb8);
        let t = common::render(&far(&s, 4, a), Output::Srgb8);
        let m = common::assert_close(
            &format!("far-lists-{label}-vs-forward"),
            &t.image,
            &fwd.image,
            &fwd_tol,
        );
        eprintln!("{label}: far lists vs forward: {m}");
    }
}

/// `render.far_radius` out of range is refused with the key and the range;
/// set where it does nothing, it is named in a warning.
#[test]
fn far_radius_is_checked_and_warned_about() {
    let dir = std::env::temp_dir();
    let text = |path: &str, extra: &str| {
        format!(
            "[camera]\neye = [0.0, 2.0, 10.0]\ntarget = [0.0, 0.0, 0.0]\n[render]\npath = \"{path}\"\nfar_field = 4\n{extra}\n"
        )
    };
    for bad in ["65", "1000"] {
        let t = text("tiled", &format!("far_radius = {bad}"));
        let e = Scene::parse(&t, &dir.join("scene.toml")).unwrap_err();
        let e = format!("{e:#}");
        assert!(
            e.contains("render.far_radius") && e.contains("1 to 64"),
            "{bad}: {e}"
        );
    }
    let ok = Scene::parse(&text("tiled", "far_radius = 2"), &dir.join("scene.toml")).unwrap();
    assert_eq!(ok.render.far_radius, 2);
    assert!(
        ok.warnings().iter().all(|w| !w.contains("far_radius")),
        "{:?}",
        ok.warnings()
    );
    for (path, extra, why) in [
        ("forward", "far_radius = 2", "only the tiled path"),
        (
            "tiled",
            "far_radius = 2\nfar_field_sh = true",
            "fallback of its own",
        ),
    ] {
        let s = Scene::parse(&text(path, extra), &dir.join("scene.toml")).unwrap();
        let w = s.warnings();
        assert!(
            w.iter()
                .any(|w| w.starts_with("render.far_radius = 2") && w.contains(why)),
            "{path} {extra}: {w:?}"
        );
    }
}
