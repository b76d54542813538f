//! The "Post chain" section (notes 01 §9 "Post processing"; docs/post.md):
//! the scene's `[[post]]` entries in the order they run, each with its
//! parameters, buttons to move or remove it, a pass to add (before the
//! final gamma), and the chain's form (ping-pong or cascaded).
//!
//! Every edit becomes an `Action::Post` with the whole edited chain; the
//! demo checks it with the scene loader's rules (src/demo/post_chain.rs)
//! and refuses a chain a file could not hold (gamma removed, moved or
//! doubled) with a message shown here, the old chain still running.
//!
//! Bloom's and FXAA's widgets are in src/demo/panel/post_params.rs.

use super::post_params::combo;
use super::{Action, PanelInput};
use crate::demo::post_chain::{REFUSED, with_added};
use crate::frame::post::steps_of;
use crate::scene::post::{
    ChainForm, KERNELS, Kernel3, MAX_BLUR_RADIUS, PASS_NAMES, PostPass, Taps, ToneOperator,
};

/// The colour of the refusal message (the panel's error colour).
const REFUSED_COLOR: egui::Color32 = egui::Color32::from_rgb(255, 110, 90);

/// The section: the edited chain and the chain's form become actions.
pub fn section(ui: &mut egui::Ui, input: &PanelInput, actions: &mut Vec<Action>) {
    let scene = input.scene;
    let title = format!("Post chain ({})", scene.post.len());
    egui::CollapsingHeader::new(title)
        .id_salt("post chain")
        .default_open(true)
        .show(ui, |ui| {
            let mut form = scene.render.post_chain;
            ui.horizontal_wrapped(|ui| {
                ui.label("form");
                for (f, word) in [
                    (ChainForm::PingPong, "ping-pong (two textures)"),
                    (ChainForm::Cascaded, "cascaded (a framebuffer per step)"),
                ] {
                    ui.selectable_value(&mut form, f, word);
                }
            });
            if form != scene.render.post_chain {
                let mut settings = scene.render.clone();
                settings.post_chain = form;
                actions.push(Action::Settings(settings));
            }
            if let Some(e) = input.error.filter(|e| e.starts_with(REFUSED)) {
                ui.colored_label(REFUSED_COLOR, e);
            }
            if scene.post.is_empty() {
                ui.weak("no [[post]] entries: the lighting passes encode to sRGB into the output");
            }
            let mut chain = scene.post.clone();
            let mut changed = false;
            let mut step = 1;
            let n = chain.len();
            let mut edit = None;
            for (i, p) in chain.iter_mut().enumerate() {
                ui.group(|ui| {
                    ui.horizontal(|ui| {
                        let steps = steps_of(p);
                        let at = match steps {
                            1 => format!("step {step}"),
                            k => format!("steps {step}-{}", step + k - 1),
                        };
                        step += steps;
                        ui.strong(format!("{}. {}", i + 1, p.name()))
                            .on_hover_text(format!("post[{i}], {at} of the chain"));
                        let name = format!("post[{i}] ({})", p.name());
                        if button(ui, "up", &format!("move {name} up"), i > 0) {
                            edit = Some(Edit::Swap(i - 1));
                        }
                        if button(ui, "down", &format!("move {name} down"), i + 1 < n) {
                            edit = Some(Edit::Swap(i));
                        }
                        if button(ui, "remove", &format!("remove {name}"), true) {
                            edit = Some(Edit::Remove(i));
                        }
                    });
                    changed |= parameters(ui, i, p);
                });
            }
            match edit {
                Some(Edit::Swap(i)) => chain.swap(i, i + 1),
                Some(Edit::Remove(i)) => {
                    chain.remove(i);
                }
                None => {}
            }
            let mut added = None;
            egui::ComboBox::from_id_salt("post add")
                .selected_text("add a pass…")
                .show_ui(ui, |ui| {
                    for name in PASS_NAMES {
                        if ui.selectable_label(false, name).clicked() {
                            added = Some(name);
                            ui.close();
                        }
                    }
                });
            if let Some(name) = added {
                // A pass that cannot be made is refused as an edit is.
                match with_added(&chain, name) {
                    Ok(c) => chain = c,
                    Err(e) => {
                        ui.colored_label(REFUSED_COLOR, format!("{e:#}"));
                        return;
                    }
                }
            }
            if changed || edit.is_some() || added.is_some() {
                actions.push(Action::Post(chain));
            }
        });
}

