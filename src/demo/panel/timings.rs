//! Per-pass times of the last frame (the plan's passes, CPU clock around
//! glFinish: on llvmpipe GL_TIME_ELAPSED under-reports) and a rolling plot
//! of the frame time.

use crate::frame::timing::PassTimes;
use std::collections::VecDeque;

/// Frames the plot keeps.
const HISTORY: usize = 300;

#[derive(Default)]
pub struct Timings {
    frames: VecDeque<f64>,
    count: u64,
}

impl Timings {
    /// Note one frame's time (ms, swap to swap).
    pub fn push(&mut self, frame_ms: f64) {
        if self.frames.len() == HISTORY {
            self.frames.pop_front();
        }
        self.frames.push_back(frame_ms);
        self.count += 1;
    }

    /// The median of the kept frame times.
    pub fn median(&self) -> Option<f64> {
        let mut v: Vec<f64> = self.frames.iter().copied().collect();
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied()
    }

    /// The timings of `plan`'s passes (one each, in its order), each named
    /// by what it draws (`FramePlan::title`).
    pub fn show(
        &self,
        ui: &mut egui::Ui,
        plan: &crate::frame::plan::FramePlan,
        times: &PassTimes,
        pass_times: &mut bool,
    ) {
        egui::CollapsingHeader::new("Timings")
            .default_open(true)
            .show(ui, |ui| {
                ui.checkbox(pass_times, "time each pass").on_hover_text(
                    "glFinish after each pass: exact pass times, a slightly slower frame",
                );
                let gpu = times.gpu.len() == times.passes.len() && !times.gpu.is_empty();
                ui.small(if gpu {
                    "clocks: CPU around glFinish after each pass, and the GPU's (GL_TIMESTAMP)"
                } else {
                    "clock: CPU around glFinish after each pass (this driver's timer queries under-report)"
                });
                // The times first, in fixed-width columns, then what the
                // pass draws, wrapped at the panel's edge.
                let row = |ui: &mut egui::Ui, times: &[String], what: egui::RichText| {
                    ui.horizontal(|ui| {
                        for t in times {
                            ui.monospace(t);
                        }
                        ui.add(egui::Label::new(what).wrap());
                    });
                };
                for (i, (name, ms)) in times.passes.iter().enumerate() {
                    // Named as the plan of the frame they timed named them.
                    let title = match times.titles.get(i) {
                        Some(title) => title.clone(),
                        None if times.passes.len() == plan.passes.len() => plan.title(i),
                        None => name.to_string(),
                    };
                    let mut columns = vec![format!("{ms:8.2} ms")];
                    if gpu {
                        columns.push(format!("GPU {:8.2} ms", times.gpu[i]));
                    }
                    row(ui, &columns, title.into());
                }
                row(
                    ui,
                    &[format!("{:8.2} ms", times.frame_ms)],
                    egui::RichText::new("renderer").strong(),
                );
                if let Some(m) = self.median() {
                    let columns = [format!("{m:8.2} ms  {:.1} fps", 1000.0 / m.max(1e-3))];
                    row(ui, &columns, egui::RichText::new("frame (median)").strong());
                }
                if let Some(c) = &times.culling {
                    ui.label(format!(
                        "frustum culling: {} of {} opaque objects drawn, {} culled ({} tests)",
                        c.drawn, c.objects, c.culled, c.tests
                    ));
                }
                if let Some(c) = &times.shadow_culling {
                    ui.label(format!(
                        "shadow casters: {} drawn, {} culled over the shadow maps' faces",
                        c.drawn, c.culled
                    ));
                }
                let start = self.count.saturating_sub(self.frames.len() as u64);
                let points: Vec<[f64; 2]> = self
                    .frames
                    .iter()
                    .enumerate()
                    .map(|(i, &ms)| [(start + i as u64) as f64, ms])
                    .collect();
                egui_plot::Plot::new("frame-times")
                    .height(110.0)
                    .include_y(0.0)
                    .allow_scroll(false)
                    .allow_drag(false)
                    .allow_zoom(false)
                    .y_axis_label("ms")
                    .show(ui, |plot| {
                        plot.line(egui_plot::Line::new("frame time", points));
                    });
            });
    }
}
