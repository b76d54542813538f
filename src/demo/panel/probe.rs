//! The panel's pixel probe section: what the probed pixel holds (the text
//! `gloss probe` prints, from src/renderer/probe.rs) beside a magnifier of
//! the pixels around it, the probed one outlined.

use super::{PanelInput, PanelState};
use crate::renderer::MAGNIFIER_RADIUS;

/// Screen points per magnified pixel.
const CELL: f32 = 12.0;

impl PanelState {
    pub(super) fn probe_section(&mut self, ui: &mut egui::Ui, input: &PanelInput) {
        egui::CollapsingHeader::new("Pixel probe")
            .default_open(true)
            .show(ui, |ui| {
                ui.checkbox(&mut self.probe_follow, "follow the pointer")
                    .on_hover_text("probe the pixel under the pointer every frame");
                let Some(p) = input.probe else {
                    ui.weak("click a pixel of the view to probe it");
                    return;
                };
                let side = (2 * MAGNIFIER_RADIUS + 1) as usize;
                let rgba: Vec<u8> = p.magnifier.iter().flatten().copied().collect();
                let image = egui::ColorImage::from_rgba_unmultiplied([side, side], &rgba);
                let texture =
                    ui.ctx()
                        .load_texture("probe-magnifier", image, egui::TextureOptions::NEAREST);
                let size = egui::vec2(CELL * side as f32, CELL * side as f32);
                let r = ui.add(egui::Image::from_texture(&texture).fit_to_exact_size(size));
                // The probed pixel, outlined in the middle.
                let at = r.rect.min + egui::vec2(CELL, CELL) * MAGNIFIER_RADIUS as f32;
                let cell = egui::Rect::from_min_size(at, egui::vec2(CELL, CELL));
                ui.painter().rect_stroke(
                    cell,
                    0.0,
                    egui::Stroke::new(2.0, egui::Color32::YELLOW),
                    egui::StrokeKind::Outside,
                );
                self.magnifier = Some(texture);
                let text = egui::RichText::new(p.to_string()).monospace().small();
                ui.add(egui::Label::new(text).wrap_mode(egui::TextWrapMode::Wrap));
            });
    }
}
