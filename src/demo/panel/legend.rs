//! The legend under a false-colour view of the pass inspector: what each
//! colour of the picture means. The heat map's colours come from `heat`,
//! the CPU twin of glsl/demo/inspect.frag's; the stencil's from
//! `renderer::stencil_color`, the same function that paints the view.

use super::PanelInput;
use crate::demo::inspector::{Mode, View};
use crate::demo::volume_views::VolumeView;

/// glsl/demo/inspect.frag's `heat`: black, then blue, green, yellow, red as
/// `t` goes from 0 to 1.
pub fn heat(t: f32) -> [f32; 3] {
    let t = t.clamp(0.0, 1.0);
    let fade = (8.0 * t).min(1.0);
    [
        (4.0 * t - 2.0).clamp(0.0, 1.0) * fade,
        (2.0 - (4.0 * t - 2.0).abs()).clamp(0.0, 1.0) * fade,
        (2.0 - 4.0 * t).clamp(0.0, 1.0) * fade,
    ]
}

/// The legend of `view`, if its colours are not the values themselves.
pub(super) fn show(ui: &mut egui::Ui, view: &View, input: &PanelInput) {
    if view.stencil || view.volumes == Some(VolumeView::Marks) {
        ui.small("stencil values:");
        ui.horizontal_wrapped(|ui| {
            for v in 0..=8u8 {
                let [r, g, b, _] = crate::renderer::stencil_color(v);
                swatch(ui, egui::Color32::from_rgb(r, g, b));
                ui.small(if v == 8 {
                    "8 …".to_string()
                } else {
                    v.to_string()
                });
            }
        });
        return;
    }
    let overdraw = view.volumes == Some(VolumeView::Overdraw);
    let grey = view.mode == Mode::Grey;
    if !overdraw && !grey {
        return;
    }
    let (low, high) = if overdraw {
        let n = input.volumes.clamp(1, 32);
        ("0 volumes".to_string(), format!("{n} or more"))
    } else {
        ("0".to_string(), "1".to_string())
    };
    ui.horizontal(|ui| {
        ui.small(low);
        let (rect, _) = ui.allocate_exact_size(egui::vec2(160.0, 12.0), egui::Sense::hover());
        let steps = 32;
        for i in 0..steps {
            let t = (i as f32 + 0.5) / steps as f32;
            let c = if overdraw { heat(t) } else { [t, t, t] };
            let x0 = rect.left() + rect.width() * i as f32 / steps as f32;
            let x1 = rect.left() + rect.width() * (i + 1) as f32 / steps as f32;
            let cell = egui::Rect::from_x_y_ranges(x0..=x1, rect.y_range());
            let byte = |v: f32| (v * 255.0).round() as u8;
            let fill = egui::Color32::from_rgb(byte(c[0]), byte(c[1]), byte(c[2]));
            ui.painter().rect_filled(cell, 0.0, fill);
        }
        ui.small(high);
    });
    if let (true, Some((lo, hi))) = (grey, input.range) {
        ui.small(format!("read back: least {lo:.4}, greatest {hi:.4}"));
    }
}

fn swatch(ui: &mut egui::Ui, colour: egui::Color32) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
    ui.painter().rect_filled(rect, 2.0, colour);
}

#[cfg(test)]
mod tests {
    use super::heat;

    #[test]
    fn the_heat_maps_ends_and_middle() {
        assert_eq!(heat(0.0), [0.0, 0.0, 0.0]);
        assert_eq!(heat(1.0), [1.0, 0.0, 0.0]);
        assert_eq!(heat(0.5), [0.0, 1.0, 0.0]);
        // A quarter: blue and green alike, full brightness.
        assert_eq!(heat(0.25), [0.0, 1.0, 1.0]);
    }
}
