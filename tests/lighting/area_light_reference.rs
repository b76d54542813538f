//! The area lights' reference (`render.area_light_reference`,
//! glsl/lighting/area_light_reference.glsl): gloss's own BRDF integrated
//! over each light by quadrature on the GPU, the image `gloss bench`
//! measures LTC against. Checked per pixel against the CPU's Monte Carlo
//! integral of the same BRDF (src/lighting/area_light.rs): random jittered
//! points over the whole rectangle in f64, no clipping, against the
//! shader's centroids of the horizon-clipped polygon's triangles in f32.
//! Hard cases: smooth and rough, head-on and grazing, straddling the
//! horizon, a light behind the surface (0), seen from behind (0 one-sided,
//! lit two-sided), Phong's lobe. Converged: N against 2N points. The
//! table-Fresnel variant against the CPU's F = 1 lobe times the table's
//! Schlick average.

use super::ltc_area_lights::{KD, RADIANCE, beside, lit_plane, pixels};
use crate::common;
use glam::DVec3;
use gloss::lighting::area_light::{QuadLight, monte_carlo_solid_angle, polygon_irradiance};
use gloss::lighting::{ltc, microfacet};
use gloss::renderer::Output;
use gloss::scene::Scene;
use gloss::scene::area_lights::AreaLightReference;
use std::f64::consts::PI;

const ETA: f64 = 1.5;
/// The Phong material's specular colour.
const KS_PHONG: f64 = 0.5;

#[derive(Clone, Copy, Debug)]
enum Lobe {
    /// gloss's microfacet BRDF at this alpha (eta 1.5, k_s 1).
    Microfacet(f64),
    /// Phong's Blinn lobe at this shininess.
    Phong(f64),
}

fn material(lobe: Lobe) -> String {
    match lobe {
        Lobe::Microfacet(a) => format!("model = \"microfacet\"\nalpha = {a}\neta = {ETA}"),
        Lobe::Phong(s) => {
            format!("specular = [{KS_PHONG}, {KS_PHONG}, {KS_PHONG}]\nshininess = {s}")
        }
    }
}

/// The plane of tests/lighting/ltc_area_lights.rs, shaded by the reference.
fn reference_plane(light: &str, lobe: Lobe, tilt: f32, mode: AreaLightReference, n: u32) -> Scene {
    let mut scene = lit_plane(light, &material(lobe), tilt);
    scene.render.area_light_reference = mode;
    scene.render.area_light_points = n;
    scene
}

/// The light above the side of the plane tilted 72 degrees from the eye.
const ABOVE: &str = "center = [0.0, 1.2, 1.5]\nsize = [1.2, 0.8]\nnormal = [0.0, -0.6, -1.0]";
/// Under the plane, facing up: behind the surface.
const BELOW: &str = "center = [0.0, -0.5, 0.0]\nsize = [1.0, 1.0]\nnormal = [0.0, 1.0, 0.0]";
/// Beside the plane, facing away from it.
const AWAY: &str = "center = [1.5, 0.5, 0.1]\nsize = [0.8, 0.6]\nnormal = [1.0, 0.0, 0.0]";

/// gloss's specular lobe times N . w, per solid angle, at direction w
/// (the shader's `reference_point`, from src/lighting/microfacet.rs): the
/// microfacet BRDF with its exact Fresnel, or with F = 1 (`f_one`); Phong's
/// Blinn lobe over pi.
fn lobe_at(lobe: Lobe, w: DVec3, v: DVec3, n: DVec3, f_one: bool) -> f64 {
    let cos = n.dot(w);
    if cos <= 0.0 {
        return 0.0;
    }
    match lobe {
        Lobe::Microfacet(a) => {
            let f = microfacet::brdf(w, v, n, a, ETA, 1.0) * cos;
            let fresnel = microfacet::fresnel_dielectric((w + v).normalize().dot(v), ETA);
            if f_one { f / fresnel } else { f }
        }
        Lobe::Phong(s) => n.dot((w + v).normalize()).max(0.0).powf(s) / PI,
    }
}

/// The CPU's value of a pixel and its standard error: k_d L_e E / pi with
/// E by Lambert's exact formula, plus k_s L_e times the Monte Carlo
/// integral of the lobe (times `fresnel`, the table's Schlick average, when
/// it is Some: F = 1 per sample then).
fn cpu_pixel(
    p: DVec3,
    n: DVec3,
    v: DVec3,
    quad: &QuadLight,
    lobe: Lobe,
    fresnel: Option<f64>,
    seed: u64,
) -> (f64, f64) {
    let l_e = f64::from(RADIANCE);
    let diffuse = KD * l_e * polygon_irradiance(p, n, quad) / PI;
    let (spec, se) = monte_carlo_solid_angle(p, quad, 160, seed, |w| {
        lobe_at(lobe, w, v, n, fresnel.is_some())
    });
    let ks = match lobe {
        Lobe::Microfacet(_) => fresnel.unwrap_or(1.0),
        Lobe::Phong(_) => KS_PHONG,
    };
    (diffuse + ks * l_e * spec, ks * l_e * se)
}

