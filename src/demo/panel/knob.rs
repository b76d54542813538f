//! One control per knob (src/scene/knobs.rs): a checkbox, a slider, a row
//! of choices or three numbers and a colour picker for a colour. The row
//! wraps at the panel's edge, so that every choice of a long list stays in
//! the panel at any width (tests/window_demo/panel_fit.rs).

use crate::scene::RenderSettings;
use crate::scene::knobs::{Kind, Knob, Value};

/// Show `k`'s control for `settings`; true when the user changed it.
pub fn show(ui: &mut egui::Ui, k: &Knob, settings: &mut RenderSettings) -> bool {
    let before = (k.get)(settings);
    let mut after = before;
    ui.horizontal_wrapped(|ui| {
        let label = ui
            .label(k.label)
            .on_hover_text(format!("{}\n{}", k.key, k.help));
        // The controls are named by the label (egui's accessibility tree,
        // which the window tests read: src/demo/layout.rs).
        ui.label_inputs_by(label.id, |ui| match (k.kind, &mut after) {
            (Kind::Bool, Value::Bool(b)) => {
                ui.checkbox(b, "");
            }
            (Kind::Number { min, max, log }, Value::Number(x)) => {
                ui.add(egui::Slider::new(x, min..=max).logarithmic(log));
            }
            (Kind::Count { min, max }, Value::Count(n)) => {
                ui.add(egui::Slider::new(n, min..=max));
            }
            (Kind::Choice(words), Value::Choice(i)) => {
                for (j, w) in words.iter().enumerate() {
                    let r = ui.selectable_value(i, j, *w);
                    // Each choice is named by its word, described by the knob.
                    ui.ctx()
                        .accesskit_node_builder(r.id, |n| n.set_description(k.label));
                }
            }
            (Kind::Color, Value::Color(c)) => {
                for v in [&mut c.x, &mut c.y, &mut c.z] {
                    ui.add(egui::DragValue::new(v).range(0.0..=10.0).speed(0.005));
                }
                // A colour picker for values within 0..1 (linear RGB, as
                // the scene file holds them); brighter ones are typed.
                if c.max_element() <= 1.0 {
                    let mut rgb = c.to_array();
                    // egui names the button "Color": the knob names it.
                    let r = ui.color_edit_button_rgb(&mut rgb).labelled_by(label.id);
                    if r.changed() {
                        *c = glam::Vec3::from_array(rgb);
                    }
                }
            }
            _ => {
                ui.label("?");
            }
        });
    });
    if after != before {
        (k.set)(settings, after);
        true
    } else {
        false
    }
}
