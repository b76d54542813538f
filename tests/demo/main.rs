//! The demo (src/demo/): its panel, drawn headless with egui_glow over a
//! rendered frame. The window itself is driven under Xvfb in
//! tests/window_smoke.rs.

#[path = "../common/mod.rs"]
mod common;

mod animation;
mod compare;
mod driver;
mod inspector_truth;
mod panel;
mod pass_names;
mod pictures;
mod post_chain;
mod probe;
mod robustness;
mod save;
mod settings;
mod shadow_knobs;
mod shadow_views;
mod volumes;
