//! src/frame/variant.rs on the paths tests/deferred/shader_variants.rs leaves
//! out, and its switches for the shadow lookup, normal maps and the
//! G-buffer's material encoding:
//!
//! * light volumes (plain and stencilled), the light pre-pass, tiled
//!   shading's far field, Gouraud and flat forward shading: the specialised
//!   programs give the general shader's image within 1/255, and the plan
//!   names each pass's variant;
//! * the shadow switches keep the maps and filters the frame has: a scene
//!   with one point caster keeps one cube and no 2D map; each filter
//!   (none, hardware, 3x3, 5x5, Poisson) and casters in several 2D and cube
//!   slots give the general image within 1/255;
//! * the normal-map and G-buffer switches: bump-mapping with and without
//!   `render.normal_mapping`, microfacet in each `render.gbuffer_encoding`,
//!   the general image within 1/255.

use crate::common;
use crate::with_path;
use gloss::frame::lights::FrameLights;
use gloss::frame::variant::LightingVariant;
use gloss::image_compare::Tolerance;
use gloss::renderer::{Output, render_scene};
use gloss::scene::material::GBufferEncoding;
use gloss::scene::shadows::Pcf;
use gloss::scene::{DeferredLights, RenderPath, Scene, Shading};

const WITHIN_1: Tolerance = Tolerance {
    threshold: 1.0 / 255.0,
    max_frac_over: 0.0,
    max_abs: Some(1.0 / 255.0),
};

fn variant(s: &Scene) -> LightingVariant {
    LightingVariant::of(s, &FrameLights::new(s))
}

fn small(name: &str) -> Scene {
    let mut s = common::scene(name);
    s.render.size = (192, 108);
    s
}

/// Render `special` specialised and general; the images within 1/255, and
/// the plan's pass `pass_name` names the variant.
fn same_as_general(ctx: &gloss::gl::Headless, label: &str, special: &Scene, pass_name: &str) {
    let mut general = special.clone();
    general.render.specialize = false;
    let v = variant(special);
    assert_ne!(v, LightingVariant::GENERAL, "{label}: nothing left out");
    for (s, words) in [
        (special, v.describe()),
        (&general, LightingVariant::GENERAL.describe()),
    ] {
        let plan = gloss::techniques::plan(s);
        let pass = (plan.passes.iter())
            .find(|p| p.name == pass_name)
            .unwrap_or_else(|| panic!("{label}: no pass {pass_name}\n{plan}"));
        assert_eq!(pass.variant.as_deref(), Some(words.as_str()), "{plan}");
    }
    let a = render_scene(ctx, special, Output::Srgb8).expect("specialised");
    let b = render_scene(ctx, &general, Output::Srgb8).expect("general");
    assert_eq!(a.variant(), v);
    let m = common::assert_close(
        &format!("variant-paths-{label}"),
        &a.read_image(),
        &b.read_image(),
        &WITHIN_1,
    );
    eprintln!("{label} [{}]: {m}", v.describe());
}

#[test]
fn the_other_paths_give_the_general_image_and_name_their_variant() {
    let ctx = common::context(common::backend());
    type Setup = fn(&mut Scene);
    let paths: [(&str, Setup, &str); 5] = [
        (
            "volumes",
            |s| s.render.path = RenderPath::Volumes,
            "lighting",
        ),
        (
            "stencil-volumes",
            |s| {
                s.render.path = RenderPath::Volumes;
                s.render.stencil_volumes = true;
            },
            "lighting",
        ),
        (
            "prepass",
            |s| s.render.path = RenderPath::Prepass,
            "light pre-pass",
        ),
        (
            "gouraud",
            |s| {
                s.render.path = RenderPath::Forward;
                s.render.shading = Shading::Gouraud;
            },
            "forward",
        ),
        (
            "flat",
            |s| {
                s.render.path = RenderPath::Forward;
                s.render.shading = Shading::Flat;
            },
            "forward",
        ),
    ];
    for name in [
        "mixed-lights.toml",
        "shadows-point.toml",
        "shadows-spot.toml",
        "microfacet.toml",
        "windowed-falloff.toml",
    ] {
        for (label, setup, pass) in paths {
            let mut s = small(name);
            setup(&mut s);
            same_as_general(&ctx, &format!("{}-{label}", s.name), &s, pass);
        }
    }
    // The far field (its own pass, then tiled shading reading it).
    let s = small("far-field.toml");
    assert!(s.render.far_field > 0 && s.render.path == RenderPath::Tiled);
    same_as_general(&ctx, "far-field", &s, "far field");
    // The lights read from the uniform block instead of the buffer texture
    // (render.light_block), by tiled shading and the far field.
    let mut block = s.clone();
    block.render.light_block = true;
    assert!(variant(&block).light_block && !variant(&s).light_block);
    same_as_general(&ctx, "far-field-light-block", &block, "far field");
    same_as_general(&ctx, "far-field-light-block-tiled", &block, "lighting");
    let mut mixed = with_path(&small("mixed-lights.toml"), RenderPath::Tiled);
    mixed.render.light_block = true;
    same_as_general(&ctx, "mixed-tiled-light-block", &mixed, "lighting");
}

