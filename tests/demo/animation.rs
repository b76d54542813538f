//! src/demo/panel/animation.rs, driven headless through the panel's
//! widgets: a scene with keyframe tracks gets an animation section; its
//! time slider asks for that instant, and the frame then is the scene at
//! that instant; "play" starts and stops the clock. A scene without tracks
//! has no such section. The geometry section edits the particle fountain
//! and the tessellated terrain.

use crate::common;
use crate::driver::{Driver, input};
use gloss::demo::panel::Action;
use gloss::gl::program::Sources;
use gloss::renderer::{Output, Renderer};

#[test]
fn the_time_slider_scrubs_and_play_pauses() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("animated-hierarchy.toml");
    scene.render.size = (160, 90);
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 160, 90).unwrap();
    let mut d = Driver::new();
    assert!(d.panel.playing, "an animated scene plays from the start");
    assert!(d.find(&input(&scene, &r), "Animation (3 tracks)").is_some());
    // Scrubbing asks for the instant, and stops the playing.
    let actions = d.set_value(&input(&scene, &r), "time (s)", 1.5);
    assert_eq!(actions, [Action::Time(1.5)]);
    assert!(!d.panel.playing);
    // The demo's answer to it (src/demo/actions.rs): the scene at 1.5 s.
    scene.set_time(1.5).unwrap();
    r.set_scene_values(&scene).unwrap();
    r.render(&scene.camera).unwrap();
    let scrubbed = r.read_image();
    let mut fresh = common::scene("animated-hierarchy.toml");
    fresh.render.size = (160, 90);
    fresh.set_time(1.5).unwrap();
    assert!(scrubbed == common::render_with(&ctx, &fresh, Output::Srgb8).image);
    // "play" starts the clock again.
    d.click(&input(&scene, &r), "play");
    assert!(d.panel.playing);
    // Particles with no tracks play too, over four lifetimes.
    let fountain = common::scene("particles.toml");
    let rf = Renderer::new(&ctx.gl, &ctx.debug, &fountain, &Sources::Embedded, 64, 36).unwrap();
    assert_eq!(fountain.playable_span(), Some((0.0, 4.0 * 1.8)));
    assert!(d.find(&input(&fountain, &rf), "time (s)").is_some());
    // A scene with nothing that moves shows no animation section.
    let still = common::scene("default.toml");
    let rs = Renderer::new(&ctx.gl, &ctx.debug, &still, &Sources::Embedded, 64, 36).unwrap();
    assert!(d.find(&input(&still, &rs), "play").is_none());
}

#[test]
fn the_geometry_section_edits_the_particles_and_the_terrain() {
    let ctx = common::context(common::backend());
    let particles = common::scene("particles.toml");
    let r = Renderer::new(&ctx.gl, &ctx.debug, &particles, &Sources::Embedded, 64, 36).unwrap();
    let mut d = Driver::new();
    let actions = d.set_value(&input(&particles, &r), "particles alive", 500.0);
    let [Action::Particles(p)] = actions.as_slice() else {
        panic!("{actions:?}")
    };
    assert_eq!(p.count, 500);
    assert!(
        (p.rate * p.lifetime - 500.0).abs() < 1e-2,
        "as many born a lifetime as live"
    );
    let actions = d.click(&input(&particles, &r), "quads from the geometry shader");
    let [Action::Particles(p)] = actions.as_slice() else {
        panic!("{actions:?}")
    };
    assert!(!p.geometry_shader);
    // The terrain: its wireframe and its levels.
    let terrain = common::scene("tessellated-terrain.toml");
    let rt = Renderer::new(&ctx.gl, &ctx.debug, &terrain, &Sources::Embedded, 64, 36).unwrap();
    let actions = d.click(&input(&terrain, &rt), "wireframe");
    let [Action::Tessellation(t)] = actions.as_slice() else {
        panic!("{actions:?}")
    };
    assert!(t.wireframe);
    let actions = d.set_value(&input(&terrain, &rt), "level near", 8.0);
    let [Action::Tessellation(t)] = actions.as_slice() else {
        panic!("{actions:?}")
    };
    assert_eq!(t.levels, [1.0, 8.0]);
    // A scene with neither has no such section.
    let still = common::scene("default.toml");
    let rs = Renderer::new(&ctx.gl, &ctx.debug, &still, &Sources::Embedded, 64, 36).unwrap();
    assert!(d.find(&input(&still, &rs), "wireframe").is_none());
}

#[test]
fn each_skinned_object_gets_its_method_and_clip() {
    let ctx = common::context(common::backend());
    let mut arm = common::scene("skinned-arm.toml");
    arm.render.size = (64, 36);
    // One skinned object, so that its combo boxes are the only ones.
    arm.objects
        .retain(|o| o.name == "floor" || o.name == "linear");
    let r = Renderer::new(&ctx.gl, &ctx.debug, &arm, &Sources::Embedded, 64, 36).unwrap();
    let mut d = Driver::new();
    // Only "twist" is left: the span is its 2 s.
    assert_eq!(arm.playable_span(), Some((0.0, 2.0)));
    assert!(
        d.click(&input(&arm, &r), "linear").is_empty(),
        "opens the list"
    );
    let actions = d.click(&input(&arm, &r), "dual_quaternion");
    let [Action::Skin(i, skin)] = actions.as_slice() else {
        panic!("{} actions", actions.len())
    };
    assert_eq!(arm.objects[*i].name, "linear");
    assert_eq!(skin.method, gloss::scene::SkinMethod::DualQuaternion);
    assert_eq!(skin.clip_name(), "twist");
    // The demo's answer: the renderer poses the object the new way.
    let mut edited = arm.clone();
    edited.objects[*i].skin = Some(skin.clone());
    let mut r = r;
    r.set_scene_values(&edited).unwrap();
    r.render(&edited.camera).unwrap();
    let mut fresh = arm.clone();
    fresh.objects[*i].skin.as_mut().unwrap().method = gloss::scene::SkinMethod::DualQuaternion;
    assert!(r.read_image() == common::render_with(&ctx, &fresh, Output::Srgb8).image);
    // The clip list: the rest pose and the file's clips.
    assert!(d.click(&input(&arm, &r), "twist").is_empty());
    let actions = d.click(&input(&arm, &r), "rest pose");
    let [Action::Skin(_, skin)] = actions.as_slice() else {
        panic!("{} actions", actions.len())
    };
    assert_eq!(skin.clip, None);
}

#[test]
fn the_timings_show_what_frustum_culling_kept() {
    let ctx = common::context(common::backend());
    let mut city = common::scene("frustum-culling.toml");
    city.render.size = (64, 36);
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &city, &Sources::Embedded, 64, 36).unwrap();
    r.render(&city.camera).unwrap();
    let c = r.last_times.culling.unwrap();
    let line = format!(
        "frustum culling: {} of {} opaque objects drawn, {} culled ({} tests)",
        c.drawn, c.objects, c.culled, c.tests
    );
    let mut d = Driver::new();
    assert!(d.find(&input(&city, &r), &line).is_some(), "{line}");
}
