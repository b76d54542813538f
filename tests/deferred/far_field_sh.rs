//! The far field as spherical harmonics (`render.far_field_sh`,
//! glsl/common/far_field_sh.glsl) with the near part binned at a shorter
//! radius (`render.near_radius`): every pixel is within its printed bound
//! of the exact far part, on a field of spheres where every light reaches
//! every pixel (scenes/far-field-spheres.toml) and on many-lights; the
//! shader's harmonics equal the CPU's (src/lighting/far_field_sh.rs) at a
//! probed pixel; `gloss plan` names the variant.

use crate::common;
use crate::with_path;
use glam::Vec3;
use gloss::lighting::far_field_sh::{self, FarLight};
use gloss::renderer::Output;
use gloss::scene::{Accumulation, LightKind, RenderPath, Scene};
use std::f32::consts::PI;

fn harmonics(scene: &Scene, k: u32, near: f32) -> Scene {
    let mut s = with_path(scene, RenderPath::Tiled);
    s.render.far_field = k;
    s.render.far_field_sh = true;
    s.render.near_radius = near;
    s.render.accumulation = Accumulation::Rgba32f;
    s
}

/// The exact far part: one sample per pixel, each pixel its own sample
/// (the far field of common/far_field.glsl at k = 1, same G-buffer, same
/// near split).
fn exact(scene: &Scene, near: f32) -> Scene {
    let mut s = harmonics(scene, 1, near);
    s.render.far_field_sh = false;
    s
}

/// Every pixel of the harmonics far field at k = 4 and 8 is within its
/// bound (plus 1/255 for the two images' 8-bit rounding) of the exact far
/// part; and the bound is not vacuous: it is finite everywhere and below
/// 255/255 on most pixels.
fn within_bound(name: &str, near: f32, size: (u32, u32)) {
    let ctx = common::context(common::backend());
    let mut base = common::scene(name);
    base.render.size = size;
    let reference = common::render_with(&ctx, &exact(&base, near), Output::Srgb8).image;
    for k in [4, 8] {
        let s = harmonics(&base, k, near);
        let image = common::render_with(&ctx, &s, Output::Srgb8).image;
        let bound = gloss::bench::bound::far_field_pixels(&ctx, &s, &image)
            .unwrap()
            .unwrap();
        let (mut outside, mut worst, mut over) = (Vec::new(), 0.0f64, 0usize);
        for (i, (a, e)) in image.pixels().zip(reference.pixels()).enumerate() {
            let d = (0..3)
                .map(|c| (f64::from(a[c]) - f64::from(e[c])).abs() / 255.0)
                .fold(0.0, f64::max);
            worst = worst.max(d);
            if d > bound[i] + 1.0 / 255.0 {
                outside.push((
                    i as u32 % size.0,
                    i as u32 / size.0,
                    d * 255.0,
                    bound[i] * 255.0,
                ));
            }
            if bound[i] >= 1.0 {
                over += 1;
            }
        }
        assert!(
            outside.is_empty(),
            "{name} near {near} k = {k}: {} pixels outside their bound (x, y, error, bound x255): {:?}",
            outside.len(),
            &outside[..outside.len().min(10)]
        );
        let frac = over as f64 / bound.len() as f64;
        assert!(
            frac < 0.05,
            "{name} k = {k}: the bound is 1 or more on {frac}"
        );
        let largest = bound.iter().copied().fold(0.0, f64::max);
        eprintln!(
            "{name} near {near} k = {k}: every pixel within its bound; error max {:.1}/255, bound max {:.1}/255",
            worst * 255.0,
            largest * 255.0
        );
    }
}

#[test]
fn a_field_of_spheres_is_within_its_bound() {
    within_bound("far-field-spheres.toml", 0.5, (320, 180));
}

#[test]
fn many_lights_is_within_its_bound_at_a_quarter_of_the_radius() {
    within_bound("many-lights.toml", 0.25, (320, 180));
}