/// The light as the CPU integrates it: wound toward the pixel when it is
/// two-sided and seen from behind.
fn facing(quad: QuadLight, p: DVec3, two_sided: bool) -> QuadLight {
    let mut q = quad;
    if two_sided && (p - q.corners[0]).dot(q.normal()) < 0.0 {
        q.corners.reverse();
    }
    q
}

/// Every other sampled pixel of the reference against the CPU: returns the
/// worst relative error, the worst error in standard errors, and the sum
/// of the values.
fn against_monte_carlo(light: &str, lobe: Lobe, tilt: f32, two_sided: bool) -> (f64, f64, f64) {
    let light = format!("{light}\ntwo_sided = {two_sided}");
    let scene = reference_plane(&light, lobe, tilt, AreaLightReference::Exact, 32);
    let quad = QuadLight::of(&scene.area_lights[0]);
    let (mut worst_rel, mut worst_se, mut total) = (0.0f64, 0.0f64, 0.0);
    for (x, y, got, p, n, v) in pixels(&scene) {
        if (x + y) % 2 != 0 {
            continue;
        }
        let q = facing(quad, p, two_sided);
        let (want, se) = cpu_pixel(p, n, v, &q, lobe, None, u64::from(x * 131 + y));
        let err = (got - want).abs();
        if want > 1e-4 {
            worst_rel = worst_rel.max(err / want);
        }
        worst_se = worst_se.max(err / se.max(1e-12));
        // The quadrature's own error (N = 32: below 0.02 % of the peak, the
        // convergence test), f32 and the 16-bit float target: 0.05 %
        // (measured at most 0.019 %); the Monte Carlo's: 4 standard errors
        // (of independent samples; the jittered ones err far less).
        assert!(
            err <= 5e-4 * want + 4.0 * se + 1e-6,
            "{light}, {lobe:?}, tilt {tilt}: pixel ({x}, {y}) is {got}, Monte Carlo says {want} +- {se}"
        );
        total += want;
    }
    (worst_rel, worst_se, total)
}

#[test]
fn the_reference_is_glosss_brdf_integrated_per_pixel() {
    let cases: [(&str, String, Lobe, f32, bool); 8] = [
        (
            "head-on, smooth",
            beside(0.2),
            Lobe::Microfacet(0.1),
            0.0,
            false,
        ),
        (
            "head-on, rough",
            beside(0.2),
            Lobe::Microfacet(0.5),
            0.0,
            false,
        ),
        (
            "grazing, smooth",
            ABOVE.into(),
            Lobe::Microfacet(0.1),
            72.0,
            false,
        ),
        (
            "grazing, rough",
            ABOVE.into(),
            Lobe::Microfacet(0.5),
            72.0,
            false,
        ),
        (
            "straddling the horizon",
            beside(-0.3),
            Lobe::Microfacet(0.3),
            0.0,
            false,
        ),
        ("Phong's lobe", beside(0.2), Lobe::Phong(32.0), 0.0, false),
        (
            "Phong's lobe, grazing",
            ABOVE.into(),
            Lobe::Phong(8.0),
            72.0,
            false,
        ),
        (
            "seen from behind, two-sided",
            AWAY.into(),
            Lobe::Microfacet(0.2),
            0.0,
            true,
        ),
    ];
    for (what, light, lobe, tilt, two_sided) in cases {
        let (rel, se, total) = against_monte_carlo(&light, lobe, tilt, two_sided);
        eprintln!(
            "{what}: worst {:.3} % of the value, {se:.2} standard errors",
            100.0 * rel
        );
        assert!(total > 0.05, "{what}: lit {total}");
    }
    // Nothing from a light behind the surface or a one-sided light seen
    // from behind: exactly 0, as gloss's BRDF gives.
    for (what, light) in [("behind the surface", BELOW), ("seen from behind", AWAY)] {
        let scene = reference_plane(
            light,
            Lobe::Microfacet(0.3),
            0.0,
            AreaLightReference::Exact,
            32,
        );
        for (x, y, got, ..) in pixels(&scene) {
            assert_eq!(got, 0.0, "{what}: pixel ({x}, {y})");
        }
    }
}

