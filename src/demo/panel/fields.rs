//! The panel's small number fields, used by the value editors (values.rs)
//! and the structure editors (structure.rs) alike.

use glam::Vec3;

/// Three numbers in a row after `label`; true when one changed.
pub(super) fn vec3(
    ui: &mut egui::Ui,
    label: &str,
    v: &mut Vec3,
    range: std::ops::RangeInclusive<f32>,
) -> bool {
    ui.horizontal(|ui| {
        let label = ui.label(label);
        ui.label_inputs_by(label.id, |ui| {
            let mut changed = false;
            for c in [&mut v.x, &mut v.y, &mut v.z] {
                changed |= ui
                    .add(egui::DragValue::new(c).range(range.clone()).speed(0.01))
                    .changed();
            }
            changed
        })
    })
    .inner
}

/// One number after `label`; true when it changed.
pub(super) fn number(
    ui: &mut egui::Ui,
    label: &str,
    v: &mut f32,
    range: std::ops::RangeInclusive<f32>,
) -> bool {
    ui.horizontal(|ui| {
        let label = ui.label(label);
        ui.add(egui::DragValue::new(v).range(range).speed(0.01))
            .labelled_by(label.id)
            .changed()
    })
    .inner
}