/// Where the unit sphere at the origin meets the ray from `eye` (looking
/// down -z, vertical field of view `fov_y` degrees, square frame of `size`
/// pixels) through window pixel (x, y) (GL's, from the bottom left): the
/// point, which is also the normal.
fn on_sphere(eye: Vec3, fov_y: f32, size: u32, x: u32, y: u32) -> Vec3 {
    let t = (fov_y.to_radians() / 2.0).tan();
    let ndc = |v: u32| (v as f32 + 0.5) / size as f32 * 2.0 - 1.0;
    let dir = Vec3::new(ndc(x) * t, ndc(y) * t, -1.0).normalize();
    // |eye + s dir| = 1, nearer root.
    let b = eye.dot(dir);
    let c = eye.length_squared() - 1.0;
    let s = -b - (b * b - c).sqrt();
    eye + s * dir
}

/// The harmonics the far pass stores, evaluated at another pixel's normal,
/// equal the CPU's (src/lighting/far_field_sh.rs): a white matte unit
/// sphere, one dim light (radius about 1) 5 away, about 78 degrees from the
/// view axis, k = 8, no ambient. The pixel at GL (32, 31) takes the four
/// samples around it, as bilinear filtering would: texels (28, 28), (36,
/// 28), (28, 36), (36, 36), weights 0.4375 x 0.5625 and so on; each point
/// found by casting its ray at the sphere. The CPU's harmonics there,
/// evaluated at the pixel's normal and weighted, are what the light target
/// holds at the pixel, within 1%. The harmonics without band 0's move (the
/// plain projection) differ by more than 2.5% (3.8% measured), so the test
/// can tell. The
/// light is dim so that every sample serves (SH_TOLERANCE).
#[test]
fn the_shader_harmonics_equal_the_cpus() {
    let mut base = common::scene("far-field-spheres.toml");
    let size = 64;
    base.render.size = (size, size);
    base.render.ambient = Vec3::ZERO;
    base.objects.truncate(1);
    base.objects[0].position = Vec3::ZERO;
    gloss::scene::update_models(&mut base.objects);
    let eye = Vec3::new(0.0, 0.0, 3.0);
    base.camera.eye = eye;
    base.camera.target = Vec3::ZERO;
    for m in base.materials.iter_mut() {
        m.diffuse = Vec3::ONE;
        m.specular = Vec3::ZERO;
    }
    let mut light = base.lights[0].clone();
    light.kind = LightKind::Point;
    light.position = Vec3::new(4.9, 0.0, 2.04);
    light.color = Vec3::new(0.02, 0.01, 0.005);
    light.intensity = 1.0;
    (light.kc, light.kl, light.kq) = (1.0, 0.0, 0.01);
    base.lights = vec![light.clone()];
    // A radius of about 1 (0.02 / (1 + 0.01 r^2) = 0.0198): the sphere, 5
    // away, is in the light's far part, and samples reach 1/4 of a unit.
    base.render.cutoff = 0.0198;
    let s = harmonics(&base, 8, 1.0);
    let fov = match base.camera.projection {
        gloss::scene::Projection::Perspective { fov_y_degrees } => fov_y_degrees,
        _ => unreachable!("the scene's camera is a perspective one"),
    };
    let ctx = common::context(common::backend());
    let r = gloss::renderer::render_scene(&ctx, &s, Output::Srgb8).unwrap();
    let light_target = r
        .targets()
        .find(gloss::frame::targets::LIGHT_ACCUMULATION)
        .unwrap();
    let texels = light_target.read_rgba_f32(0);
    let at = ((31 * size + 32) * 4) as usize;
    let got = Vec3::new(texels[at], texels[at + 1], texels[at + 2]);
    let cpu = [FarLight {
        position: light.position,
        color: light.color,
        atten: Vec3::new(1.0, 0.0, 0.01),
        radius: 1.0,
    }];
    let pixel = on_sphere(eye, fov, size, 32, 31);
    let (fx, fy) = (0.5625, 0.4375);
    let mut want = Vec3::ZERO;
    for (tx, ty, w) in [
        (28, 28, (1.0 - fx) * (1.0 - fy)),
        (36, 28, fx * (1.0 - fy)),
        (28, 36, (1.0 - fx) * fy),
        (36, 36, fx * fy),
    ] {
        let sample = on_sphere(eye, fov, size, tx, ty);
        let total = cpu[0].far_radiance(sample, 1.0).0.max_element();
        assert!(
            far_field_sh::serves(total, (pixel - sample).length(), 1.0),
            "sample ({tx}, {ty}) should serve the pixel"
        );
        let c = far_field_sh::project_exact_at(&cpu, sample, sample, 1.0);
        want += w * far_field_sh::irradiance(&c, pixel);
    }
    // Not vacuous: the harmonics without band 0's move to the sample's
    // exact light (far_field_sh::project) give another value.
    let mut plain = Vec3::ZERO;
    for (tx, ty, w) in [
        (28, 28, (1.0 - fx) * (1.0 - fy)),
        (36, 28, fx * (1.0 - fy)),
        (28, 36, (1.0 - fx) * fy),
        (36, 36, fx * fy),
    ] {
        let sample = on_sphere(eye, fov, size, tx, ty);
        plain += w * far_field_sh::irradiance(&far_field_sh::project(&cpu, sample, 1.0), pixel);
    }
    let exact = far_field_sh::exact(&cpu, pixel, pixel, 1.0);
    for ch in 0..3 {
        assert!(
            (got[ch] - want[ch]).abs() <= 0.01 * want[ch] + 1e-6,
            "channel {ch}: shader {got} CPU harmonics {want} (exact {exact}, without the move {plain})"
        );
    }
    assert!(
        (plain.x - want.x).abs() > 0.025 * want.x,
        "the harmonics without the move {plain} should differ from {want} here"
    );
    eprintln!("shader {got}, CPU {want}, exact {exact}, without the move {plain}");
}

