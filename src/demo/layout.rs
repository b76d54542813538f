//! Where the panel's widgets are, written for whoever drives the window
//! (the window tests: tests/window_demo/main.rs, `click_widget`). With
//! `GLOSS_DEMO_LAYOUT=FILE`, every time egui lays the panel out the demo
//! writes FILE (through a temporary file beside it, renamed over it) as
//! JSON lines: first `{"pass":N,"window":[W,H]}`, then one line per named
//! widget, top to bottom:
//!
//! `{"label":"outlines","kind":"CheckBox","input":true,"rect":[x0,y0,x1,y1],"toggled":true}`
//!
//! (`"about"`: the widget's description, for a choice among words the knob
//! it belongs to, `"label":"volumes", ... "about":"lighting path"`, else its
//! hover text; `"value"`: a number's value; `"text"`: a text field's or
//! drop-down's text).
//!
//! `rect` in window pixels from the top left (egui points times the pixels
//! per point). The names are egui's accessibility tree (AccessKit), which
//! egui fills as it makes each widget: a button or header its text, a knob's
//! control the knob's label (src/demo/panel/knob.rs names them). Five lines
//! name the demo's own areas: "panel" (kind "panel"), "panel scroll" (kind
//! "scroll area": the part of the panel that scrolls and shows its widgets),
//! "panel content" (kind "content": all that it holds, from its top left),
//! "thumbnail strip" (kind "scroll area": the inspector's, which scrolls
//! sideways on its own) and "3D view" (kind "view").

use egui::accesskit::{Node, NodeId, Role, Toggled, TreeUpdate};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// The environment variable naming the file.
pub const ENV: &str = "GLOSS_DEMO_LAYOUT";

/// An egui plugin that keeps the accessibility tree of the last pass.
struct Tap(Arc<Mutex<Option<TreeUpdate>>>);

impl egui::plugin::Plugin for Tap {
    fn debug_name(&self) -> &'static str {
        "gloss layout"
    }

    fn output_hook(&mut self, _ctx: &egui::Context, output: &mut egui::FullOutput) {
        if let Some(tree) = &output.platform_output.accesskit_update
            && let Ok(mut slot) = self.0.lock()
        {
            *slot = Some(tree.clone());
        }
    }
}

pub struct Layout {
    path: PathBuf,
    tree: Arc<Mutex<Option<TreeUpdate>>>,
    pass: u64,
}

impl Layout {
    /// The layout writer asked for by `GLOSS_DEMO_LAYOUT`, hooked into
    /// `ctx` (egui builds its accessibility tree from now on); None when
    /// the variable is not set.
    pub fn from_env(ctx: &egui::Context) -> Option<Layout> {
        let path = PathBuf::from(std::env::var_os(ENV).filter(|p| !p.is_empty())?);
        let tree = Arc::new(Mutex::new(None));
        ctx.enable_accesskit();
        ctx.add_plugin(Tap(Arc::clone(&tree)));
        Some(Layout {
            path,
            tree,
            pass: 0,
        })
    }

    /// Write the widgets of egui's last pass and the demo's `areas` (label,
    /// kind, rectangle in points) for a window `window` pixels large.
    pub fn write(
        &mut self,
        ppp: f32,
        window: (u32, u32),
        areas: &[(&str, &str, egui::Rect)],
    ) -> anyhow::Result<()> {
        let Some(tree) = self.tree.lock().ok().and_then(|mut t| t.take()) else {
            return Ok(());
        };
        self.pass += 1;
        let ppp = f64::from(ppp);
        let mut lines: Vec<(f64, f64, String)> = Vec::new();
        let by_id: HashMap<NodeId, &Node> = tree.nodes.iter().map(|(id, n)| (*id, n)).collect();
        for node in by_id.values() {
            let (Some(name), Some(b)) = (name(node, &by_id), node.bounds()) else {
                continue;
            };
            let rect = [b.x0, b.y0, b.x1, b.y1].map(|v| (v * ppp).round() as i64);
            let mut line = format!(
                "{{\"label\":{},\"kind\":{},\"input\":{},\"rect\":[{},{},{},{}]",
                json(&name),
                json(&format!("{:?}", node.role())),
                egui::accessibility::is_input(node.role()),
                rect[0],
                rect[1],
                rect[2],
                rect[3]
            );
            if let Some(d) = node.description() {
                line.push_str(&format!(",\"about\":{}", json(d)));
            }
            if node.role() != Role::Label
                && let Some(v) = node.value()
            {
                line.push_str(&format!(",\"text\":{}", json(v)));
            }
            if let Some(t) = node.toggled() {
                line.push_str(&format!(",\"toggled\":{}", t == Toggled::True));
            }
            if let Some(v) = node.numeric_value() {
                line.push_str(&format!(",\"value\":{v}"));
            }
            line.push('}');
            lines.push((b.y0, b.x0, line));
        }
        for (label, kind, r) in areas {
            let p = |v: f32| (f64::from(v) * ppp).round() as i64;
            lines.push((
                f64::from(r.min.y),
                f64::from(r.min.x),
                format!(
                    "{{\"label\":{},\"kind\":{},\"input\":false,\"rect\":[{},{},{},{}]}}",
                    json(label),
                    json(kind),
                    p(r.min.x),
                    p(r.min.y),
                    p(r.max.x),
                    p(r.max.y)
                ),
            ));
        }
        lines.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let mut text = format!(
            "{{\"pass\":{},\"window\":[{},{}]}}\n",
            self.pass, window.0, window.1
        );
        for (_, _, l) in lines {
            text.push_str(&l);
            text.push('\n');
        }
        let mut tmp = self.path.clone().into_os_string();
        tmp.push(".tmp");
        let tmp = PathBuf::from(tmp);
        std::fs::write(&tmp, text)
            .and_then(|()| std::fs::rename(&tmp, &self.path))
            .map_err(|e| {
                anyhow::anyhow!(
                    "could not write the panel's layout to {} ({ENV}): {e}",
                    self.path.display()
                )
            })
    }
}

/// A node's name: its own label (a label's text is its value), else that of
/// the node it is labelled by. Containers and unnamed widgets have none.
fn name(node: &Node, by_id: &HashMap<NodeId, &Node>) -> Option<String> {
    let own = |n: &Node| {
        let text = if n.role() == Role::Label {
            n.value()
        } else {
            n.label()
        };
        text.map(str::trim)
            .filter(|t| !t.is_empty())
            .map(str::to_string)
    };
    own(node).or_else(|| {
        let id = node.labelled_by().first()?;
        own(by_id.get(id)?)
    })
}

/// `s` as a JSON string.
fn json(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
