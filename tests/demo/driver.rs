//! The panel driven headless, as a screen reader drives it: egui's
//! AccessKit tree names each widget, and a click or a new value is asked
//! for through it (src/demo/panel/).

use egui::accesskit::{self, NodeId};
use gloss::demo::panel::{Action, PanelInput, PanelState};
use gloss::renderer::Renderer;
use gloss::scene::Scene;

/// The panel in an egui context of its own, tall enough that nothing scrolls.
pub struct Driver {
    ctx: egui::Context,
    pub panel: PanelState,
}

impl Driver {
    pub fn new() -> Driver {
        let ctx = egui::Context::default();
        ctx.enable_accesskit();
        Driver {
            ctx,
            panel: PanelState::new("test.toml"),
        }
    }

    /// One frame of the panel: the actions asked for and the widgets shown.
    pub fn frame(
        &mut self,
        input: &PanelInput,
        events: Vec<egui::Event>,
    ) -> (Vec<Action>, Vec<(NodeId, accesskit::Node)>) {
        let raw = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(480.0, 6000.0),
            )),
            events,
            ..Default::default()
        };
        let mut actions = Vec::new();
        let panel = &mut self.panel;
        let out = self.ctx.run_ui(raw, |ui| actions = panel.show(ui, input));
        let nodes = (out.platform_output.accesskit_update)
            .map(|u| u.nodes)
            .unwrap_or_default();
        (actions, nodes)
    }

    /// The widget named `name` (its label, or a label's text).
    pub fn find(&mut self, input: &PanelInput, name: &str) -> Option<accesskit::Node> {
        let (_, nodes) = self.frame(input, Vec::new());
        nodes.into_iter().map(|(_, n)| n).find(|n| named(n, name))
    }

    /// Click the widget named `name`; the actions of that frame.
    pub fn click(&mut self, input: &PanelInput, name: &str) -> Vec<Action> {
        self.ask(input, name, accesskit::Action::Click, None)
    }

    /// Set the slider named `name` to `value`; the actions of that frame.
    pub fn set_value(&mut self, input: &PanelInput, name: &str, value: f64) -> Vec<Action> {
        let data = Some(accesskit::ActionData::NumericValue(value));
        self.ask(input, name, accesskit::Action::SetValue, data)
    }

    /// Ask the widget named `name` for `action`, as a screen reader does.
    fn ask(
        &mut self,
        input: &PanelInput,
        name: &str,
        action: accesskit::Action,
        data: Option<accesskit::ActionData>,
    ) -> Vec<Action> {
        let (_, nodes) = self.frame(input, Vec::new());
        // The widget itself, not a label beside it that shows its name; a
        // slider is named by the label it is labelled by.
        let labels: Vec<NodeId> = (nodes.iter())
            .filter(|(_, n)| named(n, name))
            .map(|(id, _)| *id)
            .collect();
        let by_name = |n: &accesskit::Node| {
            named(n, name) || n.labelled_by().iter().any(|l| labels.contains(l))
        };
        let mut found = (nodes.iter()).filter(|(_, n)| by_name(n) && n.supports_action(action));
        let first = found.next();
        let slider = first
            .into_iter()
            .chain(found)
            .find(|(_, n)| n.role() == accesskit::Role::Slider);
        let Some((id, _)) = slider.or(first) else {
            let names: Vec<_> = nodes
                .iter()
                .filter_map(|(_, n)| n.label().or(n.value()))
                .collect();
            panic!("no widget named {name:?} among {names:?}");
        };
        let request = egui::Event::AccessKitActionRequest(accesskit::ActionRequest {
            action,
            target_tree: accesskit::TreeId::ROOT,
            target_node: *id,
            data,
        });
        self.frame(input, vec![request]).0
    }
}

pub fn named(n: &accesskit::Node, name: &str) -> bool {
    n.label() == Some(name) || n.value() == Some(name)
}

pub fn input<'a>(scene: &'a Scene, r: &'a Renderer) -> PanelInput<'a> {
    PanelInput {
        scene,
        scene_path: "test.toml",
        shipped: &[],
        plan: &r.plan,
        times: &r.last_times,
        views: &[],
        error: None,
        status: None,
        comparison: None,
        thumbnails: &[],
        gl_info: "headless test",
        size: (r.width, r.height),
        stretch: None,
        volumes: 0,
        probe: None,
        range: None,
    }
}
