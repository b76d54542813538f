//! Area lights with linearly transformed cosines
//! (src/techniques/lighting/ltc_area_lights.rs, glsl/lighting/ltc_area_lights.glsl):
//! a plane lit by one rectangle, every sampled pixel against references
//! independent of the shader: the diffuse term against the exact polygon
//! integral of src/lighting/area_light.rs (Lambert's formula, acos form)
//! per pixel; the full shading against the CPU twin (src/lighting/ltc.rs)
//! and against the Monte Carlo integral of gloss's own BRDF over the light
//! (bounds from the measured LTC error, src/lighting/ltc/tests.rs). Hard
//! cases: a light behind the surface (0), straddling the horizon (clipped),
//! seen from behind (0, or lit when two-sided), grazing view, smooth and
//! rough. And the scene's warnings on the shadings that leave the lights out
//! (the G-buffer paths: tests/deferred/ltc_area_lights_deferred.rs).

use crate::common;
use glam::{DVec3, Vec3};
use gloss::lighting::area_light::{QuadLight, monte_carlo_specular, polygon_irradiance};
use gloss::lighting::ltc;
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene, Shading};
use std::f64::consts::PI;

pub(super) const SIZE: u32 = 96;
pub(super) const EYE: [f32; 3] = [0.0, 4.0, 0.0];
pub(super) const KD: f64 = 0.5;
pub(super) const RADIANCE: f32 = 2.0;

/// A 2 x 2 plane (tilted `tilt` degrees about x) filling the image of an
/// orthographic camera above it, lit by one area light and nothing else.
pub(super) fn lit_plane(light: &str, material: &str, tilt: f32) -> Scene {
    let text = format!(
        "name = \"t\"\n[camera]\nprojection = \"orthographic\"\neye = {EYE:?}\n\
         target = [0.0, 0.0, 0.0]\nup = [0.0, 0.0, -1.0]\nhalf_height = 1.0\nnear = 1.0\nfar = 10.0\n\
         [render]\nsize = [{SIZE}, {SIZE}]\npath = \"forward\"\nambient = [0.0, 0.0, 0.0]\n\
         [[area_lights]]\n{light}\ncolor = [1.0, 1.0, 1.0]\nintensity = {RADIANCE}\n\
         [materials.m]\ndiffuse = [{KD}, {KD}, {KD}]\n{material}\n\
         [[objects]]\nmesh = \"plane\"\nmaterial = \"m\"\nrotation = [{tilt}, 0.0, 0.0]\n"
    );
    Scene::parse(&text, &common::root().join("scenes/t.toml")).unwrap()
}

/// The world point and normal pixel (x, y from the bottom) shows: the
/// camera's vertical ray through (x, z) meeting the plane; None off it.
fn surface_at(scene: &Scene, x: u32, y: u32) -> Option<(DVec3, DVec3)> {
    let s = f64::from(SIZE);
    let (px, pz) = (
        (2.0 * f64::from(x) + 1.0) / s - 1.0,
        1.0 - (2.0 * f64::from(y) + 1.0) / s,
    );
    let model = scene.objects[0].model.as_dmat4();
    let n = model.transform_vector3(DVec3::Y).normalize();
    let p = DVec3::new(px, -(n.x * px + n.z * pz) / n.y, pz);
    // Inside the plane, away from its edges.
    let local = model.inverse().transform_point3(p);
    (local.x.abs() < 0.9 && local.z.abs() < 0.9).then_some((p, n))
}

/// Every sampled pixel's red channel, with its point, normal and eye direction.
pub(super) fn pixels(scene: &Scene) -> Vec<(u32, u32, f64, DVec3, DVec3, DVec3)> {
    let r = common::render(scene, Output::Linear32F);
    let mut out = Vec::new();
    for y in (2..SIZE).step_by(7) {
        for x in (2..SIZE).step_by(7) {
            if let Some((p, n)) = surface_at(scene, x, y) {
                let v = (Vec3::from(EYE).as_dvec3() - p).normalize();
                let got = f64::from(r.linear[((y * SIZE + x) * 4) as usize]);
                out.push((x, y, got, p, n, v));
            }
        }
    }
    assert!(out.len() > 20, "{} pixels on the plane", out.len());
    out
}

/// A Phong material with no specular colour: the diffuse term alone.
const MATTE: &str = "specular = [0.0, 0.0, 0.0]";

