//! src/frame/plan.rs and the registry in src/techniques/mod.rs: the plan
//! lists the right passes and targets for every path; the renderer runs
//! exactly the planned passes; every registered technique has its file,
//! shaders, scene and docs page, and its scene runs it.

use crate::common;
use gloss::frame::targets::size_name;
use gloss::scene::{RenderPath, Scene};
use gloss::techniques::{ALL, plan};

fn with_path(scene: &Scene, path: RenderPath) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    s
}

#[test]
fn frame_plan_lists_the_right_passes() {
    let base = common::scene("mixed-lights.toml");
    let names = |p: RenderPath| -> Vec<&'static str> {
        plan(&with_path(&base, p))
            .passes
            .iter()
            .map(|p| p.name)
            .collect()
    };
    assert_eq!(names(RenderPath::Forward), ["forward"]);
    assert_eq!(
        names(RenderPath::Deferred),
        ["gbuffer", "lighting", "composite"]
    );
    assert_eq!(
        names(RenderPath::Volumes),
        ["gbuffer", "lighting", "composite"]
    );
    assert_eq!(
        names(RenderPath::Prepass),
        ["gbuffer", "light pre-pass", "combine"]
    );
    let vol = plan(&with_path(&base, RenderPath::Volumes));
    let lighting = &vol.passes[1];
    assert!(lighting.draws.contains("2 spheres"), "{}", lighting.draws);
    assert!(lighting.draws.contains("3 cones"), "{}", lighting.draws);
    assert!(
        lighting.draws.contains("1 full-screen"),
        "{}",
        lighting.draws
    );
    // The light pre-pass's G-buffer is thin; deferred shading's is not.
    let pre = plan(&with_path(&base, RenderPath::Prepass));
    assert_eq!(pre.targets[0].name, "gbuffer");
    assert_eq!(pre.targets[0].attachments().len(), 2, "{pre}");
    assert_eq!(
        plan(&with_path(&base, RenderPath::Deferred)).targets[0]
            .attachments()
            .len(),
        4
    );
    assert!(pre.passes[2].draws.contains("3 objects again"), "{pre}");
    // A scene without lights runs no lighting pass.
    let mut dark = with_path(&base, RenderPath::Volumes);
    dark.lights.clear();
    let p = plan(&dark);
    assert!(!p.has_pass("lighting"), "{p}");
    // Lights with no finite radius (Kl = Kq = 0) are drawn full screen.
    let mut flat = with_path(&base, RenderPath::Volumes);
    flat.lights.truncate(1);
    flat.lights[0].kl = 0.0;
    flat.lights[0].kq = 0.0;
    let p = plan(&flat);
    assert!(p.passes[1].draws.contains("no finite radius"), "{p}");
    // The printed plan through the CLI.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["plan", "scenes/many-lights.toml", "--path", "volumes"])
        .current_dir(common::root())
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("256 spheres"), "{text}");
    assert!(text.contains("light:RGBA16F"), "{text}");
    // Each target's bytes, and the sum of them.
    let scene = common::scene("many-lights.toml");
    let p = plan(&with_path(&scene, RenderPath::Volumes));
    let (w, h) = p.size;
    let sum: u64 = p.targets.iter().map(|t| t.bytes(w, h)).sum();
    let gbuffer = p.target("gbuffer").unwrap().bytes(w, h);
    assert_eq!(gbuffer, 20 * u64::from(w) * u64::from(h));
    let line = |name: &str| {
        text.lines()
            .find(|l| l.trim_start().starts_with(name))
            .unwrap()
    };
    assert!(
        line("gbuffer").ends_with(&format!("({})", size_name(gbuffer))),
        "{text}"
    );
    assert!(line("in all").ends_with(&size_name(sum)), "{text}");
}