#[test]
fn the_plan_names_the_harmonics_and_the_near_radius() {
    let mut base = common::scene("far-field-spheres.toml");
    base.render.size = (1280, 720);
    let plan = gloss::techniques::plan(&base);
    let text = plan.to_string();
    assert!(plan.has_pass("far field"), "{text}");
    assert!(
        text.contains(
            "diffuse as order-2 spherical harmonics; near part to 0.5 x the cutoff radius"
        ),
        "{text}"
    );
    let mut old = base.clone();
    old.render.far_field_sh = false;
    let text = gloss::techniques::plan(&old).to_string();
    assert!(text.contains("diffuse at the sample's normal"), "{text}");
}

// The CPU reference itself (src/lighting/far_field_sh.rs).

/// A small deterministic generator (no crate needed for a test's spread).
fn next(state: &mut u64) -> f32 {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    ((*state >> 40) as f32) / ((1u64 << 24) as f32)
}

fn unit(state: &mut u64) -> Vec3 {
    loop {
        let v = Vec3::new(next(state), next(state), next(state)) * 2.0 - 1.0;
        let l = v.length();
        if l > 0.1 && l <= 1.0 {
            return v / l;
        }
    }
}

#[test]
fn the_basis_integrates_to_an_orthonormal_set() {
    // Quadrature over the sphere (an independent check of the constants).
    let (nt, np) = (400, 800);
    let mut gram = [[0.0f64; 9]; 9];
    for i in 0..nt {
        let t = (i as f64 + 0.5) / nt as f64 * std::f64::consts::PI;
        for k in 0..np {
            let p = (k as f64 + 0.5) / np as f64 * 2.0 * std::f64::consts::PI;
            let n = Vec3::new(
                (t.sin() * p.cos()) as f32,
                (t.sin() * p.sin()) as f32,
                t.cos() as f32,
            );
            let y = far_field_sh::basis(n);
            let dw = t.sin()
                * (std::f64::consts::PI / nt as f64)
                * (2.0 * std::f64::consts::PI / np as f64);
            for a in 0..9 {
                for b in 0..9 {
                    gram[a][b] += f64::from(y[a]) * f64::from(y[b]) * dw;
                }
            }
        }
    }
    for (a, row) in gram.iter().enumerate() {
        for (b, &g) in row.iter().enumerate() {
            let want = if a == b { 1.0 } else { 0.0 };
            assert!((g - want).abs() < 2e-4, "<Y{a}, Y{b}> = {g}");
        }
    }
}