/// The largest difference between the images at N and 2N points, over the
/// brightest pixel of the 2N image (red channel, linear, every pixel).
fn n_against_2n(light: &str, lobe: Lobe, tilt: f32, n: u32) -> f64 {
    let image = |n| {
        let scene = reference_plane(light, lobe, tilt, AreaLightReference::Exact, n);
        common::render(&scene, Output::Linear32F).linear
    };
    let (a, b) = (image(n), image(2 * n));
    let peak = b.iter().step_by(4).fold(0.0f32, |m, &x| m.max(x));
    let diff = a
        .iter()
        .zip(&b)
        .step_by(4)
        .fold(0.0f32, |m, (x, y)| m.max((x - y).abs()));
    assert!(peak > 0.01, "{light}: peak {peak}");
    f64::from(diff / peak)
}

#[test]
fn the_reference_converges_n_against_2n() {
    // The midpoint rule's error falls as 1 / N^2: at the default N = 32
    // against 64, every pixel of the hard cases within 0.05 % of the
    // brightest (measured 0.004-0.013 %), and 8 times closer than N = 8
    // against 16 (measured 15-16 times: 4^2).
    for (what, light, lobe, tilt) in [
        (
            "smooth, grazing",
            ABOVE.to_string(),
            Lobe::Microfacet(0.1),
            72.0,
        ),
        (
            "straddling the horizon",
            beside(-0.3),
            Lobe::Microfacet(0.3),
            0.0,
        ),
        ("Phong", beside(0.2), Lobe::Phong(32.0), 0.0),
    ] {
        let fine = n_against_2n(&light, lobe, tilt, 32);
        let coarse = n_against_2n(&light, lobe, tilt, 8);
        eprintln!(
            "{what}: N 32 against 64: {:.4} %, N 8 against 16: {:.4} %",
            100.0 * fine,
            100.0 * coarse
        );
        assert!(
            fine < 5e-4,
            "{what}: N = 32 against 64 differ by {fine} of the peak"
        );
        assert!(fine < coarse / 8.0, "{what}: {fine} against {coarse}");
    }
}

#[test]
fn the_table_fresnel_variant_is_the_f_one_lobe_times_the_tables_average() {
    // A microfacet plane: every other pixel against the CPU's F = 1 lobe
    // times F0 magnitude + (1 - F0) fresnel over magnitude from the table,
    // read as src/lighting/ltc.rs reads it.
    let lobe = Lobe::Microfacet(0.3);
    let scene = reference_plane(
        &beside(0.2),
        lobe,
        0.0,
        AreaLightReference::TableFresnel,
        32,
    );
    let quad = QuadLight::of(&scene.area_lights[0]);
    let f0 = ltc::f0(ETA);
    for (x, y, got, p, n, v) in pixels(&scene) {
        if (x + y) % 2 != 0 {
            continue;
        }
        let t = ltc::bilinear(ltc::ltc_2(), ltc::table_coords(0.3, n.dot(v)));
        let fresnel = (f0 * t[0] + (1.0 - f0) * t[1]) / t[0];
        let (want, se) = cpu_pixel(p, n, v, &quad, lobe, Some(fresnel), u64::from(x * 131 + y));
        // The GPU reads the table with GL_LINEAR (8-bit weights on llvmpipe): 1 %.
        assert!(
            (got - want).abs() <= 1e-2 * want + 4.0 * se + 1e-6,
            "pixel ({x}, {y}) is {got}, the CPU says {want} +- {se}"
        );
    }
    // Phong has no Fresnel: the variant is the exact reference, bit for bit.
    let phong = |mode| {
        let scene = reference_plane(&beside(0.2), Lobe::Phong(32.0), 0.0, mode, 16);
        common::render(&scene, Output::Linear32F).linear
    };
    assert_eq!(
        phong(AreaLightReference::TableFresnel),
        phong(AreaLightReference::Exact)
    );
}

#[test]
fn bad_reference_keys_are_errors_that_name_the_key() {
    let path = common::root().join("scenes/t.toml");
    let with = |keys: &str| {
        format!(
            "name = \"t\"\n[camera]\neye = [0.0, 1.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n[render]\n{keys}\n"
        )
    };
    for (keys, says) in [
        (
            "area_light_points = 0",
            "render.area_light_points: expected 1..=256 (N x N points per triangle of a light), found 0",
        ),
        ("area_light_points = 257", "found 257"),
        (
            "area_light_reference = \"monte_carlo\"",
            "expected off, exact or table_fresnel, found \"monte_carlo\"",
        ),
    ] {
        let e = format!("{:#}", Scene::parse(&with(keys), &path).unwrap_err());
        assert!(e.contains(says), "{keys}: {e}");
    }
    let ok = Scene::parse(
        &with("area_light_reference = \"exact\"\narea_light_points = 64"),
        &path,
    );
    let r = ok.unwrap().render;
    assert_eq!(
        (r.area_light_reference, r.area_light_points),
        (AreaLightReference::Exact, 64)
    );
}
