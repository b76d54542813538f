//! One frame of the demo: render the plan, show the output (or the
//! inspected target), take a screenshot if asked, draw the panel, restore
//! the GL state egui changed, swap; then carry out what the panel asked.

use super::panel::PanelInput;
use super::shadow_views::ShadowView;
use super::{Demo, inspector, present, screenshot, to_i32};
use crate::gl::framebuffer::Framebuffer;
use anyhow::Result;
use std::path::PathBuf;
use std::time::Instant;

impl Demo {
    /// Render, show, draw the panel, swap. Returns whether the demo should stop.
    pub(super) fn frame(&mut self) -> Result<bool> {
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        if let Some(n) = self.options.frames
            && run.frames >= n
        {
            return Ok(true);
        }
        let (w, h) = run.ctx.size();
        if w == 0 || h == 0 {
            return Ok(false); // minimised
        }
        self.reload_if_changed();
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        if run.fly {
            let held = |c| if run.held.contains(&c) { 1.0 } else { 0.0 };
            let seconds = run.last_swap.elapsed().as_secs_f32();
            self.orbit.fly(
                held('w') - held('s'),
                held('d') - held('a'),
                held('e') - held('q'),
                seconds,
            );
        }
        // The animation plays on from where it is, by the time since the
        // last swap (src/demo/panel/animation.rs).
        if let Some(span) = self.scene.playable_span()
            && run.panel.playing
        {
            let dt = run.last_swap.elapsed().as_secs_f32() * run.panel.speed;
            let t = super::panel::advance(self.scene.animation.time, dt, span);
            let mut scene = self.scene.clone();
            scene.set_time(t)?;
            self.set_values(scene)?;
        }
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        // The 3D view's rectangle (beside the panel, or the whole window)
        // and the frame rendered at its size, or at 1/2 or 1/4 of it.
        run.view = view_rect(&run.panel, run.egui.egui_ctx.pixels_per_point(), w, h);
        let [_, _, vw, vh] = run.view;
        let s = run.panel.scale.divisor();
        run.renderer
            .resize(((vw + s - 1) / s).max(1), ((vh + s - 1) / s).max(1))
            .map_err(|e| e.context("could not resize the renderer to the view"))?;
        let camera = self.orbit.camera();
        // Pass times are measured (glFinish after each pass) while the panel shows them.
        run.renderer.timing = run.panel.open && run.panel.pass_times;
        run.renderer.render(&camera)?;
        // The probed pixel read back from this frame (src/demo/probe.rs).
        if let Some(e) = run.update_probe(&camera) {
            self.message = Some(e);
        }
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };

