//! Passes are named by what they draw (`FramePlan::title`), alike in the
//! panel's timings, in `gloss plan` and in the stencil view's pass slider:
//! a mirror frame's forward passes are told apart by the reflection they
//! draw, a shadow pass by its light.

use crate::common;
use crate::driver::{Driver, input};
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use std::process::Command;

#[test]
fn a_mirror_frames_passes_are_named_by_the_reflection_they_draw() {
    let ctx = common::context(common::backend());
    let scene = common::scene("mirrors-several.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 96, 54).unwrap();
    r.timing = true;
    r.render(&scene.camera).unwrap();
    let forward: Vec<String> = (0..r.plan.passes.len())
        .filter(|&i| r.plan.passes[i].name == "forward")
        .map(|i| r.plan.title(i))
        .collect();
    assert!(forward.len() >= 3, "{forward:?}");
    assert_eq!(forward[0], "forward");
    for (i, a) in forward.iter().enumerate() {
        assert!(
            forward[i + 1..].iter().all(|b| a != b),
            "two forward passes named alike: {forward:?}"
        );
    }
    let left = "forward (reflection in mirror 'left mirror')";
    assert!(forward.iter().any(|t| t == left), "{forward:?}");
    // The panel's timings name it so...
    let mut d = Driver::new();
    assert!(
        d.find(&input(&scene, &r), left).is_some(),
        "the timings show {left:?}"
    );
    // ...and so does `gloss plan`.
    let out = Command::new(env!("CARGO_BIN_EXE_gloss"))
        .args(["plan", "mirrors-several"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains(&format!("4. {left} ->")), "{text}");
}

#[test]
fn a_shadow_pass_is_named_by_its_light_and_a_cube_face_by_its_face() {
    let scene = common::scene("shadows-directional.toml");
    let plan = gloss::techniques::plan(&scene);
    assert_eq!(plan.title(0), "shadow map (light 0)");
    // A point light's cube, one pass per face (tests/shadows/face_passes.rs).
    let scene = common::scene("shadows-point.toml");
    let plan = gloss::techniques::plan(&scene);
    assert_eq!(plan.title(0), "shadow map (light 0, face +X)");
    assert_eq!(plan.title(5), "shadow map (light 0, face -Z)");
}