#[test]
fn the_shadow_switches_keep_the_maps_and_filters_the_frame_has() {
    let ctx = common::context(common::backend());
    let point = small("shadows-point.toml");
    let v = variant(&point);
    assert_eq!((v.shadow_maps_2d, v.shadow_cubes), (0, 1), "{v:?}");
    let spot = small("shadows-spot.toml");
    let v = variant(&spot);
    assert_eq!((v.shadow_maps_2d, v.shadow_cubes), (1, 0), "{v:?}");
    for pcf in Pcf::ALL {
        for (base, path) in [(&spot, RenderPath::Forward), (&point, RenderPath::Deferred)] {
            let mut s = with_path(base, path);
            s.render.deferred_lights = DeferredLights::SinglePass;
            for l in &mut s.lights {
                if let Some(sh) = &mut l.shadow {
                    sh.pcf = pcf;
                }
            }
            let v = variant(&s);
            assert_eq!(v.pcf_box, matches!(pcf, Pcf::Box3 | Pcf::Box5), "{v:?}");
            assert_eq!(v.pcf_poisson, pcf == Pcf::Poisson, "{v:?}");
            let pass = if path == RenderPath::Forward {
                "forward"
            } else {
                "lighting"
            };
            same_as_general(&ctx, &format!("{}-{}", s.name, pcf.name()), &s, pass);
        }
    }
    // Casters in every slot of each kind: the scene's one caster as four,
    // moved apart, so that each map holds a different shadow (a variant
    // that read another slot's map would move one).
    for (base, kind) in [(&spot, "2d"), (&point, "cube")] {
        let mut s = with_path(base, RenderPath::Forward);
        let one = (s.lights.iter().find(|l| l.shadow.is_some()).cloned()).expect("a caster");
        s.lights.retain(|l| l.shadow.is_none());
        for k in 0..4 {
            let mut l = one.clone();
            l.position += glam::Vec3::new(0.6 * k as f32 - 0.9, 0.0, 0.3 * k as f32);
            l.intensity = one.intensity / 2.0;
            s.lights.push(l);
        }
        let v = variant(&s);
        assert_eq!(
            (v.shadow_maps_2d, v.shadow_cubes),
            if kind == "2d" { (4, 0) } else { (0, 4) }
        );
        same_as_general(&ctx, &format!("four-{kind}-casters"), &s, "forward");
        // Three casters: slots 0..3 of the kind.
        s.lights.pop();
        same_as_general(&ctx, &format!("three-{kind}-casters"), &s, "forward");
    }
}

#[test]
fn the_normal_map_and_gbuffer_switches_give_the_general_image() {
    let ctx = common::context(common::backend());
    let bump = small("bump-mapping.toml");
    assert!(variant(&bump).normal_maps);
    same_as_general(
        &ctx,
        "bump-forward",
        &with_path(&bump, RenderPath::Forward),
        "forward",
    );
    let mut off = with_path(&bump, RenderPath::Forward);
    off.render.normal_mapping = false;
    assert!(!variant(&off).normal_maps);
    same_as_general(&ctx, "bump-forward-off", &off, "forward");
    assert!(!variant(&small("mixed-lights.toml")).normal_maps);

    use gloss::frame::gbuffer::material_code;
    for (encoding, code) in [
        (GBufferEncoding::ReportRgba8, material_code::REPORT),
        (GBufferEncoding::ReportRgba16f, material_code::REPORT),
        (GBufferEncoding::PlainRgba16f, material_code::PLAIN),
    ] {
        let mut s = with_path(&small("microfacet.toml"), RenderPath::Deferred);
        s.render.deferred_lights = DeferredLights::SinglePass;
        s.render.gbuffer_encoding = encoding;
        assert_eq!(variant(&s).gbuffer_material, code);
        same_as_general(&ctx, &format!("microfacet-{encoding:?}"), &s, "lighting");
    }
    let phong = small("mixed-lights.toml");
    assert_eq!(variant(&phong).gbuffer_material, material_code::NONE);
}
