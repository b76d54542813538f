//! A point light's cube drawn face by face is six passes, each named by the
//! face it draws ("shadow map (light 0, face +X)", GL's face order +X, -X,
//! +Y, -Y, +Z, -Z), alike in the plan, `gloss plan`, the timings, `gloss
//! bench`'s table and `gloss trace`; the geometry-shader cube is one pass
//! that says it draws all six. Splitting the cube into passes changes no
//! pixel: both ways give, byte for byte, the images the single cube pass
//! gave before the split (tests/shadows/before_face_passes/, rendered by
//! `gloss render` at commit e92ca20, when the six faces were one pass).

use crate::common;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::CubeRender;

const FACES: [&str; 6] = [
    "shadow map (light 0, face +X)",
    "shadow map (light 0, face -X)",
    "shadow map (light 0, face +Y)",
    "shadow map (light 0, face -Y)",
    "shadow map (light 0, face +Z)",
    "shadow map (light 0, face -Z)",
];
const LAYERED: &str = "shadow map (light 0, six faces by gl_Layer)";

#[test]
fn a_cube_drawn_face_by_face_is_six_passes_named_by_their_faces() {
    let mut scene = common::scene("shadows-point.toml");
    scene.render.size = (96, 54);
    let shadow = scene.lights[0].shadow.as_mut().unwrap();
    assert_eq!(shadow.cube, CubeRender::SixPasses);
    let ctx = common::context(common::backend());
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 96, 54).unwrap();
    r.timing = true;
    r.render(&scene.camera).unwrap();
    let titles: Vec<String> = (0..r.plan.passes.len()).map(|i| r.plan.title(i)).collect();
    // The first six passes, one per face, in GL's order.
    assert_eq!(titles[..6], FACES, "{titles:?}");
    assert!(!titles[6..].iter().any(|t| t.starts_with("shadow map")));
    for (face, p) in r.plan.passes[..6].iter().enumerate() {
        assert_eq!((p.name, p.face, p.item), ("shadow map", Some(face), 0));
    }
    // The timings name each pass as the plan does, one row per pass.
    assert_eq!(r.last_times.titles, titles);
    assert_eq!(r.last_times.passes.len(), titles.len());
    // `gloss plan` lists them so, numbered in that order.
    let plan = common::gloss(&["plan", "shadows-point"]);
    for (i, face) in FACES.iter().enumerate() {
        let line = format!("  {}. {face} -> shadow map", i + 1);
        assert!(plan.contains(&line), "{line:?} in\n{plan}");
    }
    // `gloss trace`: each face its own pass, under its own heading.
    let trace = common::gloss(&[
        "trace",
        "shadows-point",
        "--technique",
        "shadow_map",
        "--size",
        "96x54",
    ]);
    let headings: Vec<&str> = (trace.lines())
        .filter(|l| l.contains(": shadow_map ("))
        .collect();
    assert_eq!(headings.len(), 6, "{trace}");
    for (i, (h, face)) in headings.iter().zip(FACES).enumerate() {
        assert!(h.starts_with(&format!("{}. {face}: ", i + 1)), "{h}");
    }
    // Each face pass draws into its own face: one framebuffer bound per pass.
    let binds = (trace.lines().map(str::trim_start))
        .filter(|l| l.starts_with("glBindFramebuffer(GL_FRAMEBUFFER,") && !l.contains(", 0)"))
        .count();
    assert_eq!(binds, 6, "{trace}");
    // Each its own KHR_debug group, named "1. shadow map (light 0, face
    // +X) (shadow_map)": the trace shows the group's number and its name's
    // length (the name itself is a pointer to it).
    let all = common::gloss(&["trace", "shadows-point", "--size", "96x54"]);
    for (i, face) in FACES.iter().enumerate() {
        let name = format!("{}. {face} (shadow_map)", i + 1);
        let push = format!(
            "glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, {}, {}, &data)",
            i + 1,
            name.len()
        );
        assert!(all.contains(&push), "{push:?} in\n{all}");
    }
}

#[test]
fn a_cube_drawn_by_the_geometry_shader_is_one_pass_that_says_so() {
    let mut scene = common::scene("shadows-point.toml");
    scene.lights[0].shadow.as_mut().unwrap().cube = CubeRender::GeometryShader;
    let plan = gloss::techniques::plan(&scene);
    let shadow: Vec<String> = (0..plan.passes.len())
        .filter(|&i| plan.passes[i].name == "shadow map")
        .map(|i| plan.title(i))
        .collect();
    assert_eq!(shadow, [LAYERED]);
    let text = common::gloss(&[
        "plan",
        "shadows-point",
        "--set",
        "lights[0].shadow.cube=geometry_shader",
    ]);
    assert!(
        text.contains(&format!("  1. {LAYERED} -> shadow map")),
        "{text}"
    );
}

#[test]
fn gloss_bench_times_each_face_under_its_name() {
    let out = std::env::temp_dir().join("gloss-bench-faces");
    let _ = std::fs::remove_dir_all(&out);
    let table = common::gloss(&[
        "bench",
        "scenes/shadows-point.toml",
        "--vary",
        "lights[0].shadow.cube=six_passes,geometry_shader",
        "--frames",
        "1",
        "--warmup",
        "0",
        "--size",
        "96x54",
        "--out",
        out.to_str().unwrap(),
    ]);
    let header = table.lines().next().unwrap();
    let mut at = 0;
    for name in FACES.iter().chain([&LAYERED]) {
        let column = format!("{name} ms");
        let found = header[at..].find(&column);
        assert!(found.is_some(), "{column:?} after column {at} in {header}");
        at += found.unwrap() + column.len();
    }
}

#[test]
fn splitting_the_cube_into_face_passes_changes_no_pixel() {
    let dir = common::out_dir();
    for path in ["forward", "deferred"] {
        let before = common::root().join(format!(
            "tests/shadows/before_face_passes/shadows-point-320x180-{path}.png"
        ));
        let before = image::open(&before).unwrap().to_rgba8();
        for mode in ["six_passes", "geometry_shader"] {
            let png = dir.join(format!("face-passes-{mode}-{path}.png"));
            let set = format!("lights[0].shadow.cube={mode}");
            common::gloss(&[
                "render",
                "scenes/shadows-point.toml",
                "--size",
                "320x180",
                "--path",
                path,
                "--set",
                &set,
                // The references were made when the shader encoded sRGB;
                // GL's encoding differs by a step in some pixels.
                "--set",
                "render.hardware_srgb=false",
                "--debug",
                "-o",
                png.to_str().unwrap(),
            ]);
            let now = image::open(&png).unwrap().to_rgba8();
            let differ = common::pixels_differing(&now, &before, &format!("{mode} on {path}"));
            assert_eq!(differ, 0, "{mode} on {path}: {differ} pixels differ");
        }
    }
}