#[test]
fn the_renderer_runs_exactly_the_planned_passes() {
    // The plan is not just words: with timing on, the renderer reports each
    // pass it ran, and they must be the plan's passes in the plan's order,
    // with and without lights.
    let ctx = common::context(common::backend());
    for lights in [true, false] {
        for path in [
            RenderPath::Forward,
            RenderPath::Deferred,
            RenderPath::Volumes,
            RenderPath::Prepass,
        ] {
            let mut scene = with_path(&common::scene("mixed-lights.toml"), path);
            if !lights {
                scene.lights.clear();
            }
            scene.render.size = (64, 36);
            let mut r = gloss::renderer::Renderer::new(
                &ctx.gl,
                &ctx.debug,
                &scene,
                &gloss::gl::program::Sources::Embedded,
                64,
                36,
            )
            .unwrap();
            r.timing = true;
            r.render(&scene.camera.clone()).unwrap();
            let ran: Vec<&str> = r.last_times.passes.iter().map(|p| p.0).collect();
            let planned: Vec<&str> = plan(&scene).passes.iter().map(|p| p.name).collect();
            assert_eq!(ran, planned, "{path:?}, lights: {lights}");
        }
    }
}

#[test]
fn every_technique_has_its_file_shaders_scene_and_docs_and_its_scene_runs_it() {
    let root = common::root();
    for t in ALL {
        for path in [t.file, t.scene, t.docs] {
            assert!(
                root.join(path).is_file(),
                "{}: {path} does not exist",
                t.name
            );
        }
        assert!(
            t.file.ends_with(&format!("/{}.rs", t.name)),
            "{}: the file is named as the technique: {}",
            t.name,
            t.file
        );
        // Every technique draws with shaders, but for the split viewports,
        // whose one pass draws with scissored glClear calls alone, and the
        // MSAA resolve, a glBlitFramebuffer.
        assert!(
            !t.shaders.is_empty() || ["viewports", "msaa"].contains(&t.name),
            "{} has no shader",
            t.name
        );
        for s in t.shaders {
            assert!(
                root.join("glsl").join(s).is_file(),
                "{}: glsl/{s} does not exist",
                t.name
            );
        }
        let scene = Scene::load(&root.join(t.scene)).unwrap();
        let p = plan(&scene);
        assert!(
            p.passes.iter().any(|pass| pass.code == t.file),
            "{}: its scene {} does not run it:\n{p}",
            t.name,
            t.scene
        );
    }
}

#[test]
fn a_frame_without_lights_allocates_no_light_target() {
    for path in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let mut s = with_path(&common::scene("mixed-lights.toml"), path);
        s.lights.clear();
        let p = plan(&s);
        assert!(p.target("light_accumulation").is_none(), "{p}");
        assert!(p.target("gbuffer").is_some(), "{p}");
    }
    let p = plan(&common::scene("shading-phong.toml"));
    assert_eq!(
        p.targets.len(),
        1,
        "forward renders straight into the output: {p}"
    );
}

