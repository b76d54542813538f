//! The panel's animation section (notes 01 §7; src/scene/animation.rs),
//! shown when the scene has keyframe tracks or particles: play or pause, scrub the time
//! over the keys' span, and the playing speed. Scrubbing asks for
//! `Action::Time`; while playing, the demo advances the time each frame
//! (`advance`). Each skinned object (notes 01 §7.1) gets its skinning
//! method and clip.

use super::{Action, PanelInput, PanelState};

/// The time `dt` seconds after `t`, looping over the span `(first, last)`.
pub fn advance(t: f32, dt: f32, (first, last): (f32, f32)) -> f32 {
    let length = last - first;
    if length.is_nan() || length <= 0.0 || !(t + dt).is_finite() {
        return first;
    }
    first + (t + dt - first).rem_euclid(length)
}

/// Did the user move the time slider? Drawing it rounds the time to its
/// 2 decimals, which egui reports as a change: only a drag, or a new value
/// further off than that rounding (a click, a key, a screen reader), is the
/// user's, and only that pauses the playing.
fn scrubbed(r: &egui::Response, before: f32, after: f32) -> bool {
    r.dragged() || r.drag_stopped() || (r.changed() && (after - before).abs() > 0.006)
}

impl PanelState {
    pub(super) fn animation_section(
        &mut self,
        ui: &mut egui::Ui,
        input: &PanelInput,
        actions: &mut Vec<Action>,
    ) {
        let Some((first, last)) = input.scene.playable_span() else {
            return;
        };
        let clips = input.scene.animation.tracks.len();
        egui::CollapsingHeader::new(format!("Animation ({clips} tracks)"))
            .default_open(true)
            .show(ui, |ui| {
                ui.checkbox(&mut self.playing, "play");
                let t0 = input.scene.animation.time;
                let mut t = t0;
                let slider = egui::Slider::new(&mut t, first..=last)
                    .text("time (s)")
                    .fixed_decimals(2);
                let r = ui.add(slider);
                if scrubbed(&r, t0, t) {
                    self.playing = false;
                    actions.push(Action::Time(t));
                }
                ui.add(egui::Slider::new(&mut self.speed, 0.0..=4.0).text("speed"));
                for i in input.scene.skinned_objects() {
                    skin_controls(ui, i, input.scene, actions);
                }
            });
    }
}

/// Object `i`'s skinning method and clip.
fn skin_controls(
    ui: &mut egui::Ui,
    i: usize,
    scene: &crate::scene::Scene,
    actions: &mut Vec<Action>,
) {
    let mut skin = scene.objects[i].skin.clone().unwrap();
    let before = (skin.method, skin.clip);
    // Wrapped at the panel's edge; the two drop-downs named by the object.
    ui.horizontal_wrapped(|ui| {
        let label = ui.label(&scene.objects[i].name);
        ui.label_inputs_by(label.id, |ui| skin_menus(ui, i, &mut skin));
    });
    if (skin.method, skin.clip) != before {
        actions.push(Action::Skin(i, skin));
    }
}

/// The skinning method's and the clip's drop-downs.
fn skin_menus(ui: &mut egui::Ui, i: usize, skin: &mut crate::scene::skins::ObjectSkin) {
    use crate::scene::SkinMethod;
    egui::ComboBox::from_id_salt(("skinning", i))
        .selected_text(skin.method.name())
        .show_ui(ui, |ui| {
            for &m in SkinMethod::ALL {
                ui.selectable_value(&mut skin.method, m, m.name());
            }
        });
    egui::ComboBox::from_id_salt(("clip", i))
        .selected_text(skin.clip_name().to_owned())
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut skin.clip, None, "rest pose");
            for (c, clip) in skin.mesh.clips.iter().enumerate() {
                ui.selectable_value(&mut skin.clip, Some(c), clip.name.as_str());
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_time_loops_over_the_span() {
        assert_eq!(advance(0.5, 0.25, (0.0, 2.0)), 0.75);
        assert!((advance(1.9, 0.3, (0.0, 2.0)) - 0.2).abs() < 1e-6);
        assert!((advance(3.0, 0.0, (1.0, 2.0)) - 1.0).abs() < 1e-6);
        // Before the span: brought into it.
        assert!((advance(-0.5, 0.0, (0.0, 2.0)) - 1.5).abs() < 1e-6);
        // One key, or a time that is not a number: the first key.
        assert_eq!(advance(0.3, 0.1, (1.0, 1.0)), 1.0);
        assert_eq!(advance(f32::NAN, 0.1, (0.0, 2.0)), 0.0);
    }
}