/// A 0.8 x 0.6 light beside the plane (outside the image), facing -x.
pub(super) fn beside(bottom: f32) -> String {
    let centre = bottom + 0.3;
    format!("center = [1.5, {centre}, 0.1]\nsize = [0.8, 0.6]\nnormal = [-1.0, 0.0, 0.0]")
}

fn diffuse_matches(light: &str, tilt: f32, two_sided: bool) -> f64 {
    let light = format!("{light}\ntwo_sided = {two_sided}");
    let scene = lit_plane(&light, MATTE, tilt);
    let quad = QuadLight::of(&scene.area_lights[0]);
    let mut total = 0.0;
    for (x, y, got, p, n, _) in pixels(&scene) {
        // Two-sided from behind: the same rectangle wound the other way.
        let mut q = quad;
        if two_sided && (p - q.corners[0]).dot(q.normal()) < 0.0 {
            q.corners.reverse();
        }
        let want = KD * f64::from(RADIANCE) * polygon_irradiance(p, n, &q) / PI;
        // f32 shading into a 16-bit float target: 1e-3 of the value.
        assert!(
            (got - want).abs() <= 1e-3 * want + 1e-6,
            "{light}, tilt {tilt}: pixel ({x}, {y}) is {got}, Lambert's formula says {want}"
        );
        total += want;
    }
    total
}

#[test]
fn the_diffuse_term_is_the_exact_polygon_integral_per_pixel() {
    // In front, tilted toward the light, and straddling the horizon (its
    // lower half below the plane: clipped, not counted negative).
    assert!(diffuse_matches(&beside(0.2), 0.0, false) > 0.1);
    assert!(diffuse_matches(&beside(0.2), -20.0, false) > 0.1);
    assert!(diffuse_matches(&beside(-0.3), 0.0, false) > 0.01);
    // Behind the surface: under the plane, facing up. Exactly 0.
    let below = "center = [0.0, -0.5, 0.0]\nsize = [1.0, 1.0]\nnormal = [0.0, 1.0, 0.0]";
    assert_eq!(diffuse_matches(below, 0.0, false), 0.0);
    // Seen from behind: one-sided 0, two-sided lit.
    let away = "center = [1.5, 0.5, 0.1]\nsize = [0.8, 0.6]\nnormal = [1.0, 0.0, 0.0]";
    assert_eq!(diffuse_matches(away, 0.0, false), 0.0);
    assert!(diffuse_matches(away, 0.0, true) > 0.1);
}

#[test]
fn the_full_shading_against_the_cpu_twin_and_monte_carlo() {
    // (alpha, tilt): smooth and rough, head-on and grazing (the plane
    // tilted 72 degrees from the eye).
    for (alpha, tilt) in [(0.1, 0.0), (0.5, 0.0), (0.1, 72.0), (0.5, 72.0)] {
        let material = format!("model = \"microfacet\"\nalpha = {alpha}\neta = 1.5");
        // Head-on: beside the plane; grazing: above the side the plane faces.
        let light = if tilt == 0.0 {
            beside(0.2)
        } else {
            "center = [0.0, 1.2, 1.5]\nsize = [1.2, 0.8]\nnormal = [0.0, -0.6, -1.0]".to_string()
        };
        let scene = lit_plane(&light, &material, tilt);
        let quad: QuadLight = QuadLight::of(&scene.area_lights[0]);
        let l_e = f64::from(RADIANCE);
        let (mut worst_twin, mut worst_mc, mut most_specular) = (0.0f64, 0.0f64, 0.0f64);
        let mut lit = 0;
        for (x, y, got, p, n, v) in pixels(&scene) {
            let ff = ltc::diffuse_form_factor(p, n, &quad, false);
            let twin = l_e * (KD * ff + ltc::ltc_specular(p, n, v, &quad, (alpha, 1.5), false));
            // The shader against its CPU twin: the table read by GL_LINEAR
            // (8-bit weights on llvmpipe), f32, a 16-bit float target.
            let twin_err = (got - twin).abs() / twin.max(1e-3);
            most_specular = most_specular.max(1.0 - l_e * KD * ff / twin.max(1e-9));
            worst_twin = worst_twin.max(twin_err);
            assert!(
                twin_err < 0.02,
                "alpha {alpha}, tilt {tilt}: pixel ({x}, {y}) is {got}, the CPU twin says {twin}"
            );
            if twin > 1e-3 {
                lit += 1;
            }
            if (x + y) % 3 == 0 && twin > 0.0 {
                let (spec, se) = monte_carlo_specular(p, n, v, &quad, (alpha, 1.5), 120, 5);
                let want = l_e * (KD * ff + spec);
                // The LTC error measured on the CPU (facing 17 %, grazing
                // 75 % of the larger of the highlight and the form
                // factor), on the specular part only.
                let err = (got - want).abs() / (l_e * spec.max(ff));
                worst_mc = worst_mc.max(err);
                let bound = if tilt == 0.0 { 0.20 } else { 0.80 };
                assert!(
                    err < bound + 4.0 * se / spec.max(ff).max(1e-9),
                    "alpha {alpha}, tilt {tilt}: pixel ({x}, {y}) is {got}, Monte Carlo says {want} (error {err:.3} of the larger term)"
                );
            }
        }
        assert!(lit > 20, "alpha {alpha}, tilt {tilt}: {lit} pixels lit");
        eprintln!(
            "alpha {alpha}, tilt {tilt}: worst against the CPU twin {:.4} %, against Monte Carlo {:.1} %; the highlight up to {:.0} % of a pixel",
            100.0 * worst_twin,
            100.0 * worst_mc,
            100.0 * most_specular
        );
    }
}

