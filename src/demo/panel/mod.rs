//! The demo's panel (egui): the scene, the techniques of the frame and their
//! settings, the pass inspector, per-pass timings, the frame plan and the
//! keys. It reads the frame through `PanelInput` and answers with `Action`s
//! that the demo carries out after painting; it changes nothing itself.
//!
//! Nothing here names a technique: the technique list and each one's
//! settings come from the registry (src/techniques/mod.rs) and the knobs it
//! lists, and the inspector's views from the plan's targets, so a technique
//! appears here through its one registration.

mod animation;
mod fields;
mod geometry;
mod head;
mod help;
mod inspector;
mod knob;
mod legend;
mod post_chain;
mod post_params;
mod probe;
mod shadow_knobs;
mod structure;
mod timings;
mod values;

pub use animation::advance;
pub use head::RenderScale;
pub use shadow_knobs::too_many_casters;
pub use timings::Timings;

use super::inspector::View;
use crate::frame::plan::FramePlan;
use crate::frame::timing::PassTimes;
use crate::scene::{Camera, Light, Material, RenderSettings, Scene, knobs};
use crate::techniques;
use help::{help_window, keys_grid};
use std::path::PathBuf;

/// The panel's width when it opens (egui points).
pub const PANEL_WIDTH: u16 = 340;

/// What the panel asks the demo to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Load a scene file (a path, or the name of a shipped scene).
    Load(PathBuf),
    /// Write the scene, with the panel's edits, to a file.
    SaveAs(PathBuf),
    Reload,
    Settings(RenderSettings),
    /// The number of lights of the scene's `[light_grid]`.
    LightCount(usize),
    /// The scene's `[light_grid]`, edited.
    LightGrid(crate::scene::LightGrid),
    /// The billboards list and fields, edited.
    Billboards(
        Vec<crate::scene::BillboardFile>,
        Vec<crate::scene::BillboardFieldFile>,
    ),
    /// The split views' rectangles, edited.
    Views(Vec<crate::scene::SplitView>),
    /// Edited lights (all of them, in the scene's order).
    Lights(Vec<Light>),
    /// Edited materials (all of them).
    Materials(Vec<Material>),
    /// The camera's lens edited.
    Camera(Camera),
    /// Edited object transforms (all objects, in the scene's order).
    Objects(Vec<crate::scene::Object>),
    /// The edited post chain (all entries, in order): checked, then run.
    Post(Vec<crate::scene::post::PostPass>),
    /// Show a view full-window (None: the final image).
    Inspect(Option<usize>),
    /// A screenshot; `true`: with the panel.
    Screenshot(bool),
    ResetCamera,
    /// Compare the frame with the forward reference.
    Compare,
    /// Show this instant of the scene's animation (seconds).
    Time(f32),
    /// The particle fountain, edited.
    Particles(crate::scene::particles::Particles),
    /// The tessellated terrain, edited.
    Tessellation(crate::scene::tessellation::Tessellation),
    /// A skinned object's method and clip (notes 01 §7.1), edited.
    Skin(usize, crate::scene::skins::ObjectSkin),
}

/// What the panel shows.
pub struct PanelInput<'a> {
    pub scene: &'a Scene,
    pub scene_path: &'a str,
    pub shipped: &'a [String],
    pub plan: &'a FramePlan,
    pub times: &'a PassTimes,
    pub views: &'a [View],
    pub error: Option<&'a str>,
    pub status: Option<&'a str>,
    /// The last comparison with the forward reference, in words.
    pub comparison: Option<&'a str>,
    /// A small picture of each view (None: no thumbnail for it).
    pub thumbnails: &'a [Option<egui::TextureHandle>],
    pub gl_info: &'a str,
    /// The frame's size in pixels (every target has it).
    pub size: (i32, i32),
    /// The least and greatest value below 1.0 that the shadow-map view
    /// shown stretches to black and white.
    pub stretch: Option<(f32, f32)>,
    /// How many lights have a volume (the overdraw view's hottest count).
    pub volumes: usize,
    /// What the probed pixel holds (src/renderer/probe.rs).
    pub probe: Option<&'a crate::renderer::Probe>,
    /// A one-channel view's least and greatest value, read back.
    pub range: Option<(f32, f32)>,
}

