//! The pass inspector tells the truth (src/demo/inspect_views.rs,
//! src/demo/frame.rs): a one-channel target (the SSAO result, R16F) is
//! shown in grey, each pixel its stored value, not as red; the G-buffer's
//! microfacet triple is labelled as what it holds, not as light; the
//! light-volume views are offered only when the frame draws light volumes.

use crate::common;
use gloss::demo::inspector::{Inspector, Mode, views};
use gloss::gl::framebuffer::Framebuffer;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use gloss::scene::RenderPath;

#[test]
fn the_ambient_occlusion_target_is_shown_in_grey_at_its_values() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let scene = common::scene("ambient-occlusion.toml");
    let (w, h) = (160, 90);
    let mut r = Renderer::new(gl, &ctx.debug, &scene, &Sources::Embedded, w, h).unwrap();
    r.render(&scene.camera).unwrap();
    let all = views(&r.plan, false, &[]);
    let ao = (all.iter())
        .find(|v| v.attachment == "ao")
        .expect("the SSAO target is a view");
    assert_eq!(ao.mode, Mode::Grey);
    assert!(ao.label().contains("ambient occlusion"), "{}", ao.label());
    let inspector = Inspector::new(gl, &Sources::Embedded).unwrap();
    let into = Framebuffer::new(gl, "into", w, h, &[glow::RGBA8], None).unwrap();
    inspector.draw(gl, ao, r.targets(), &scene.camera, 1.0, &into);
    ctx.debug.check(gl, "the AO view").unwrap();
    // The CPU side: the stored values, read back, made bytes.
    let stored = r.targets().find(ao.target).unwrap().read_rgba_f32(0);
    let shown = into.read_rgba_f32(0);
    let mut spread = (f32::MAX, f32::MIN);
    for (s, p) in stored.chunks(4).zip(shown.chunks(4)) {
        let want = s[0].clamp(0.0, 1.0);
        spread = (spread.0.min(want), spread.1.max(want));
        assert!(
            p[0] == p[1] && p[1] == p[2],
            "not grey: {p:?} for AO {}",
            s[0]
        );
        assert!(
            (p[0] - want).abs() <= 1.0 / 255.0,
            "shown {} for AO {want}",
            p[0]
        );
    }
    assert!(
        spread.1 - spread.0 > 0.2,
        "the AO varies over the frame: {spread:?}"
    );
    // The label's range: the least and greatest stored value (R), and no
    // range for a view that is not one channel.
    let red = stored.chunks(4).map(|p| p[0]);
    let least = red.clone().fold(f32::MAX, f32::min);
    let greatest = red.fold(f32::MIN, f32::max);
    let range = gloss::demo::inspector::grey_range(r.targets(), ao);
    assert_eq!(range, Some((least, greatest)));
    let normal = (all.iter()).find(|v| v.mode == Mode::Normal).unwrap();
    assert_eq!(
        gloss::demo::inspector::grey_range(r.targets(), normal),
        None
    );
}

#[test]
fn the_microfacet_triple_is_not_labelled_light() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("microfacet.toml");
    scene.render.path = RenderPath::Deferred;
    let r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
    let all = views(&r.plan, false, &[]);
    let alpha = (all.iter())
        .find(|v| v.target == "gbuffer" && v.attachment == "alpha")
        .expect("the G-buffer holds the microfacet triple");
    assert_eq!(alpha.mode, Mode::Color { encode: false });
    assert!(
        alpha.label().contains("microfacet triple") && !alpha.label().contains("light"),
        "{}",
        alpha.label()
    );
}

#[test]
fn light_volume_views_only_when_the_frame_draws_volumes() {
    let ctx = common::context(common::backend());
    let mut scene = common::scene("mixed-lights.toml");
    for (path, drawn) in [
        (RenderPath::Forward, false),
        (RenderPath::Deferred, false),
        (RenderPath::Volumes, true),
    ] {
        scene.render.path = path;
        let r = Renderer::new(&ctx.gl, &ctx.debug, &scene, &Sources::Embedded, 64, 36).unwrap();
        let offered = gloss::demo::frame_views(&r)
            .iter()
            .any(|v| v.volumes.is_some());
        assert_eq!(offered, drawn, "{path:?}");
    }
}
