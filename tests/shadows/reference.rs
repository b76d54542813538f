//! Shadows against the exact reference (src/bench/shadows.rs: a ray from
//! each pixel's surface point to the light, src/lighting/shadow_reference.rs).
//! Bounds, with the default knobs, at 480 x 270:
//!
//! * misclassified (outside the one-pixel band around the true boundary):
//!   at most 1% of judged pixels on every shadow scene, in every path;
//! * acne: at most 0.5% of truly lit pixels;
//! * peter-panning on the contact scene: the mapped shadow starts within
//!   0.05 world units of the true one.
//!
//! And the knobs do what the notes say: without any bias the grazing sun
//! covers the floor in acne; a bias larger than the plank is thick detaches
//! its shadow.

use crate::common;
use gloss::bench::shadows::{ShadowEvaluation, evaluate};
use gloss::image_compare::shadow_mask::GlShadow;
use gloss::image_compare::shadow_metrics::Visibility;
use gloss::lighting::shadow_reference::{pixel_world_point, sphere_shadow_on_plane};
use gloss::scene::{RenderPath, Scene};
use image::{Rgba, RgbaImage};

fn small(name: &str) -> Scene {
    let mut s = common::scene(name);
    s.render.size = (480, 270);
    s
}

/// The GL mask over the reference: green both lit, dark both shadowed, red
/// GL shadowed where lit, blue GL lit where shadowed (written on failure).
fn mask_image(e: &ShadowEvaluation) -> RgbaImage {
    let (w, h) = (e.mask.width as u32, e.mask.height as u32);
    RgbaImage::from_fn(w, h, |x, y| {
        let i = ((h - 1 - y) * w + x) as usize;
        match (e.mask.pixels[i], e.reference[i]) {
            (_, Visibility::Background) | (GlShadow::Ignored, _) => Rgba([40, 40, 40, 255]),
            (GlShadow::Lit, Visibility::Lit) => Rgba([90, 200, 90, 255]),
            (GlShadow::Shadowed, Visibility::Shadowed) => Rgba([10, 60, 10, 255]),
            (GlShadow::Shadowed, Visibility::Lit) => Rgba([255, 0, 0, 255]),
            (GlShadow::Lit, Visibility::Shadowed) => Rgba([0, 80, 255, 255]),
        }
    })
}

fn check(label: &str, e: &ShadowEvaluation, ok: bool, what: &str) {
    if !ok {
        let dir = common::out_dir();
        let mask = dir.join(format!("{label}.shadow-mask.png"));
        let actual = dir.join(format!("{label}.actual.png"));
        mask_image(e).save(&mask).unwrap();
        e.images[0].save(&actual).unwrap();
        panic!(
            "{label}: {what}: {} (mask against the reference: {}, image: {})",
            e.errors,
            mask.display(),
            actual.display()
        );
    }
}

#[test]
fn every_shadow_scene_matches_the_exact_shadows_in_every_path() {
    let ctx = common::context(common::backend());
    for name in [
        "shadows-directional.toml",
        "shadows-spot.toml",
        "shadows-point.toml",
        "shadows-grazing.toml",
        "shadows-contact.toml",
    ] {
        for path in RenderPath::ALL {
            let mut s = small(name);
            s.render.path = *path;
            let e = evaluate(&ctx, &s).unwrap();
            let label = format!("{}-{}", s.name, path.name());
            assert!(
                e.errors.judged > 10_000,
                "{label}: {} judged",
                e.errors.judged
            );
            check(
                &label,
                &e,
                e.errors.misclassified <= 0.01,
                "misclassified > 1%",
            );
            check(&label, &e, e.errors.acne <= 0.005, "acne > 0.5%");
        }
    }
}

