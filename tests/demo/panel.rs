//! src/demo/panel/: the panel is drawn (text in its rectangle), and after
//! `restore_after_egui` the GL state is the fresh context's again and the
//! next frame's pixels are exactly those of a frame without the panel.

use crate::common;
use gloss::demo::inspector::views;
use gloss::demo::panel::{PanelInput, PanelState};
use gloss::demo::restore_after_egui;
use gloss::gl::program::Sources;
use gloss::renderer::Renderer;
use glow::HasContext;

#[test]
fn the_panel_is_drawn_and_leaves_the_scene_and_the_gl_state_as_they_were() {
    let ctx = common::context(common::backend());
    let gl = &ctx.gl;
    let scene = common::scene("mixed-lights.toml");
    let (w, h) = (640u32, 400u32);
    let fresh = common::gl_state(gl);
    let mut r = Renderer::new(
        gl,
        &ctx.debug,
        &scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
    )
    .unwrap();
    r.timing = true;
    r.render(&scene.camera).unwrap();
    let without = r.read_image();

    // The panel, as the demo draws it, painted over the renderer's output.
    let egui_ctx = egui::Context::default();
    let mut painter = egui_glow::Painter::new(gl.clone(), "", None, false).unwrap();
    let mut panel = PanelState::new("scenes/mixed-lights.toml");
    let views = views(&r.plan, true, &[]);
    let shipped = gloss::assets::shipped_scenes();
    let input = PanelInput {
        scene: &scene,
        scene_path: "scenes/mixed-lights.toml",
        shipped: &shipped,
        plan: &r.plan,
        times: &r.last_times,
        views: &views,
        error: None,
        status: None,
        comparison: Some("volumes against forward, 640x400: RMSE 0.1/255"),
        gl_info: "headless test",
        thumbnails: &[],
        size: (w as i32, h as i32),
        stretch: None,
        volumes: 0,
        probe: None,
        range: None,
    };
    let raw = egui::RawInput {
        screen_rect: Some(egui::Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(w as f32, h as f32),
        )),
        ..Default::default()
    };
    let mut textures = egui::TexturesDelta::default();
    let mut shapes = Vec::new();
    let mut ppp = 1.0;
    for _ in 0..2 {
        // The second run lays out with the sizes the first one measured.
        let out = egui_ctx.run_ui(raw.clone(), |ui| {
            panel.show(ui, &input);
        });
        textures.append(out.textures_delta);
        shapes = out.shapes;
        ppp = out.pixels_per_point;
    }
    let primitives = egui_ctx.tessellate(shapes, ppp);
    unsafe { gl.bind_framebuffer(glow::FRAMEBUFFER, Some(r.output().id)) };
    painter.paint_and_update_textures([w, h], ppp, &primitives, &mut textures);
    let with_panel = r.output().read_rgba8_top_down(0);
    restore_after_egui(gl);
    painter.destroy();
    ctx.debug.check(gl, "painting the panel").unwrap();

    // The panel is there: on the left, most pixels changed, and light text
    // pixels stand on the dark panel.
    let (mut changed, mut text, mut area) = (0, 0, 0);
    for y in 0..h {
        for x in 0..300 {
            area += 1;
            let (a, b) = (without.get_pixel(x, y).0, with_panel.get_pixel(x, y).0);
            if a[..3] != b[..3] {
                changed += 1;
            }
            if b[..3].iter().all(|&c| c > 150) {
                text += 1;
            }
        }
    }
    assert!(
        changed * 2 > area,
        "the panel covers its rectangle: {changed} of {area} pixels changed"
    );
    assert!(text > 200, "text pixels in the panel: {text}");

    // egui's state is gone: every setting is the fresh context's.
    let now = common::gl_state(gl);
    let left: Vec<String> = fresh
        .iter()
        .zip(&now)
        .filter(|(a, b)| a != b)
        .map(|(a, b)| format!("{} = {} (fresh: {})", b.0, b.1, a.1))
        .collect();
    assert!(
        left.is_empty(),
        "after restore_after_egui:\n  {}",
        left.join("\n  ")
    );

    // And the next frame is the frame without the panel, pixel for pixel.
    r.render(&scene.camera).unwrap();
    let again = r.read_image();
    assert!(
        again.as_raw() == without.as_raw(),
        "a frame after the panel differs from a frame without it"
    );
}
