//! The panel's section for notes 01 §3's vertex and geometry stages, shown
//! when the scene has them: the particle fountain (how many, built by the
//! geometry shader or on the CPU, streamed mapped or by glBufferSubData)
//! and the tessellated terrain (its levels, shared or per-patch edges, the
//! wireframe).

use super::{Action, PanelInput, PanelState};

impl PanelState {
    pub(super) fn geometry_section(
        &mut self,
        ui: &mut egui::Ui,
        input: &PanelInput,
        actions: &mut Vec<Action>,
    ) {
        let scene = input.scene;
        if scene.particles.is_none() && scene.tessellation.is_none() {
            return;
        }
        egui::CollapsingHeader::new("Vertex and geometry stages")
            .default_open(true)
            .show(ui, |ui| {
                if let Some(p) = &scene.particles {
                    let mut p = p.clone();
                    let mut changed = false;
                    let mut alive = p.count;
                    let slider = egui::Slider::new(&mut alive, 1..=1_000_000)
                        .logarithmic(true)
                        .text("particles alive");
                    if ui.add(slider).changed() {
                        // As many born a lifetime as may live.
                        p.count = alive;
                        p.rate = alive as f32 / p.lifetime;
                        changed = true;
                    }
                    changed |= ui
                        .checkbox(&mut p.geometry_shader, "quads from the geometry shader")
                        .changed();
                    changed |= ui
                        .checkbox(&mut p.map, "stream through a mapped buffer")
                        .changed();
                    if changed {
                        actions.push(Action::Particles(p));
                    }
                }
                if let Some(t) = &scene.tessellation {
                    let mut t = t.clone();
                    let max = crate::scene::tessellation::MAX_LEVEL;
                    let mut changed = false;
                    let [mut far, mut near] = t.levels;
                    changed |= ui
                        .add(egui::Slider::new(&mut near, 1.0..=max).text("level near"))
                        .changed();
                    changed |= ui
                        .add(egui::Slider::new(&mut far, 1.0..=max).text("level far"))
                        .changed();
                    t.levels = [far.min(near), near];
                    changed |= ui
                        .checkbox(&mut t.shared_edges, "a level per edge (no cracks)")
                        .changed();
                    changed |= ui.checkbox(&mut t.wireframe, "wireframe").changed();
                    if changed {
                        actions.push(Action::Tessellation(t));
                    }
                }
            });
    }
}