#[test]
fn without_bias_a_grazing_sun_covers_the_floor_in_acne() {
    let ctx = common::context(common::backend());
    let mut s = small("shadows-grazing.toml");
    let shadow = s.lights[0].shadow.as_mut().unwrap();
    (shadow.bias, shadow.slope_bias, shadow.normal_offset) = (0.0, 0.0, 0.0);
    let e = evaluate(&ctx, &s).unwrap();
    check(
        "grazing-no-bias",
        &e,
        e.errors.acne > 0.2,
        "expected acne on > 20% of the lit floor",
    );
    let e = evaluate(&ctx, &small("shadows-grazing.toml")).unwrap();
    check("grazing-default", &e, e.errors.acne <= 0.005, "acne > 0.5%");
}

#[test]
fn a_bias_thicker_than_the_plank_detaches_its_shadow_and_the_default_does_not() {
    let ctx = common::context(common::backend());
    let e = evaluate(&ctx, &small("shadows-contact.toml")).unwrap();
    let gap = e.errors.peter_panning.expect("lines from the plank's base");
    check("contact-default", &e, gap.abs() <= 0.05, "gap beyond 0.05");
    let mut s = small("shadows-contact.toml");
    s.lights[0].shadow.as_mut().unwrap().bias = 0.5;
    let e = evaluate(&ctx, &s).unwrap();
    let gap = e.errors.peter_panning.expect("lines from the plank's base");
    check(
        "contact-bias-0.5",
        &e,
        gap > 0.2,
        "expected a detached shadow (gap > 0.2)",
    );
}

#[test]
fn a_sphere_over_a_plane_casts_the_analytic_conic() {
    // A point light above a sphere over the floor: a floor point is in
    // shadow exactly when its segment to the light passes within the
    // radius of the centre. Floor pixels within 2% of the radius of that
    // boundary (the sphere is a mesh; a pixel is not a point) are left out.
    let text = r#"
        name = "sphere-conic"
        [camera]
        eye = [0.0, 7.0, 6.0]
        target = [0.0, 0.0, 0.0]
        fov_y = 50.0
        [render]
        size = [480, 360]
        ambient = [0.05, 0.05, 0.05]
        [[lights]]
        type = "point"
        position = [0.8, 4.0, -0.5]
        intensity = 4.0
        attenuation = [1.0, 0.0, 0.02]
        shadow = { resolution = 1024, pcf = "none" }
        [materials.grey]
        diffuse = [0.8, 0.8, 0.8]
        specular = [0.0, 0.0, 0.0]
        [[objects]]
        name = "floor"
        mesh = "plane"
        material = "grey"
        scale = [6.0, 1.0, 6.0]
        [[objects]]
        name = "ball"
        mesh = "sphere"
        material = "grey"
        position = [0.0, 1.6, 0.0]
        scale = [0.8, 0.8, 0.8]
    "#;
    let s = Scene::parse(text, std::path::Path::new("sphere-conic.toml")).unwrap();
    let ctx = common::context(common::backend());
    let e = evaluate(&ctx, &s).unwrap();
    let (w, h) = (e.mask.width, e.mask.height);
    let (depth, inverse) = (&e.depth, e.inverse_view_projection);
    let (light, centre, radius) = (s.lights[0].position, glam::Vec3::new(0.0, 1.6, 0.0), 0.8);
    let (mut judged, mut wrong, mut shadowed) = (0, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            let d = depth[i];
            if d >= 1.0 || e.mask.pixels[i] == GlShadow::Ignored {
                continue;
            }
            let p = pixel_world_point(x, y, d, inverse, w, h);
            if p.y.abs() > 1e-3 {
                continue; // the sphere, not the floor
            }
            let inner = sphere_shadow_on_plane(light, centre, radius * 0.98, p);
            let outer = sphere_shadow_on_plane(light, centre, radius * 1.02, p);
            if inner != outer {
                continue; // within 2% of the boundary
            }
            judged += 1;
            shadowed += inner as usize;
            wrong += ((e.mask.pixels[i] == GlShadow::Shadowed) != inner) as usize;
        }
    }
    assert!(
        judged > 50_000 && shadowed > 2_000,
        "{judged} judged, {shadowed} in the conic"
    );
    check(
        "sphere-conic",
        &e,
        wrong == 0,
        &format!("{wrong} of {judged} floor pixels disagree with the conic"),
    );
}
