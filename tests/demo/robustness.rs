//! What the demo does over and over, done many times headless: switching
//! techniques (`Renderer::set_render_settings`, as the panel and the keys
//! do) and reloading the scene (a new renderer, as F5 and a changed scene
//! file do). The GL objects gloss's owners hold (src/gl/live.rs) stay flat.
//! Also sizes: 1x1, very wide, back again.

use crate::common;
use gloss::gl::live;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::{Accumulation, RenderPath, Scene};
use std::time::Instant;

fn settings_cycle(scene: &Scene) -> Vec<gloss::scene::RenderSettings> {
    let mut v = Vec::new();
    for path in RenderPath::ALL {
        for (stencil, accumulation) in [
            (false, Accumulation::Rgba16f),
            (true, Accumulation::Rgba32f),
        ] {
            let mut s = scene.render.clone();
            s.path = *path;
            s.stencil_volumes = stencil;
            s.accumulation = accumulation;
            v.push(s);
        }
    }
    v
}

#[test]
fn gl_objects_stay_flat_over_1000_switches_and_1000_reloads() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let mut scene = common::scene("mixed-lights.toml");
    scene.render.size = (48, 27);
    let (w, h) = (48, 27);
    let before = live::counts();
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
    let cycle = settings_cycle(&scene);
    // One round builds every technique's programs; after it nothing may grow.
    for s in &cycle {
        r.set_render_settings(s.clone()).unwrap();
        r.render(&scene.camera).unwrap();
    }
    let warm = live::counts();
    for i in 0..1000 {
        r.set_render_settings(cycle[i % cycle.len()].clone())
            .unwrap();
        if i % 10 == 0 {
            r.render(&scene.camera).unwrap();
        }
    }
    r.set_render_settings(cycle[cycle.len() - 1].clone())
        .unwrap();
    assert_eq!(live::counts(), warm, "after 1000 technique switches");
    drop(r);
    assert_eq!(
        live::counts(),
        before,
        "a dropped renderer frees everything"
    );

    // Reloads: a new renderer for a freshly loaded scene, the old one dropped.
    let path = common::root().join("scenes/plane.toml");
    let start = Instant::now();
    let plane = Scene::load(&path).unwrap();
    let mut r = Renderer::new(gl, &ctx.debug, &plane, &Sources::Embedded, w, h).unwrap();
    let one = live::counts();
    for _ in 0..1000 {
        let mut s = Scene::load(&path).unwrap();
        s.render.size = (w as u32, h as u32);
        r = Renderer::new(gl, &ctx.debug, &s, &Sources::Embedded, w, h).unwrap();
        r.render(&s.camera).unwrap();
        assert_eq!(
            live::counts(),
            one,
            "a reload holds what the first load held"
        );
    }
    drop(r);
    assert_eq!(live::counts(), before, "after 1000 reloads");
    eprintln!("1000 reloads: {:.1} s", start.elapsed().as_secs_f64());
    ctx.debug.check(gl, "switching and reloading").unwrap();
}

#[test]
fn sizes_from_1x1_to_very_wide_and_back() {
    let ctx = common::context(common::backend());
    let scene = common::scene("mixed-lights.toml");
    let mut r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    for path in RenderPath::ALL {
        let mut s = scene.render.clone();
        s.path = *path;
        r.set_render_settings(s).unwrap();
        for (w, h) in [(1, 1), (4096, 8), (8, 2048), (0, 0), (64, 36)] {
            r.resize(w, h).unwrap();
            r.render(&scene.camera).unwrap();
            if (w, h) != (0, 0) {
                assert_eq!((r.output().width, r.output().height), (w, h));
            }
        }
    }
    // A 0 x 0 size (a minimised window) keeps the last size.
    r.resize(0, 0).unwrap();
    assert_eq!((r.width, r.height), (64, 36));
}