        // 1. The image: the final frame, or the inspected target.
        let views = all_views(run);
        run.panel.inspect = inspector::follow(run.panel.inspect, &mut run.inspected, &views);
        let view = run.panel.inspect.and_then(|i| views.get(i));
        let range = view.and_then(|v| inspector::grey_range(run.renderer.targets(), v));
        // A shadow-map view's depths shown as black and white.
        let mut stretch = None;
        let shown = match view {
            None => run.renderer.output(),
            Some(v) => {
                let size = (run.renderer.width, run.renderer.height);
                if run.inspect_fb.as_ref().map(|f| (f.width, f.height)) != Some(size) {
                    run.inspect_fb = None;
                    run.inspect_fb = Some(Framebuffer::new(
                        &run.ctx.gl,
                        "inspector",
                        size.0,
                        size.1,
                        &[glow::RGBA8],
                        None,
                    )?);
                }
                let fb = run.inspect_fb.as_ref().expect("made above");
                match (v.volumes, &run.comparison) {
                    (_, Some(c)) if v.difference => run.inspector.draw_texture(
                        &run.ctx.gl,
                        Some(c.difference.id),
                        inspector::Mode::Color { encode: false },
                        &camera,
                        1.0,
                        fb,
                    ),
                    _ if v.stencil => {
                        let (sw, sh) = (run.renderer.width as u32, run.renderer.height as u32);
                        // At the end of the frame, or as pass n left it.
                        let values = match run.panel.stencil_after {
                            0 => run.renderer.read_stencil(),
                            n => run.renderer.stencil_after(&camera, n)?,
                        };
                        let img = crate::renderer::stencil_image(&values, sw, sh);
                        let img = image::imageops::flip_vertical(&img);
                        let texture = crate::gl::texture::Texture::from_rgba8(
                            &run.ctx.gl,
                            sw,
                            sh,
                            img.as_raw(),
                            false,
                            crate::gl::texture::Sampling::NEAREST_CLAMP,
                        )?;
                        run.inspector.draw_texture(
                            &run.ctx.gl,
                            Some(texture.id),
                            inspector::Mode::Color { encode: false },
                            &camera,
                            1.0,
                            fb,
                        );
                    }
                    _ if let Some(s) = &v.shadow => {
                        stretch = run.shadow_views.draw(s, run.renderer.shadows(), fb)?;
                    }
                    (Some(which), _) => run.volume_views.draw(
                        &run.ctx.gl,
                        which,
                        &run.renderer,
                        &camera,
                        &run.inspector,
                        fb,
                    )?,
                    _ => run.inspector.draw(
                        &run.ctx.gl,
                        v,
                        run.renderer.targets(),
                        &camera,
                        run.panel.exposure,
                        fb,
                    ),
                }
                fb
            }
        };
        present::present(&run.ctx, shown, run.view, to_i32(h))?;
        // 2. A screenshot shows the view without the panel, unless asked.
        if run.screenshot == Some(false) {
            run.screenshot = None;
            let [x, y, vw, vh] = run.view;
            let shot = screenshot::save(&run.ctx.gl, [x, to_i32(h) - y - vh, vw, vh]);
            self.note_screenshot(shot);
        }
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        // 3. The panel (with the inspector's thumbnails), drawn into its
        //    layer when due (src/demo/panel_layer.rs), then the state egui
        //    leaves behind put back; the layer laid over the frame.
        let (lw, lh) = (to_i32(w), to_i32(h));
        if !run.panel_layer.due(lw, lh) && run.screenshot != Some(true) {
            run.panel_layer.composite(&run.ctx.gl, lw, lh);
            run.ctx
                .debug
                .check(&run.ctx.gl, "laying the panel over the frame")?;
            return self.finish_frame();
        }
        if run.panel.open && run.panel.thumbnails {
            run.thumbnails.update(
                &run.ctx.gl,
                &run.egui.egui_ctx,
                &views,
                &run.renderer,
                &camera,
                &run.inspector,
                &mut run.shadow_views,
                run.panel.exposure,
            )?;
        }
        let scene_path = self.scene_path.display().to_string();
        let comparison = run
            .comparison
            .as_ref()
            .map(|c| format!("{}: {}", c.what, c.metrics));
        let input = PanelInput {
            scene: &self.scene,
            scene_path: &scene_path,
            shipped: &run.shipped,
            plan: &run.renderer.plan,
            times: &run.renderer.last_times,
            views: &views,
            error: self.message.as_deref(),
            status: self.status.as_deref(),
            comparison: comparison.as_deref(),
            thumbnails: &run.thumbnails.textures,
            size: (run.renderer.width, run.renderer.height),
            gl_info: &run.gl_info,
            stretch,
            volumes: volume_count(&run.renderer),
            probe: run.probe.as_ref(),
            range,
        };
        let mut actions = Vec::new();
        let panel = &mut run.panel;
        run.egui
            .run(&run.ctx.window, |ui| actions = panel.show(ui, &input));
        // What was drawn this pass, and what egui drew the pass before (a
        // menu open over the view).
        let used = (run.egui.egui_ctx.globally_used_rect()).union(run.panel.drawn);
        let ppp = run.egui.egui_ctx.pixels_per_point();
        if let Some(layout) = run.layout.as_mut() {
            let [x, y, vw, vh] = run.view.map(|v| v as f32 / ppp);
            let view = egui::Rect::from_min_size(egui::pos2(x, y), egui::vec2(vw, vh));
            let areas = [
                ("3D view", "view", Some(view)),
                ("panel", "panel", run.panel.rect),
            ]
            .into_iter()
            .chain([
                ("panel scroll", "scroll area", run.panel.scroll),
                ("panel content", "content", run.panel.content),
                ("thumbnail strip", "scroll area", run.panel.strip),
            ])
            .filter_map(|(l, k, r)| Some((l, k, r?)))
            .collect::<Vec<_>>();
            layout.write(ppp, (w, h), &areas)?;
        }
        run.panel_layer.set_area(used, ppp, lh);
        // egui animates (a panel sliding open): draw it again next frame.
        if run.egui.egui_ctx.has_requested_repaint() {
            run.panel_layer.stale = true;
        }
        run.panel_layer.begin(&run.ctx.gl, lw, lh)?;
        run.egui.paint(&run.ctx.window);
        present::restore_after_egui(&run.ctx.gl);
        // An action changes what the panel shows: draw it again next frame.
        if !actions.is_empty() {
            run.panel_layer.stale = true;
        }
        run.panel_layer.composite(&run.ctx.gl, lw, lh);
        run.ctx.debug.check(&run.ctx.gl, "drawing the panel")?;
        if run.screenshot == Some(true) {
            run.screenshot = None;
            let shot = screenshot::save(&run.ctx.gl, [0, 0, lw, lh]);
            self.note_screenshot(shot);
        }
        for a in actions {
            self.apply(a);
        }
        self.finish_frame()
    }

    /// Swap, count the frame, update the title; true when the demo should stop.
    fn finish_frame(&mut self) -> Result<bool> {
        let Some(run) = self.running.as_mut() else {
            return Ok(false);
        };
        run.ctx.swap_buffers()?;

        run.frames += 1;
        let now = Instant::now();
        run.panel
            .timings
            .push((now - run.last_swap).as_secs_f64() * 1000.0);
        run.last_swap = now;
        if let Some(ms) = run.title.tick() {
            run.ctx.window.set_title(&format!(
                "gloss — {} — {ms:.2} ms/frame ({:.0} fps)",
                self.scene.name,
                1000.0 / ms.max(1e-3)
            ));
        }
        Ok(self.options.frames.is_some_and(|n| run.frames >= n))
    }

    pub(super) fn note_screenshot(&mut self, shot: Result<PathBuf>) {
        match shot {
            Ok(path) => {
                println!("gloss: screenshot {}", path.display());
                self.status = Some(format!("screenshot: {}", path.display()));
            }
            Err(e) => self.message = Some(format!("{e:#}")),
        }
    }
}

