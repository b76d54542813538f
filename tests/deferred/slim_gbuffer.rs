//! The slim G-buffer (`render.gbuffer_slim`, src/frame/gbuffer_slim.rs):
//! no specular attachment when every opaque material has one specular
//! colour; the lighting passes read it from a uniform.
//!
//! * every G-buffer path (deferred per light and in one pass, the general
//!   shader, tiled, tiled with the far field, light volumes plain and
//!   stencilled, SSAO, the octahedral normal) draws the same image, byte
//!   for byte, with the slim G-buffer as with the full one
//!   (`render.gbuffer_slim = false`); the specialised programs leave the
//!   texture read out by a define, the general one by a uniform;
//! * the plan drops the target exactly when the materials share the value:
//!   a second specular colour, a specular map, a microfacet lobe or a
//!   reflective material keeps it and `gloss plan` says why; a transparent
//!   material's colour does not count; the variant line says where the
//!   colour comes from; the inspector offers no view of a target that is
//!   not there.
//! * the constant is the value the attachment would have given back: the
//!   sRGB 8-bit round trip of the colour, against the standard's formula.

use crate::common;
use glam::Vec3;
use gloss::demo::inspector::views;
use gloss::frame::gbuffer_slim;
use gloss::image_compare::compare_rgba8;
use gloss::renderer::Output;
use gloss::scene::{DeferredLights, RenderPath, Scene};

/// `scene` at 256x192 on `path`, slim or full.
fn on(scene: &Scene, path: RenderPath, slim: bool) -> Scene {
    let mut s = crate::with_path(scene, path);
    s.render.gbuffer_slim = slim;
    s.render.size = (256, 192);
    s
}

/// Every material's specular colour set to `c`.
fn one_specular(mut s: Scene, c: Vec3) -> Scene {
    for m in &mut s.materials {
        m.specular = c;
    }
    s
}

/// The G-buffer target's attachments and the G-buffer pass's words.
fn gbuffer_of(s: &Scene) -> (Vec<&'static str>, String) {
    let plan = gloss::techniques::plan(s);
    let t = plan.targets.iter().find(|t| t.name == "gbuffer").unwrap();
    let p = plan.passes.iter().find(|p| p.name == "gbuffer").unwrap();
    (t.colors.iter().map(|c| c.0).collect(), p.draws.clone())
}

/// The variations of one path the test renders, with their labels.
fn variations(scene: &Scene) -> Vec<(String, Scene)> {
    let mut out = Vec::new();
    let mut add = |label: &str, path: RenderPath, f: &dyn Fn(&mut Scene)| {
        for slim in [false, true] {
            let mut s = on(scene, path, slim);
            f(&mut s);
            out.push((label.to_string(), s));
        }
    };
    add("deferred per light", RenderPath::Deferred, &|s| {
        s.render.deferred_lights = DeferredLights::PerLight
    });
    add("deferred single pass", RenderPath::Deferred, &|s| {
        s.render.deferred_lights = DeferredLights::SinglePass
    });
    add("deferred general shader", RenderPath::Deferred, &|s| {
        s.render.specialize = false
    });
    add("deferred octahedral", RenderPath::Deferred, &|s| {
        s.render.gbuffer = gloss::scene::material::GBufferNormals::Octahedral
    });
    add("tiled", RenderPath::Tiled, &|_| {});
    add("tiled + far field 4", RenderPath::Tiled, &|s| {
        s.render.far_field = 4
    });
    add("volumes", RenderPath::Volumes, &|s| {
        s.render.stencil_volumes = false
    });
    add("stencil volumes", RenderPath::Volumes, &|s| {
        s.render.stencil_volumes = true
    });
    out
}

#[test]
fn every_gbuffer_path_draws_the_same_image_slim_and_full() {
    let ctx = common::context(common::backend());
    let scenes = [
        common::scene("logl-like.toml"),
        // 0.3 encodes to 148.9 / 255: a rounding the constant must match.
        one_specular(common::scene("deferred-shading.toml"), Vec3::splat(0.3)),
        // SSAO reads the G-buffer too.
        one_specular(common::scene("ambient-occlusion.toml"), Vec3::splat(0.1)),
    ];
    for scene in &scenes {
        for pair in variations(scene).chunks(2) {
            let [(label, full), (_, slim)] = pair else {
                unreachable!()
            };
            let (full_colors, _) = gbuffer_of(full);
            let (slim_colors, words) = gbuffer_of(slim);
            assert!(
                full_colors.contains(&"specular"),
                "{label}: {full_colors:?}"
            );
            assert!(
                !slim_colors.contains(&"specular") && words.contains("no specular attachment"),
                "{} {label}: {slim_colors:?} {words}",
                scene.name
            );
            let a = common::render_with(&ctx, full, Output::Srgb8).image;
            let b = common::render_with(&ctx, slim, Output::Srgb8).image;
            let m = compare_rgba8(&b, &a, 0.0).unwrap();
            eprintln!(
                "{} {label}: slim vs full max {:.0}/255, {} pixels differ",
                scene.name,
                m.max_abs * 255.0,
                (m.frac_over * (256.0 * 192.0)).round()
            );
            assert!(
                a.as_raw() == b.as_raw(),
                "{} {label}: slim differs from full: {m:?}",
                scene.name
            );
        }
    }
}

