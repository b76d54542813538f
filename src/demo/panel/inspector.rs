//! The panel's pass inspector section: the view shown (from the list or
//! the thumbnail strip), the exposure, the stencil view's pass, "compare
//! with reference", and under the view its legend and what it shows.

use super::{Action, PanelInput, PanelState, legend};
use crate::demo::inspector::View;

impl PanelState {
    pub(super) fn inspector_section(
        &mut self,
        ui: &mut egui::Ui,
        input: &PanelInput,
        actions: &mut Vec<Action>,
    ) {
        egui::CollapsingHeader::new("Pass inspector")
            .default_open(true)
            .show(ui, |ui| {
                let current = self.inspect;
                let label = |i: Option<usize>| match i {
                    None => "output: the final image".to_string(),
                    Some(i) => input.views.get(i).map(View::label).unwrap_or_default(),
                };
                // The shown view's label with its values' range, read back.
                let selected = match input.range {
                    Some((lo, hi)) => format!("{}; values {lo:.4} to {hi:.4}", label(current)),
                    None => label(current),
                };
                egui::ComboBox::from_id_salt("inspector")
                    .width(300.0)
                    .selected_text(selected)
                    .show_ui(ui, |ui| {
                        for i in std::iter::once(None).chain((0..input.views.len()).map(Some)) {
                            if ui.selectable_label(current == i, label(i)).clicked() {
                                actions.push(Action::Inspect(i));
                            }
                        }
                    })
                    .response
                    .accessible_name("inspector view");
                ui.checkbox(&mut self.thumbnails, "thumbnails (click one to view it)");
                if self.thumbnails {
                    let strip = ui.scope(|ui| {
                        egui::ScrollArea::horizontal().show(ui, |ui| {
                        ui.horizontal(|ui| {
                            for (i, t) in input.thumbnails.iter().enumerate() {
                                let Some(t) = t else { continue };
                                let image = egui::Image::from_texture(t)
                                    .fit_to_exact_size(egui::vec2(96.0, 54.0))
                                    .sense(egui::Sense::click());
                                let r = ui.add(image).on_hover_text(
                                    input.views.get(i).map(View::label).unwrap_or_default(),
                                );
                                if r.clicked() {
                                    actions.push(Action::Inspect(Some(i)));
                                }
                            }
                        });
                        });
                    });
                    self.strip = Some(strip.response.rect);
                }
                ui.add(
                    egui::Slider::new(&mut self.exposure, 0.01..=100.0)
                        .logarithmic(true)
                        .text("exposure (light views)"),
                );
                if current.and_then(|i| input.views.get(i)).is_some_and(|v| v.stencil) {
                    // The stencil as any pass left it (the frame is drawn
                    // again up to that pass).
                    let passes = &input.plan.passes;
                    self.stencil_after = self.stencil_after.min(passes.len());
                    ui.add(
                        egui::Slider::new(&mut self.stencil_after, 0..=passes.len())
                            .text("stencil after pass (0: end of frame)"),
                    );
                    if let Some(p) = self.stencil_after.checked_sub(1).and_then(|i| passes.get(i)) {
                        let title = input.plan.title(self.stencil_after - 1);
                        ui.small(format!("{}. {title}: {}", self.stencil_after, p.draws));
                    }
                }
                ui.horizontal(|ui| {
                    if ui.button("compare with reference").on_hover_text(
                        "render forward with the same camera and size; show RMSE, max and the difference (a view above)",
                    ).clicked() {
                        actions.push(Action::Compare);
                    }
                });
                if let Some(c) = input.comparison {
                    ui.label(c);
                }
                if let Some(v) = current.and_then(|i| input.views.get(i)) {
                    legend::show(ui, v, input);
                }
                if let Some(s) = current.and_then(|i| input.views.get(i)?.shadow) {
                    let n = s.resolution;
                    let (lo, hi) = input.stretch.unwrap_or((0.0, 1.0));
                    ui.small(format!(
                        "light {}'s map, {n} x {n}{} DEPTH_COMPONENT32F: black {lo:.4}, white {hi:.4}",
                        s.light,
                        if s.cube() { " x 6" } else { "" }
                    ));
                } else if let Some(v) = current.and_then(|i| input.views.get(i)) {
                    let fb = input
                        .plan
                        .target(v.target)
                        .map(|t| t.attachments().join(", "));
                    let (w, h) = input.size;
                    ui.small(format!("{} ({w}x{h}): {}", v.target, fb.unwrap_or_default()));
                }
            });
    }
}