/// The 3D view's rectangle in a `w` x `h` window (x, y from the top left,
/// width, height, in pixels): right of the panel while it is shown, else
/// the whole window.
pub(super) fn view_rect(panel: &super::panel::PanelState, ppp: f32, w: u32, h: u32) -> [i32; 4] {
    let (w, h) = (to_i32(w), to_i32(h));
    let x = match panel.view {
        Some(rect) if panel.open => ((rect.min.x * ppp).round() as i32).clamp(0, w - 1),
        _ => 0,
    };
    [x, 0, w - x, h]
}

/// The inspector's views: the shadow maps, the plan's targets, the light
/// volumes, and the difference image of the last comparison.
pub(super) fn all_views(run: &super::Running) -> Vec<inspector::View> {
    let mut views = frame_views(&run.renderer);
    if run.comparison.is_some()
        && let Some(first) = views.first().cloned()
    {
        views.push(inspector::View {
            target: "comparison",
            attachment: "difference",
            difference: true,
            volumes: None,
            stencil: false,
            shadow: None,
            level: 0,
            written: None,
            ..first
        });
    }
    views
}

/// The views the inspector offers for `r`'s frame: its casting lights'
/// shadow maps, its plan's targets (the post chain's named by their step),
/// and the light volumes when the frame draws them.
pub fn frame_views(r: &crate::renderer::Renderer) -> Vec<inspector::View> {
    let shadows = ShadowView::of(r.shadows().maps.iter().map(|(c, _)| c), |i| {
        r.scene.lights[i].kind
    });
    let mut views = inspector::views(&r.plan, has_volumes(r), &shadows);
    super::post_chain::name_steps(&mut views, &r.scene, &r.plan);
    views
}

/// Does this frame draw light volumes (a light-volume pass runs, notes 04
/// and 05) and has some light one (a sphere or a cone)? Only then are the
/// volume views offered.
pub(super) fn has_volumes(r: &crate::renderer::Renderer) -> bool {
    let drawn = (r.plan.passes.iter()).any(|p| {
        let name = crate::techniques::ALL.get(p.technique).map(|t| t.name);
        matches!(name, Some("light_volumes" | "stencil_light_volumes"))
    });
    drawn && volume_count(r) > 0
}

/// How many lights have a volume (the overdraw view's hottest count).
pub(super) fn volume_count(r: &crate::renderer::Renderer) -> usize {
    (r.lights().lights.iter())
        .filter(|l| l.volume != crate::frame::lights::Volume::FullScreen)
        .count()
}
