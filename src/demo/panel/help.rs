//! The keys: the grid the panel's "Keys" section and the F1 window show.

use crate::demo::keys::KEYS;

pub(super) fn keys_grid(ui: &mut egui::Ui) {
    egui::Grid::new("keys").striped(true).show(ui, |ui| {
        for (key, what) in KEYS {
            ui.monospace(*key);
            ui.label(*what);
            ui.end_row();
        }
    });
}

/// The keys' window; where it is drawn.
pub(super) fn help_window(ui: &mut egui::Ui, open: &mut bool) -> Option<egui::Rect> {
    egui::Window::new("gloss — keys (F1)")
        .open(open)
        .collapsible(false)
        .show(ui.ctx(), keys_grid)
        .map(|r| r.response.rect)
}
