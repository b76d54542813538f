//! Invariants between the render paths (issue 3):
//! * deferred shading and the light pre-pass equal forward within the
//!   precision of the G-buffer formats (bound stated below, docs/gbuffer.md);
//! * light volumes equal full-screen deferred within the cutoff bound;
//! * the camera inside a light's sphere; spot cone volumes cover the lit region;
//! * `gloss plan` lists the passes of each path.

mod common;

use gloss::image_compare::{Tolerance, compare_f32, compare_rgba8};
use gloss::renderer::Output;
use gloss::scene::{RenderPath, Scene};

fn with_path(scene: &Scene, path: RenderPath) -> Scene {
    let mut s = scene.clone();
    s.render.path = path;
    s
}

fn show(name: &str) {
    let base = common::scene(name);
    let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
    let fwd_lin = common::render(&with_path(&base, RenderPath::Forward), Output::Linear32F);
    for p in [
        RenderPath::Deferred,
        RenderPath::Volumes,
        RenderPath::Prepass,
    ] {
        let r = common::render(&with_path(&base, p), Output::Srgb8);
        let m = compare_rgba8(&r.image, &fwd.image, 1.0 / 255.0).unwrap();
        let rl = common::render(&with_path(&base, p), Output::Linear32F);
        let ml = compare_f32(&rl.linear, &fwd_lin.linear, 4, 1.0 / 255.0);
        eprintln!("{name} {p:?}: srgb8 {m}\n   linear {ml}");
    }
}

#[test]
fn measure() {
    for n in ["default.toml", "plane.toml"] {
        show(n);
    }
}

#[test]
fn dump_diffs() {
    let base = common::scene("default.toml");
    let fwd = common::render(&with_path(&base, RenderPath::Forward), Output::Srgb8);
    for p in [RenderPath::Deferred, RenderPath::Prepass] {
        let r = common::render(&with_path(&base, p), Output::Srgb8);
        let d = gloss::image_compare::diff_image(&r.image, &fwd.image);
        d.save(format!("/tmp/diff-{p:?}.png")).unwrap();
        let mut worst = (0u32, 0u32, 0u8);
        for (x, y, px) in d.enumerate_pixels() {
            let m = px[0].max(px[1]).max(px[2]);
            if m > worst.2 {
                worst = (x, y, m);
            }
        }
        eprintln!(
            "{p:?} worst at {:?}: fwd {:?} got {:?}",
            worst,
            fwd.image.get_pixel(worst.0, worst.1),
            r.image.get_pixel(worst.0, worst.1)
        );
    }
}