#[test]
fn other_shadings_say_they_leave_the_lights_out() {
    let scene = common::scene("area-lights.toml");
    let warned = |s: &Scene| {
        let w = s.warnings();
        w.iter().any(|w| {
            w.starts_with("area_lights: the 3 area lights") && w.contains("per fragment only")
        })
    };
    assert!(!warned(&scene));
    // Gouraud shading on the forward path leaves them out, and says so.
    let mut gouraud = scene.clone();
    gouraud.render.shading = Shading::Gouraud;
    assert!(warned(&gouraud), "{:?}", gouraud.warnings());
    let plan = gloss::techniques::plan(&gouraud);
    assert!(
        plan.passes
            .iter()
            .all(|p| !p.name.starts_with("area lights"))
    );
    // A G-buffer path lights every pixel whatever render.shading says: the
    // area lights are drawn (deferred/ltc_area_lights_deferred.rs), no warning.
    gouraud.render.path = RenderPath::Deferred;
    assert!(
        gouraud
            .warnings()
            .iter()
            .all(|w| !w.starts_with("area_lights")),
        "{:?}",
        gouraud.warnings()
    );
    let plan = gloss::techniques::plan(&gouraud);
    assert!(plan.has_pass("area lights (LTC)") && plan.has_pass("area lights"));
}

#[test]
fn bad_area_light_keys_are_errors_that_name_the_key() {
    let base = "name = \"t\"\n[camera]\neye = [0.0, 1.0, 3.0]\ntarget = [0.0, 0.0, 0.0]\n";
    let light = |keys: &str| format!("{base}[[area_lights]]\n{keys}\n");
    let good = "center = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\nnormal = [0.0, -1.0, 0.0]";
    let path = common::root().join("scenes/t.toml");
    assert!(Scene::parse(&light(good), &path).is_ok());
    for (keys, says) in [
        (
            "center = [0.0, 1.0, 0.0]\nsize = [1.0, 0.0]\nnormal = [0.0, -1.0, 0.0]",
            "area_lights[0].size: expected a width and height in (0, 1e4]",
        ),
        (
            "center = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\nnormal = [0.0, 0.0, 0.0]",
            "area_lights[0].normal: must not be zero",
        ),
        (
            &format!("{good}\nup = [0.0, 2.0, 0.0]"),
            "area_lights[0].up: expected a direction not parallel to normal",
        ),
        (
            &format!("{good}\nintensity = -1.0"),
            "area_lights[0].intensity: expected values >= 0",
        ),
        (&format!("{good}\ncolour = [1.0, 1.0, 1.0]"), "colour"),
    ] {
        let e = format!("{:#}", Scene::parse(&light(keys), &path).unwrap_err());
        assert!(e.contains(says), "{keys}: {e}");
    }
    let nine = (0..9)
        .map(|_| format!("[[area_lights]]\n{good}\n"))
        .collect::<String>();
    let e = format!(
        "{:#}",
        Scene::parse(&format!("{base}{nine}"), &path).unwrap_err()
    );
    assert!(
        e.contains("area_lights: expected at most 8 area lights, found 9"),
        "{e}"
    );
}