#[test]
fn the_plan_drops_the_specular_target_exactly_when_the_materials_share_it() {
    let logl = common::scene("logl-like.toml");
    // One material, one specular colour: normal 8 + albedo 4 + depth 4.
    let slim = on(&logl, RenderPath::Deferred, true);
    let (colors, words) = gbuffer_of(&slim);
    assert_eq!(colors, ["normal_shininess", "albedo"]);
    assert!(
        words.contains("no specular attachment: every material's is (0.50, 0.50, 0.50)")
            && words.contains("16 bytes/px"),
        "{words}"
    );
    let plan = gloss::techniques::plan(&slim);
    let lighting = plan.passes.iter().find(|p| p.variant.is_some()).unwrap();
    let variant = lighting.variant.as_deref().unwrap();
    assert!(
        variant.contains("specular colour from a uniform"),
        "{variant}"
    );
    // The inspector offers the attachments there are, and no specular.
    let gbuffer_views: Vec<String> = (views(&plan, false, &[]).iter())
        .filter(|v| v.target == "gbuffer")
        .map(|v| v.attachment.to_string())
        .collect();
    assert!(
        gbuffer_views.contains(&"albedo".to_string()),
        "{gbuffer_views:?}"
    );
    assert!(
        !gbuffer_views.contains(&"specular".to_string()),
        "{gbuffer_views:?}"
    );
    // The knob off: the full G-buffer, 20 bytes, the variant reads the texture.
    let full = on(&logl, RenderPath::Deferred, false);
    let (colors, words) = gbuffer_of(&full);
    assert_eq!(colors, ["normal_shininess", "albedo", "specular"]);
    assert!(words.contains("20 bytes/px"), "{words}");
    let plan = gloss::techniques::plan(&full);
    assert!(!plan.to_string().contains("specular colour from a uniform"));
    let views_full = views(&plan, false, &[]);
    assert!(
        (views_full.iter()).any(|v| v.target == "gbuffer" && v.attachment == "specular"),
        "the full G-buffer's specular view"
    );

    // Each thing that makes the channel vary keeps the attachment, said.
    let kept = |label: &str, s: &Scene, why: &str| {
        let (colors, words) = gbuffer_of(s);
        assert!(colors.contains(&"specular"), "{label}: {colors:?}");
        assert!(words.contains(why), "{label}: {words}");
        assert!(gbuffer_slim::constant_specular(s).is_none(), "{label}");
    };
    // The shipped scene with two specular colours (0.3 and 0.7).
    let two = on(
        &common::scene("deferred-shading.toml"),
        RenderPath::Deferred,
        true,
    );
    kept("deferred-shading", &two, "two specular colours");
    // Two materials on logl-like's objects, a hair apart.
    let rock = slim.objects[0].material;
    let mut s = slim.clone();
    let mut other = s.materials[rock].clone();
    other.name = "other".into();
    other.specular = Vec3::new(0.5, 0.5, 0.501);
    s.materials.push(other.clone());
    let k = s.materials.len() - 1;
    s.objects[3].material = k;
    kept("two colours", &s, "two specular colours");
    // The same colour in a second material: still one value, dropped.
    s.materials[k].specular = Vec3::splat(0.5);
    assert_eq!(gbuffer_of(&s).0, ["normal_shininess", "albedo"]);
    // A transparent object is shaded forward: its colour does not count.
    s.materials[k].specular = Vec3::splat(0.9);
    s.materials[k].opacity = 0.5;
    assert_eq!(gbuffer_of(&s).0, ["normal_shininess", "albedo"]);
    // A specular map, a microfacet lobe, reflectivity.
    let mut s = slim.clone();
    s.materials[rock].specular_map = Some("textures/specular.png".into());
    kept("specular map", &s, "has a specular map");
    let mut s = slim.clone();
    s.materials[rock].reflectivity = 0.25;
    kept("reflective", &s, "is reflective");
    let micro = on(
        &common::scene("microfacet.toml"),
        RenderPath::Deferred,
        true,
    );
    kept("microfacet", &micro, "is microfacet");

    // The other paths: tiled and volumes drop it too; the pre-pass's thin
    // G-buffer never had it; forward has none.
    for path in [RenderPath::Tiled, RenderPath::Volumes] {
        assert_eq!(
            gbuffer_of(&on(&logl, path, true)).0,
            ["normal_shininess", "albedo"]
        );
    }
    assert_eq!(
        gbuffer_of(&on(&logl, RenderPath::Prepass, true)).0,
        ["normal_shininess"]
    );
    assert!(gbuffer_slim::constant_specular(&on(&logl, RenderPath::Prepass, true)).is_none());
    let forward = gloss::techniques::plan(&on(&logl, RenderPath::Forward, true));
    assert!(forward.targets.iter().all(|t| t.name != "gbuffer"));
}

