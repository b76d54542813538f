//! The panel's head, outside its scrolling (the frame time, the GL, the
//! render scale, one fixed slot for the last error or status), the note
//! laid over the view while the panel is hidden, and the render scale.

use super::{PanelInput, PanelState};

/// How much of the view's resolution the frame is rendered at (the rest
/// made up by scaling it up): for software rasterizers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RenderScale {
    Full,
    Half,
    Quarter,
}

impl RenderScale {
    pub const ALL: [RenderScale; 3] = [RenderScale::Full, RenderScale::Half, RenderScale::Quarter];

    /// The view's size is divided by this.
    pub fn divisor(self) -> i32 {
        match self {
            RenderScale::Full => 1,
            RenderScale::Half => 2,
            RenderScale::Quarter => 4,
        }
    }

    /// The one after it, the last followed by the first (F2).
    pub fn next(self) -> RenderScale {
        let i = RenderScale::ALL
            .iter()
            .position(|&s| s == self)
            .unwrap_or(0);
        RenderScale::ALL[(i + 1) % RenderScale::ALL.len()]
    }

    pub fn name(self) -> &'static str {
        match self {
            RenderScale::Full => "1",
            RenderScale::Half => "1/2",
            RenderScale::Quarter => "1/4",
        }
    }
}

impl PanelState {
    /// The panel's head, outside its scrolling: the frame time, the render
    /// scale, and one fixed slot for the last error or status (so that a
    /// message never pushes the widgets below it down).
    pub(super) fn top(&mut self, ui: &mut egui::Ui, input: &PanelInput) {
        ui.horizontal(|ui| {
            ui.heading("gloss");
            // The button before the frame time, whose width changes.
            if ui.small_button("hide (Tab)").clicked() {
                self.open = false;
            }
            ui.label(self.frame_time());
        });
        ui.small(input.gl_info);
        ui.horizontal(|ui| {
            ui.label("render scale:");
            for s in RenderScale::ALL {
                ui.selectable_value(&mut self.scale, s, s.name())
                    .on_hover_text(
                        "render the view at this fraction of its pixels, shown scaled up (F2)",
                    );
            }
        });
        let (text, colour) = match (input.error, input.status) {
            (Some(e), _) => (e, egui::Color32::from_rgb(255, 110, 90)),
            (None, Some(s)) => (s, ui.visuals().text_color()),
            (None, None) => ("", ui.visuals().text_color()),
        };
        let slot = egui::vec2(
            ui.available_width(),
            2.0 * ui.text_style_height(&egui::TextStyle::Body),
        );
        ui.allocate_ui_with_layout(slot, egui::Layout::top_down(egui::Align::Min), |ui| {
            ui.set_min_size(slot);
            ui.set_max_size(slot);
            ui.add(egui::Label::new(egui::RichText::new(text).color(colour)).truncate())
                .on_hover_text(text);
        });
        ui.separator();
    }

    /// With the panel hidden: the frame time, the render scale and how to
    /// get the panel back, small in the view's top left corner.
    pub(super) fn overlay(
        &self,
        ui: &egui::Ui,
        view: egui::Rect,
        input: &PanelInput,
    ) -> egui::Rect {
        let scale = match self.scale {
            RenderScale::Full => String::new(),
            s => format!(" · render scale {}", s.name()),
        };
        let error = input.error.map(|e| format!("\n{e}")).unwrap_or_default();
        egui::Area::new(egui::Id::unique("gloss-overlay"))
            .fixed_pos(view.min + egui::vec2(6.0, 6.0))
            .interactable(false)
            .show(ui.ctx(), |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    let text = format!("{}{scale} · Tab: panel{error}", self.frame_time());
                    ui.add(egui::Label::new(egui::RichText::new(text).small()).extend());
                });
            })
            .response
            .rect
    }

    /// "12.3 ms (81 fps)": the median of the last frames, swap to swap.
    fn frame_time(&self) -> String {
        match self.timings.median() {
            Some(ms) => format!("{ms:.1} ms ({:.0} fps)", 1000.0 / ms.max(1e-3)),
            None => "– ms".into(),
        }
    }
}
