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
mod geometry;
mod help;
mod knob;
mod legend;
mod post_chain;
mod post_params;
mod shadow_knobs;
mod structure;
mod timings;
mod values;

pub use animation::advance;
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
    path_text: String,
    save_text: String,
}

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
            path_text: scene_path.to_string(),
            save_text: "edited.toml".into(),
        }
    }

    /// Draw the panel (and the help overlay) and collect what was asked;
    /// note the rectangle left beside it for the 3D view (`view`).
    pub fn show(&mut self, ui: &mut egui::Ui, input: &PanelInput) -> Vec<Action> {
        let mut actions = Vec::new();
        self.drawn = egui::Rect::NOTHING;
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
                egui::ScrollArea::both().show(ui, |ui| {
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
            });
        self.drawn = self.drawn.union(panel.response.rect);
        // Kept while the panel is hidden: Tab brings it back at this width.
        self.view = Some(ui.available_rect_before_wrap());
        actions
    }

    /// The panel's head, outside its scrolling: the frame time, the render
    /// scale, and one fixed slot for the last error or status (so that a
    /// message never pushes the widgets below it down).
    fn top(&mut self, ui: &mut egui::Ui, input: &PanelInput) {
        ui.horizontal(|ui| {
            ui.heading("gloss");
            ui.label(self.frame_time());
            if ui.small_button("hide (Tab)").clicked() {
                self.open = false;
            }
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
    fn overlay(&self, ui: &egui::Ui, view: egui::Rect, input: &PanelInput) -> egui::Rect {
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
                ui.horizontal(|ui| {
                    ui.text_edit_singleline(&mut self.path_text);
                    if ui.button("open").clicked() {
                        actions.push(Action::Load(PathBuf::from(self.path_text.trim())));
                    }
                });
                ui.horizontal(|ui| {
                    ui.text_edit_singleline(&mut self.save_text);
                    if ui.button("save as").clicked() {
                        actions.push(Action::SaveAs(PathBuf::from(self.save_text.trim())));
                    }
                });
                ui.horizontal(|ui| {
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

    fn inspector_section(
        &mut self,
        ui: &mut egui::Ui,
        input: &PanelInput,
        actions: &mut Vec<Action>,
    ) {
        egui::CollapsingHeader::new("Pass inspector")
            .default_open(true)
            .show(ui, |ui| {
                let current = self.inspect;
                let label = |i: Option<usize>| match i {
                    None => "output: the final image".to_string(),
                    Some(i) => input.views.get(i).map(View::label).unwrap_or_default(),
                };
                egui::ComboBox::from_id_salt("inspector")
                    .width(300.0)
                    .selected_text(label(current))
                    .show_ui(ui, |ui| {
                        for i in std::iter::once(None).chain((0..input.views.len()).map(Some)) {
                            if ui.selectable_label(current == i, label(i)).clicked() {
                                actions.push(Action::Inspect(i));
                            }
                        }
                    });
                ui.checkbox(&mut self.thumbnails, "thumbnails (click one to view it)");
                if self.thumbnails {
                    egui::ScrollArea::horizontal().show(ui, |ui| {
                        ui.horizontal(|ui| {
                            for (i, t) in input.thumbnails.iter().enumerate() {
                                let Some(t) = t else { continue };
                                let image = egui::Image::from_texture(t)
                                    .fit_to_exact_size(egui::vec2(96.0, 54.0))
                                    .sense(egui::Sense::click());
                                let r = ui.add(image).on_hover_text(
                                    input.views.get(i).map(View::label).unwrap_or_default(),
                                );
                                if r.clicked() {
                                    actions.push(Action::Inspect(Some(i)));
                                }
                            }
                        });
                    });
                }
                ui.add(
                    egui::Slider::new(&mut self.exposure, 0.01..=100.0)
                        .logarithmic(true)
                        .text("exposure (light views)"),
                );
                if current.and_then(|i| input.views.get(i)).is_some_and(|v| v.stencil) {
                    // The stencil as any pass left it (the frame is drawn
                    // again up to that pass).
                    let passes = &input.plan.passes;
                    self.stencil_after = self.stencil_after.min(passes.len());
                    ui.add(
                        egui::Slider::new(&mut self.stencil_after, 0..=passes.len())
                            .text("stencil after pass (0: end of frame)"),
                    );
                    if let Some(p) = self.stencil_after.checked_sub(1).and_then(|i| passes.get(i)) {
                        let title = input.plan.title(self.stencil_after - 1);
                        ui.small(format!("{}. {title}: {}", self.stencil_after, p.draws));
                    }
                }
                ui.horizontal(|ui| {
                    if ui.button("compare with reference").on_hover_text(
                        "render forward with the same camera and size; show RMSE, max and the difference (a view above)",
                    ).clicked() {
                        actions.push(Action::Compare);
                    }
                });
                if let Some(c) = input.comparison {
                    ui.label(c);
                }
                if let Some(v) = current.and_then(|i| input.views.get(i)) {
                    legend::show(ui, v, input);
                }
                if let Some(s) = current.and_then(|i| input.views.get(i)?.shadow) {
                    let n = s.resolution;
                    let (lo, hi) = input.stretch.unwrap_or((0.0, 1.0));
                    ui.small(format!(
                        "light {}'s map, {n} x {n}{} DEPTH_COMPONENT32F: black {lo:.4}, white {hi:.4}",
                        s.light,
                        if s.cube() { " x 6" } else { "" }
                    ));
                } else if let Some(v) = current.and_then(|i| input.views.get(i)) {
                    let fb = input
                        .plan
                        .target(v.target)
                        .map(|t| t.attachments().join(", "));
                    let (w, h) = input.size;
                    ui.small(format!("{} ({w}x{h}): {}", v.target, fb.unwrap_or_default()));
                }
            });
    }
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
            if changed {
                actions.push(Action::Settings(settings));
            }
        });
}