#[test]
fn one_light_is_off_by_at_most_three_32nds_and_exactly_that_at_90_degrees() {
    let light = FarLight {
        position: Vec3::new(0.0, 0.0, 10.0),
        color: Vec3::ONE,
        atten: Vec3::new(1.0, 0.0, 0.0),
        radius: 0.0, // all far
    };
    let c = far_field_sh::project(&[light], Vec3::ZERO, 1.0);
    let mut worst: f32 = 0.0;
    for i in 0..=1800 {
        let t = (i as f32 / 1800.0) * PI;
        let n = Vec3::new(t.sin(), 0.0, t.cos());
        let got = far_field_sh::irradiance(&c, n).x;
        let want = t.cos().max(0.0);
        worst = worst.max((got - want).abs());
    }
    assert!(
        (worst - far_field_sh::TRUNCATION).abs() < 1e-4,
        "worst {worst}"
    );
    // Facing the light: 1/4 + 1/2 + 5/16.
    assert!((far_field_sh::irradiance(&c, Vec3::Z).x - 1.0625).abs() < 1e-4);
}

#[test]
fn the_bound_holds_for_random_lights_points_and_normals() {
    let mut s = 12345u64;
    let mut tightest = f32::INFINITY;
    for case in 0..200 {
        let lights: Vec<FarLight> = (0..32)
            .map(|_| FarLight {
                position: Vec3::new(next(&mut s), next(&mut s), next(&mut s)) * 8.0 - 4.0,
                color: Vec3::new(next(&mut s), next(&mut s), next(&mut s)) * 0.6,
                atten: Vec3::new(1.0, 0.7, 1.8),
                radius: 3.874,
            })
            .collect();
        let near_scale = [1.0, 0.5, 0.25][case % 3];
        let rho = 0.25 * near_scale;
        let sample = Vec3::new(next(&mut s), next(&mut s), next(&mut s)) - 0.5;
        let n_s = unit(&mut s);
        let c = far_field_sh::project_exact_at(&lights, sample, n_s, near_scale);
        // At the sample's own normal and point: exact.
        let at = far_field_sh::irradiance(&c, n_s)
            - far_field_sh::exact(&lights, sample, n_s, near_scale);
        assert!(at.abs().max_element() < 1e-4, "case {case}: {at}");
        for i in 0..20 {
            let x = sample + unit(&mut s) * rho * next(&mut s);
            // Normals near the sample's (a curved surface) and anywhere.
            let n = if i % 2 == 0 {
                (n_s + unit(&mut s) * 0.3 * next(&mut s)).normalize()
            } else {
                unit(&mut s)
            };
            let off = (x - sample).length();
            let turn = (n - n_s).length();
            let err = (far_field_sh::irradiance(&c, n)
                - far_field_sh::exact(&lights, x, n, near_scale))
            .abs();
            let b = far_field_sh::bound(&lights, sample, off, rho, near_scale, turn);
            assert!(
                err.max_element() <= b * 1.0001 + 1e-6,
                "case {case}: {err} > {b}"
            );
            tightest = tightest.min(b / err.max_element().max(1e-9));
        }
    }
    // Not vacuous: somewhere the error is within 20x of the bound.
    assert!(tightest < 20.0, "bound at least {tightest}x the error");
}

/// The truncation term is tight where it should be: one light on the
/// sample's horizon (N_s . L = 0, where g changes fastest), the pixel at the
/// sample's point with its normal turned 0.1 rad towards the light. The
/// error is then 0.0453 c and the bound 0.0500 c: a slope below 1/2 in the
/// bound would not hold here.
#[test]
fn the_truncation_bound_is_tight_at_the_horizon() {
    let light = FarLight {
        position: Vec3::new(10.0, 0.0, 0.0),
        color: Vec3::ONE,
        atten: Vec3::new(1.0, 0.0, 0.0),
        radius: 0.0, // all far
    };
    let n_s = Vec3::Z;
    let n = Vec3::new(0.1f32.sin(), 0.0, 0.1f32.cos());
    let c = far_field_sh::project_exact_at(&[light], Vec3::ZERO, n_s, 1.0);
    let err = (far_field_sh::irradiance(&c, n) - far_field_sh::exact(&[light], Vec3::ZERO, n, 1.0))
        .abs()
        .x;
    let b = far_field_sh::bound(&[light], Vec3::ZERO, 0.0, 0.0, 1.0, (n - n_s).length());
    assert!(err <= b, "error {err} over bound {b}");
    assert!(err > 0.85 * b, "error {err} should be near the bound {b}");
}
