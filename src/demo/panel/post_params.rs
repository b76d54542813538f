//! The "Post chain" section's widgets for bloom's and FXAA's settings
//! (the keys src/scene/bloom.rs and src/scene/fxaa.rs read). Like every
//! edit of the chain, a changed value goes through the scene loader's
//! rules before it runs; one out of range is refused with its message.

use crate::scene::bloom::{Bloom, BloomScheme, MAX_RADIUS};
use crate::scene::fxaa::{Fxaa, PRESETS};
use crate::scene::post::Taps;

/// Entry `i`'s bloom: where its blurs run, their taps, each blur's sigma
/// and radius (full-resolution pixels), the cut, the merge's weights.
/// True when one changed.
pub fn bloom(ui: &mut egui::Ui, i: usize, b: &mut Bloom) -> bool {
    let mut changed = false;
    let schemes = BloomScheme::ALL;
    changed |= combo(
        ui,
        ("bloom scheme", i),
        "scheme",
        &mut b.scheme,
        schemes,
        BloomScheme::name,
    );
    let taps = [Taps::Direct, Taps::Linear];
    changed |= combo(ui, ("bloom taps", i), "taps", &mut b.taps, taps, Taps::name);
    // The slider's words after it, on the next line when the panel is narrow.
    ui.horizontal_wrapped(|ui| {
        let r = ui.add(egui::Slider::new(&mut b.radius_scale, 0.05..=1.0));
        let label = ui.label("radius scale (fewer taps)");
        changed |= r.labelled_by(label.id).changed();
    });
    egui::Grid::new(("bloom levels", i)).show(ui, |ui| {
        ui.label("blur");
        ui.label("sigma (pixels)");
        ui.label("radius (pixels)");
        ui.end_row();
        for (k, l) in b.levels.iter_mut().enumerate() {
            ui.label(format!("{}", k + 1));
            let s = egui::DragValue::new(&mut l.sigma)
                .range(0.1..=f64::from(MAX_RADIUS))
                .speed(0.1);
            let name = format!("blur{} sigma", k + 1);
            changed |= named(ui.add(s), &name, l.sigma).changed();
            let r = egui::DragValue::new(&mut l.radius).range(1..=MAX_RADIUS);
            let name = format!("blur{} radius", k + 1);
            changed |= named(ui.add(r), &name, f64::from(l.radius)).changed();
            ui.end_row();
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label("weights");
        for (k, w) in b.weights.iter_mut().enumerate() {
            let name = match k {
                0 => "weight of the original".to_string(),
                k => format!("weight of blur{k}"),
            };
            let d = egui::DragValue::new(w)
                .range(0.0..=1.0)
                .speed(0.001)
                .max_decimals(4);
            let r = ui.add(d);
            changed |= named(r, &name, *w).on_hover_text(&name).changed();
        }
    });
    let sum: f64 = b.weights.iter().sum();
    ui.weak(format!(
        "the weights sum to {sum:.4} (1: the image's energy kept)"
    ));
    changed
}

/// Entry `i`'s FXAA: the preset and the three thresholds of FXAA 3.11.
/// True when one changed.
pub fn fxaa(ui: &mut egui::Ui, i: usize, x: &mut Fxaa) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label("quality preset");
        egui::ComboBox::from_id_salt(("fxaa quality", i))
            .selected_text(x.quality.to_string())
            .show_ui(ui, |ui| {
                for (q, steps) in PRESETS {
                    let text = format!("{q} ({} search steps)", steps.len());
                    if ui.selectable_value(&mut x.quality, q, text).changed() {
                        changed = true;
                        ui.close();
                    }
                }
            });
    });
    for (v, range, text) in [
        (&mut x.subpix, 0.0..=1.0, "subpix (0 off, 1 softer)"),
        (&mut x.edge_threshold, 0.001..=1.0, "edge threshold"),
        (&mut x.edge_threshold_min, 0.0..=1.0, "edge threshold min"),
    ] {
        let s = egui::Slider::new(v, range).logarithmic(true).text(text);
        changed |= ui.add(s).changed();
    }
    changed
}

/// A number box named `name` for a screen reader (and the tests): a grid
/// cell has no label of its own.
fn named(r: egui::Response, name: &str, value: f64) -> egui::Response {
    r.widget_info(|| egui::WidgetInfo {
        label: Some(name.to_string()),
        ..egui::WidgetInfo::drag_value(true, value)
    });
    r
}

/// A choice among `all`, each shown by `name`.
pub(super) fn combo<T: Copy + PartialEq, const N: usize>(
    ui: &mut egui::Ui,
    id: (&str, usize),
    label: &str,
    v: &mut T,
    all: [T; N],
    name: fn(T) -> &'static str,
) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label(label);
        egui::ComboBox::from_id_salt(id)
            .selected_text(name(*v))
            .show_ui(ui, |ui| {
                for c in all {
                    if ui.selectable_value(v, c, name(c)).changed() {
                        changed = true;
                        ui.close();
                    }
                }
            });
    });
    changed
}