enum Edit {
    /// Swap entries i and i + 1.
    Swap(usize),
    Remove(usize),
}

/// A small button showing `text`, named `name` for a screen reader (and
/// the tests) and on hover; true when clicked.
fn button(ui: &mut egui::Ui, text: &str, name: &str, enabled: bool) -> bool {
    let r = ui.add_enabled(enabled, egui::Button::new(text).small());
    r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, enabled, name));
    r.on_hover_text(name).clicked()
}

/// Entry `i`'s parameters as widgets; true when one changed.
fn parameters(ui: &mut egui::Ui, i: usize, p: &mut PostPass) -> bool {
    let mut changed = false;
    match p {
        PostPass::Tonemap { operator, exposure } => {
            let all = ToneOperator::ALL;
            changed |= combo(ui, ("post operator", i), "operator", operator, all, |o| {
                o.name()
            });
            let s = egui::Slider::new(exposure, 0.01..=100.0).logarithmic(true);
            changed |= ui.add(s.text("exposure multiplier")).changed();
        }
        PostPass::Gamma { gamma, srgb } => {
            let exact = "exact sRGB (GL_FRAMEBUFFER_SRGB)";
            changed |= ui.checkbox(srgb, exact).changed();
            if !*srgb {
                let s = egui::Slider::new(gamma, 0.1..=10.0).text("γ (out = in^(1/γ))");
                changed |= ui.add(s).changed();
            }
        }
        PostPass::Blur {
            sigma,
            radius,
            taps,
        } => {
            // The radius follows sigma (ceil(3 sigma), the file's default)
            // until it is set apart from it.
            let follows = *radius == default_radius(*sigma);
            let s = egui::Slider::new(sigma, 0.1..=MAX_BLUR_RADIUS as f32 / 2.0);
            if ui.add(s.logarithmic(true).text("sigma (texels)")).changed() {
                changed = true;
                if follows {
                    *radius = default_radius(*sigma);
                }
            }
            changed |= radius_slider(ui, radius);
            let all = [Taps::Direct, Taps::Linear];
            changed |= combo(ui, ("post taps", i), "taps", taps, all, Taps::name);
        }
        PostPass::Box { radius } => changed |= radius_slider(ui, radius),
        PostPass::Kernel(k) => changed |= kernel(ui, i, k),
        PostPass::Bloom(b) => changed |= super::post_params::bloom(ui, i, b),
        PostPass::Fxaa(x) => changed |= super::post_params::fxaa(ui, i, x),
        PostPass::Grayscale | PostPass::Invert => {}
    }
    changed
}

fn default_radius(sigma: f32) -> u32 {
    ((3.0 * sigma).ceil() as u32).clamp(1, MAX_BLUR_RADIUS)
}

fn radius_slider(ui: &mut egui::Ui, radius: &mut u32) -> bool {
    let s = egui::Slider::new(radius, 1..=MAX_BLUR_RADIUS).text("radius (texels)");
    ui.add(s).changed()
}

/// A 3x3 kernel: a preset, or the nine weights row by row (editing one
/// makes the kernel the file's nine numbers).
fn kernel(ui: &mut egui::Ui, i: usize, k: &mut Kernel3) -> bool {
    let mut changed = false;
    ui.horizontal(|ui| {
        ui.label("kernel");
        egui::ComboBox::from_id_salt(("post kernel", i))
            .selected_text(k.preset.unwrap_or("nine weights"))
            .show_ui(ui, |ui| {
                for (name, w) in KERNELS {
                    if ui.selectable_label(k.preset == Some(name), name).clicked() {
                        *k = Kernel3 {
                            preset: Some(name),
                            weights: w,
                        };
                        changed = true;
                        ui.close();
                    }
                }
            });
    });
    egui::Grid::new(("post kernel weights", i)).show(ui, |ui| {
        for row in k.weights.chunks_mut(3) {
            for w in row {
                let d = egui::DragValue::new(w).range(-100.0..=100.0).speed(0.05);
                if ui.add(d).changed() {
                    changed = true;
                    k.preset = None;
                }
            }
            ui.end_row();
        }
    });
    changed
}
