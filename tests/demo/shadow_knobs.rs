//! src/demo/panel/shadow_knobs.rs, driven headless through the panel's
//! widgets (egui's AccessKit tree names each widget; a click is asked for
//! as a screen reader asks): "casts shadows" adds the light's `shadow map`
//! pass to the plan and takes it away again, a knob reaches the map, and a
//! fifth casting light is refused with a message, in the scene loader's
//! own limit.

use crate::common;
use crate::driver::{Driver, input};
use gloss::demo::panel::{Action, too_many_casters};
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::{Light, Scene, Shadow};

/// The edited lights of the one `Action::Lights` among `actions`.
fn lights(actions: Vec<Action>) -> Vec<Light> {
    let mut edited = actions.into_iter().filter_map(|a| match a {
        Action::Lights(l) => Some(l),
        _ => None,
    });
    let l = edited.next().expect("an Action::Lights");
    assert!(edited.next().is_none());
    l
}

/// The lights with a shadow pass, each once (a point light's cube drawn
/// face by face has six passes in a row).
fn shadow_passes(r: &Renderer) -> Vec<usize> {
    let mut lights: Vec<usize> = (r.plan.passes.iter())
        .filter(|p| p.name == "shadow map")
        .map(|p| p.item)
        .collect();
    lights.dedup();
    lights
}

#[test]
fn casts_shadows_adds_and_removes_the_lights_shadow_map_pass() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("shadows-point.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let mut d = Driver::new();
    assert_eq!(shadow_passes(&r), [0]);
    d.click(&input(&scene, &r), "Lights (1)");
    d.click(&input(&scene, &r), "light 0: point");
    // A point light has the cube's knob, not a directional light's fit.
    assert!(d.find(&input(&scene, &r), "cube faces").is_some());
    assert!(d.find(&input(&scene, &r), "fit to").is_none());
    for casts in [false, true] {
        let edited = lights(d.click(&input(&scene, &r), "casts shadows"));
        assert_eq!(edited[0].shadow, casts.then(Shadow::default));
        scene.lights = edited;
        r.set_scene_values(&scene).unwrap();
        r.render(&scene.camera).unwrap();
        let want: &[usize] = if casts { &[0] } else { &[] };
        assert_eq!(shadow_passes(&r), want, "casts shadows: {casts}");
        assert_eq!(r.shadows().maps.len(), want.len());
    }
    // A knob: the map's resolution, from its combo box.
    d.click(&input(&scene, &r), "2048 x 2048");
    let edited = lights(d.click(&input(&scene, &r), "512 x 512"));
    assert_eq!(edited[0].shadow.unwrap().resolution, 512);
    scene.lights = edited;
    r.set_scene_values(&scene).unwrap();
    assert_eq!(r.shadows().maps[0].1.size, 512);
    ctx.debug.check(&ctx.gl, "toggling shadows").unwrap();
}

#[test]
fn a_fifth_casting_light_is_refused_with_a_message() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("shadows-directional.toml");
    let sun = scene.lights[0].clone();
    scene.lights = vec![sun.clone(); 5];
    scene.lights[4].shadow = None;
    let r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    assert_eq!(shadow_passes(&r), [0, 1, 2, 3]);
    let mut d = Driver::new();
    let input = input(&scene, &r);
    d.click(&input, "Lights (5)");
    d.click(&input, "light 4: directional");
    let message = "4 directional and spot lights cast shadows already: at most 4 may (a 2D-map texture unit each)";
    assert!(d.find(&input, message).is_some(), "the message is shown");
    let checkbox = d.find(&input, "casts shadows").expect("the checkbox");
    assert!(checkbox.is_disabled());
    let actions = d.click(&input, "casts shadows");
    assert!(
        !actions.iter().any(|a| matches!(a, Action::Lights(_))),
        "the fifth caster is refused: {actions:?}"
    );

    // The demo checks edited lights against the loader's limit too, in the
    // loader's words.
    let mut five = scene.lights.clone();
    five[4].shadow = Some(Shadow::default());
    let e = too_many_casters(&five).expect("five casters are too many");
    let text = format!(
        "[camera]\neye = [0, 2, 5]\ntarget = [0, 0, 0]\n{}",
        "[[lights]]\ntype = \"directional\"\ndirection = [0, -1, 0]\nshadow = true\n".repeat(5)
    );
    let loader = Scene::parse(&text, std::path::Path::new("five.toml"))
        .unwrap_err()
        .to_string();
    assert!(loader.contains(&e), "{loader}\n{e}");
    assert!(too_many_casters(&scene.lights).is_none());
}

#[test]
fn a_directional_lights_cascade_knobs_reach_the_plan_and_the_maps() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("cascaded-shadows.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let cascades = |r: &Renderer| {
        let p = r.plan.passes.iter();
        p.filter(|p| p.name == "cascaded shadow map").count()
    };
    assert_eq!((cascades(&r), shadow_passes(&r).len()), (4, 0));
    assert_eq!(r.shadows().maps[0].1.target, glow::TEXTURE_2D_ARRAY);
    let mut d = Driver::new();
    d.click(&input(&scene, &r), "Lights (1)");
    d.click(&input(&scene, &r), "light 0: directional");
    for label in [
        "cascades",
        "split",
        "stable cascades (texel-snapped)",
        "blend band",
    ] {
        assert!(d.find(&input(&scene, &r), label).is_some(), "{label}");
    }
    // The debug colouring, from its checkbox.
    let edited = lights(d.click(&input(&scene, &r), "cascade colours"));
    assert!(edited[0].shadow.unwrap().cascade_colors);
    scene.lights = edited;
    r.set_scene_values(&scene).unwrap();
    r.render(&scene.camera).unwrap();
    // One cascade is the single map again: its pass and a 2D texture.
    scene.lights[0].shadow.as_mut().unwrap().cascades = 1;
    r.set_scene_values(&scene).unwrap();
    r.render(&scene.camera).unwrap();
    assert_eq!((cascades(&r), shadow_passes(&r).len()), (0, 1));
    assert_eq!(r.shadows().maps[0].1.target, glow::TEXTURE_2D);
    ctx.debug.check(&ctx.gl, "the cascade knobs").unwrap();
}