/// What the panel remembers between frames.
pub struct PanelState {
    pub open: bool,
    pub help: bool,
    pub inspect: Option<usize>,
    pub exposure: f32,
    /// The stencil view shows the stencil right after this pass (1-based,
    /// as `gloss plan` numbers them; 0: at the end of the frame).
    pub stencil_after: usize,
    pub timings: Timings,
    /// Time each pass (glFinish after it) while the panel is shown.
    pub pass_times: bool,
    /// Draw the inspector's thumbnail strip.
    pub thumbnails: bool,
    /// Play the scene's animation (advance its time every frame).
    pub playing: bool,
    /// How fast it plays (1: real time).
    pub speed: f32,
    /// The view is rendered at this fraction of its size.
    pub scale: RenderScale,
    /// The rectangle beside the panel (egui points) at its last drawing:
    /// the 3D view's.
    pub view: Option<egui::Rect>,
    /// What the panel drew at its last drawing (points): the panel, the
    /// overlay, the help window. egui's own used rectangle is the pass
    /// before's.
    pub drawn: egui::Rect,
    /// Probe the pixel under the pointer every frame, not only on a click.
    pub probe_follow: bool,
    /// The panel's rectangle and the part of it that scrolls (points), at
    /// its last drawing; None while hidden.
    pub rect: Option<egui::Rect>,
    pub scroll: Option<egui::Rect>,
    /// The size of all that the scrolling part holds (points), from its
    /// top left: wider than `scroll` when something runs past the edge.
    pub content: Option<egui::Rect>,
    /// The inspector's thumbnail strip, which scrolls sideways on its own
    /// (points), at its last drawing; None while not drawn.
    pub strip: Option<egui::Rect>,
    /// The probe's magnifier, kept until the panel is drawn again.
    magnifier: Option<egui::TextureHandle>,
    path_text: String,
    save_text: String,
}

impl PanelState {
    pub fn new(scene_path: &str) -> PanelState {
        PanelState {
            open: true,
            help: false,
            inspect: None,
            exposure: 1.0,
            stencil_after: 0,
            timings: Timings::default(),
            pass_times: true,
            thumbnails: true,
            playing: true,
            speed: 1.0,
            scale: RenderScale::Full,
            // Until the panel is first drawn: the panel at its first width.
            drawn: egui::Rect::NOTHING,
            view: Some(egui::Rect::from_min_max(
                egui::pos2(f32::from(PANEL_WIDTH), 0.0),
                egui::pos2(f32::INFINITY, f32::INFINITY),
            )),
            probe_follow: false,
            rect: None,
            scroll: None,
            content: None,
            strip: None,
            magnifier: None,
            path_text: scene_path.to_string(),
            save_text: "edited.toml".into(),
        }
    }

    /// Draw the panel (and the help overlay) and collect what was asked;
    /// note the rectangle left beside it for the 3D view (`view`).
    pub fn show(&mut self, ui: &mut egui::Ui, input: &PanelInput) -> Vec<Action> {
        let mut actions = Vec::new();
        self.drawn = egui::Rect::NOTHING;
        (self.rect, self.scroll, self.content) = (None, None, None);
        self.strip = None;
        if self.help
            && let Some(r) = help_window(ui, &mut self.help)
        {
            self.drawn = r;
        }
        if !self.open {
            let r = self.overlay(ui, ui.available_rect_before_wrap(), input);
            self.drawn = self.drawn.union(r);
            return actions;
        }
        let panel = egui::Panel::left("gloss-panel")
            .default_size(f32::from(PANEL_WIDTH))
            .size_range(220.0..=900.0)
            .resizable(true)
            .show(ui, |ui| {
                self.top(ui, input);
                // Wide content (the plan, long names) scrolls sideways
                // rather than widening the panel.
                let scroll = egui::ScrollArea::both().show(ui, |ui| {
                    self.probe_section(ui, input);
                    self.scene_section(ui, input, &mut actions);
                    self.animation_section(ui, input, &mut actions);
                    self.geometry_section(ui, input, &mut actions);
                    technique_section(ui, input, &mut actions);
                    post_chain::section(ui, input, &mut actions);
                    self.inspector_section(ui, input, &mut actions);
                    self.timings
                        .show(ui, input.plan, input.times, &mut self.pass_times);
                    egui::CollapsingHeader::new("Frame plan")
                        .default_open(false)
                        .show(ui, |ui| {
                            ui.monospace(input.plan.to_string());
                        });
                    egui::CollapsingHeader::new("Keys")
                        .default_open(false)
                        .show(ui, keys_grid);
                });
                self.scroll = Some(scroll.inner_rect);
                self.content = Some(egui::Rect::from_min_size(
                    scroll.inner_rect.min,
                    scroll.content_size,
                ));
            });
        self.drawn = self.drawn.union(panel.response.rect);
        self.rect = Some(panel.response.rect);
        // Kept while the panel is hidden: Tab brings it back at this width.
        self.view = Some(ui.available_rect_before_wrap());
        actions
    }