#[test]
fn the_constant_is_the_srgb_round_trip_of_the_colour() {
    // The standard's formulas (IEC 61966-2-1), written out here.
    let encode = |c: f64| {
        if c <= 0.003_130_8 {
            12.92 * c
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        }
    };
    let decode = |v: f64| {
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    // Known bytes: 0.5 is 187.5 -> 188, 0.3 is 149.4 -> 149, 1 is 255, 0 is 0.
    for (c, byte) in [(0.5, 188.0), (0.3, 149.0), (1.0, 255.0), (0.0, 0.0)] {
        assert_eq!((encode(c) * 255.0).round(), byte, "{c}");
        let want = decode(byte / 255.0) as f32;
        assert_eq!(gbuffer_slim::as_stored(c as f32), want, "{c}");
    }
    // Every byte's decoded value comes back as itself.
    for b in 0..=255 {
        let v = decode(f64::from(b) / 255.0) as f32;
        assert_eq!(gbuffer_slim::as_stored(v), v, "byte {b}");
    }
    // What the renderer passes for logl-like: 0.5 as stored.
    let s = on(&common::scene("logl-like.toml"), RenderPath::Deferred, true);
    let stored = gbuffer_slim::stored_specular(&s).unwrap();
    assert_eq!(stored, Vec3::splat(decode(188.0 / 255.0) as f32));
    assert!((stored.x - 0.5).abs() > 1e-4, "the round trip moves 0.5");
}

#[test]
fn the_uniform_is_what_this_gl_reads_back_from_the_attachment() {
    let ctx = common::context(common::backend());
    let decode = |v: f64| {
        if v <= 0.04045 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    for v in [0.5f32, 0.3, 0.1, 0.2, 0.6, 0.05, 1.0] {
        // The full G-buffer's attachment, as the geometry pass stored it.
        let s = on(
            &common::scene("logl-like.toml"),
            RenderPath::Deferred,
            false,
        );
        let s = one_specular(s, Vec3::splat(v));
        let r = gloss::renderer::render_scene(&ctx, &s, Output::Srgb8).unwrap();
        let bytes = r.targets().get("gbuffer").read_rgba8_top_down(2);
        let byte = bytes.pixels().map(|p| p[0]).max().unwrap();
        let got = gbuffer_slim::read_back(&ctx.gl, Vec3::splat(v)).unwrap();
        let want = decode(f64::from(byte) / 255.0) as f32;
        eprintln!(
            "specular {v}: stored byte {byte}, read back {}, the standard's round trip {}",
            got.x,
            gbuffer_slim::as_stored(v)
        );
        // The probe reads the byte the attachment holds, decoded by this
        // GL's sampler: nearer that byte's value than either neighbour's
        // (llvmpipe's decode is off the standard's by up to ~1e-3).
        let at = |b: f64| decode(b.clamp(0.0, 255.0) / 255.0) as f32;
        let b = f64::from(byte);
        let half = |n: f64| (at(b + n) - want).abs() / 2.0;
        assert!(
            (got.x - want).abs() < half(-1.0).max(half(1.0)),
            "{v}: {got} vs byte {byte} ({want})"
        );
        assert!(got.x == got.y && got.y == got.z, "{got}");
        // And the standard's value is at most about one step away.
        let step = half(-1.0).max(half(1.0)) * 2.0;
        assert!(
            (gbuffer_slim::as_stored(v) - got.x).abs() <= 1.5 * step,
            "{v}"
        );
    }
}