/// A frame allocates what its passes use: the output has a depth-stencil
/// buffer only where a pass after the composite (or forward) tests depth,
/// the G-buffer a stencil only for the stencil volumes and the light
/// pre-pass (whose combine copies its depth into the output), and the
/// light accumulation target copies the G-buffer's depth format.
#[test]
fn a_frame_allocates_only_the_buffers_its_passes_use() {
    let base = common::scene("mixed-lights.toml");
    let attachments = |s: &Scene, target: &str| -> Vec<String> {
        plan(s).target(target).map_or(vec![], |t| t.attachments())
    };
    let depth_of = |s: &Scene, target: &str| -> Option<String> {
        attachments(s, target)
            .into_iter()
            .find(|a| a.starts_with("depth"))
    };
    for path in [RenderPath::Deferred, RenderPath::Volumes, RenderPath::Tiled] {
        let s = with_path(&base, path);
        // The composite encodes sRGB by GL_FRAMEBUFFER_SRGB into it
        // (render.hardware_srgb; tests/deferred/hardware_srgb.rs).
        assert_eq!(
            attachments(&s, "output"),
            ["color:SRGB8_ALPHA8"],
            "{path:?}"
        );
        assert_eq!(
            depth_of(&s, "gbuffer").as_deref(),
            Some("depth:DEPTH_COMPONENT24"),
            "{path:?}"
        );
    }
    let forward = with_path(&base, RenderPath::Forward);
    assert_eq!(
        depth_of(&forward, "output").as_deref(),
        Some("depth_stencil:DEPTH24_STENCIL8")
    );
    let prepass = with_path(&base, RenderPath::Prepass);
    assert_eq!(
        depth_of(&prepass, "gbuffer").as_deref(),
        Some("depth_stencil:DEPTH24_STENCIL8")
    );
    let mut stencil = with_path(&base, RenderPath::Volumes);
    stencil.render.stencil_volumes = true;
    for target in ["gbuffer", "light_accumulation"] {
        assert_eq!(
            depth_of(&stencil, target).as_deref(),
            Some("depth_stencil:DEPTH24_STENCIL8"),
            "{target}"
        );
    }
    let volumes = with_path(&base, RenderPath::Volumes);
    assert_eq!(
        depth_of(&volumes, "light_accumulation").as_deref(),
        Some("depth:DEPTH_COMPONENT24")
    );
    // A deferred frame with a mirror draws after its composite: the output
    // keeps its depth-stencil for the mirror's stencil marks.
    let mut mirrors = common::scene("mirror-normal-first.toml");
    mirrors.render.path = RenderPath::Deferred;
    assert_eq!(
        depth_of(&mirrors, "output").as_deref(),
        Some("depth_stencil:DEPTH24_STENCIL8")
    );
    // The memory `gloss plan` reports shrinks accordingly: 4 bytes a pixel
    // less in the output of a deferred frame.
    let text = plan(&with_path(&base, RenderPath::Deferred)).to_string();
    let (w, h) = base.render.size;
    let output = size_name(4 * u64::from(w) * u64::from(h));
    assert!(
        text.contains(&format!("color:SRGB8_ALPHA8  ({output})")),
        "{text}"
    );
}

/// Notes 01 §6.2: opaque objects drawn front to back, by the eye-space depth
/// of their centres, so that the depth test rejects hidden fragments before
/// they are shaded. The order changes the cost, never the image: forward
/// and deferred frames are the same with and without it.
#[test]
fn opaque_objects_are_drawn_front_to_back_and_the_image_does_not_change() {
    use gloss::frame::draw_list::DrawList;
    use gloss::renderer::Output;
    let ctx = common::context(common::backend());
    let scene = common::scene("many-lights.toml");
    let draws = DrawList::new(&ctx.gl, &scene).unwrap();
    let view = scene.camera.view();
    let depth = |i: usize| {
        let d = &draws.items[i];
        -view.transform_point3(d.model.transform_point3(d.centre)).z
    };
    let sorted = draws.opaque_order(&view, None, true);
    let depths: Vec<f32> = sorted.iter().map(|&i| depth(i)).collect();
    assert!(depths.windows(2).all(|w| w[0] <= w[1]), "{depths:?}");
    let unsorted = draws.opaque_order(&view, None, false);
    assert!(unsorted.windows(2).all(|w| w[0] < w[1]), "the file's order");
    assert_eq!(sorted.len(), unsorted.len());
    assert_ne!(sorted, unsorted, "many-lights lists its floor first");
    for path in [RenderPath::Forward, RenderPath::Deferred] {
        let mut s = with_path(&scene, path);
        s.render.size = (240, 136);
        s.lights.truncate(16);
        let on = common::render_with(&ctx, &s, Output::Srgb8).image;
        s.render.sort_opaque = false;
        let off = common::render_with(&ctx, &s, Output::Srgb8).image;
        assert!(on == off, "{path:?}: sorting changed the image");
    }
}