    fn scene_section(&mut self, ui: &mut egui::Ui, input: &PanelInput, actions: &mut Vec<Action>) {
        egui::CollapsingHeader::new("Scene")
            .default_open(true)
            .show(ui, |ui| {
                ui.label(format!("{} ({})", input.scene.name, input.scene_path));
                egui::ComboBox::from_id_salt("shipped-scenes")
                    .selected_text("shipped scenes…")
                    .show_ui(ui, |ui| {
                        for s in input.shipped {
                            if ui.selectable_label(false, s).clicked() {
                                actions.push(Action::Load(PathBuf::from(s)));
                            }
                        }
                    });
                if field_and_button(ui, &mut self.path_text, "scene path", "open") {
                    actions.push(Action::Load(PathBuf::from(self.path_text.trim())));
                }
                if field_and_button(ui, &mut self.save_text, "file to save as", "save as") {
                    actions.push(Action::SaveAs(PathBuf::from(self.save_text.trim())));
                }
                ui.horizontal_wrapped(|ui| {
                    if ui.button("reload (F5)").clicked() {
                        actions.push(Action::Reload);
                    }
                    if ui.button("reset camera (R)").clicked() {
                        actions.push(Action::ResetCamera);
                    }
                    if ui.button("screenshot (F12)").clicked() {
                        actions.push(Action::Screenshot(false));
                    }
                });
                if let Some(n) = input.scene.grid_lights {
                    let mut count = n;
                    let fixed = input.scene.lights.len() - n;
                    ui.horizontal(|ui| {
                        ui.label("light grid:");
                        let r = ui.add(egui::Slider::new(&mut count, 0..=1024).logarithmic(true));
                        if r.drag_stopped() || (r.changed() && !r.dragged()) {
                            actions.push(Action::LightCount(count));
                        }
                        ui.label(format!("(+{fixed} fixed)"));
                    });
                }
                if let Some(g) = values::light_grid(ui, input.scene) {
                    actions.push(Action::LightGrid(g));
                }
                if let Some(l) = values::lights(ui, input.scene) {
                    actions.push(Action::Lights(l));
                }
                if let Some(m) = values::materials(ui, input.scene) {
                    actions.push(Action::Materials(m));
                }
                if let Some(o) = values::objects(ui, input.scene) {
                    actions.push(Action::Objects(o));
                }
                if let Some((list, fields)) = structure::billboards(ui, input.scene) {
                    actions.push(Action::Billboards(list, fields));
                }
                if let Some(v) = structure::views(ui, input.scene) {
                    actions.push(Action::Views(v));
                }
                if let Some(c) = values::camera(ui, &input.scene.camera) {
                    actions.push(Action::Camera(c));
                }
            });
    }
}

/// A text field named `name` filling the row, and `button` at its right
/// end (inside the panel at any width); true when the button was clicked.
fn field_and_button(ui: &mut egui::Ui, text: &mut String, name: &str, button: &str) -> bool {
    // One row high: a layout of the whole height would centre the row in it.
    let row = egui::vec2(ui.available_width(), ui.spacing().interact_size.y);
    let layout = egui::Layout::right_to_left(egui::Align::Center);
    ui.allocate_ui_with_layout(row, layout, |ui| {
        let clicked = ui.button(button).clicked();
        let field = egui::TextEdit::singleline(text).desired_width(f32::INFINITY);
        ui.add(field).accessible_name(name);
        clicked
    })
    .inner
}

/// The lighting path, then every registered technique: those in this frame
/// with the settings they read, the others named.
fn technique_section(ui: &mut egui::Ui, input: &PanelInput, actions: &mut Vec<Action>) {
    egui::CollapsingHeader::new("Techniques")
        .default_open(true)
        .show(ui, |ui| {
            let mut settings = input.scene.render.clone();
            let mut changed = knob::show(ui, &knobs::PATH, &mut settings);
            let mut shown = vec![knobs::PATH.key];
            for (i, t) in techniques::ALL.iter().enumerate() {
                let runs = input.plan.passes.iter().any(|p| p.technique == i);
                if !runs {
                    continue;
                }
                ui.separator();
                ui.strong(t.name)
                    .on_hover_text(format!("{}\n{}", t.notes, t.file));
                for k in t.knobs {
                    if !shown.contains(&k.key) {
                        shown.push(k.key);
                        changed |= knob::show(ui, k, &mut settings);
                    }
                }
            }
            let idle: Vec<&str> = techniques::ALL
                .iter()
                .enumerate()
                .filter(|(i, _)| !input.plan.passes.iter().any(|p| p.technique == *i))
                .map(|(_, t)| t.name)
                .collect();
            if !idle.is_empty() {
                ui.separator();
                ui.weak(format!("not in this frame: {}", idle.join(", ")));
            }
            // A technique switched off: its switch stays, to turn it on.
            for (k, applies) in knobs::SWITCHES {
                if applies(input.scene) && !shown.contains(&k.key) {
                    shown.push(k.key);
                    changed |= knob::show(ui, k, &mut settings);
                }
            }
            if changed {
                actions.push(Action::Settings(settings));
            }
        });
}
