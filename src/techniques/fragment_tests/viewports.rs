//! Split viewports with scissored clears (notes 01 §4.2 "Scissor testing":
//! "fragments outside of a given rectangle on the screen are discarded; can
//! set unique scissor box per viewport").
//!
//! A scene with `[[views]]` (src/scene/views.rs) is drawn once per view,
//! each into its own rectangle of the output, from its own camera (an
//! orthographic top, front and side view and a perspective one, as a
//! modelling program shows them). The world passes of the lighting path run
//! for each view in turn; for a split view each of them
//!
//! 1. sets glViewport(x, y, w, h) to the view's rectangle, so the view's
//!    projection fills it (its aspect is the rectangle's);
//! 2. clears the output with glEnable(GL_SCISSOR_TEST) and glScissor(x, y,
//!    w, h): glViewport does not limit glClear, the scissor test does, so
//!    one view's clear leaves the others' pixels alone.
//!
//! Those calls are in each pass that draws or clears (src/frame/views.rs,
//! `View::rect`). This file orders the frame (one `Stage::World` per view)
//! and adds one pass of its own after the views: each view's edges drawn as
//! one-pixel lines by scissored clears, the scissor test as a drawing tool
//! (`glScissor` to a 1-pixel-wide box, then `glClear`). It needs no shader.

use crate::frame::lights::FrameLights;
use crate::frame::plan::Pass;
use crate::frame::post::world_target;
use crate::frame::targets::TargetDesc;
use crate::frame::views::View;
use crate::frame::{Frame, FrameOrder, Programs, RunPasses, Runs, Stage, Technique};
use crate::scene::Scene;
use anyhow::Result;
use glow::HasContext;

pub const VIEWPORTS: Technique = Technique {
    name: "viewports",
    notes: "notes 01 §4.2, Scissor testing",
    file: file!(),
    shaders: &[],
    scene: "scenes/viewports.toml",
    docs: "docs/fragment_tests/viewports.md",
    knobs: &[],
    passes,
    targets,
    create,
    order: Some(order),
    runs: Runs::PerView,
};

fn passes(_: &Scene, _: &FrameLights) -> Vec<Pass> {
    vec![]
}

fn targets(_: &Scene, _: &FrameLights) -> Vec<TargetDesc> {
    vec![]
}

/// One view per `[[views]]` entry, the world drawn for each in turn; None
/// for a scene without split views.
fn order(scene: &Scene, _: &FrameLights) -> Option<FrameOrder> {
    if scene.views.is_empty() {
        return None;
    }
    let views: Vec<View> = scene
        .views
        .iter()
        .map(|v| View {
            name: format!("'{}' in [{}]", v.name, fractions(v.viewport)),
            camera: v.camera.clone(),
            viewport: Some(v.viewport),
            ..View::camera()
        })
        .collect();
    let mut stages: Vec<Stage> = (0..views.len()).map(Stage::World).collect();
    let draws = format!("{} views' edges, 1-pixel scissored clears", views.len());
    stages.push(Stage::Own(Pass::new(
        "viewport borders",
        world_target(scene),
        draws,
        file!(),
    )));
    Some(FrameOrder { views, stages })
}

fn fractions(r: [f32; 4]) -> String {
    r.map(|x| format!("{x}")).join(", ")
}

/// The borders' colour (linear grey; encoded like the clear colour).
const BORDER: f32 = 0.5;

/// The pass draws with glClear only: no program to build.
struct Viewports;

fn create(_: &Programs) -> Result<Box<dyn RunPasses>> {
    Ok(Box::new(Viewports))
}

impl RunPasses for Viewports {
    /// Each view's four edges, one pixel wide, as scissored clears.
    fn run(&self, _: &Pass, f: &Frame) {
        let gl = f.gl;
        let output = f.targets.get(world_target(f.scene));
        let grey = if f.uniforms.output_srgb {
            crate::lighting::srgb_encode(BORDER)
        } else {
            BORDER
        };
        unsafe {
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(output.id));
            gl.clear_color(grey, grey, grey, 1.0);
            gl.enable(glow::SCISSOR_TEST);
            for v in &f.scene.views {
                let view = View {
                    viewport: Some(v.viewport),
                    ..View::camera()
                };
                let (x, y, w, h) = view.rect(output.width, output.height);
                for (bx, by, bw, bh) in [
                    (x, y, w, 1),         // bottom
                    (x, y + h - 1, w, 1), // top
                    (x, y, 1, h),         // left
                    (x + w - 1, y, 1, h), // right
                ] {
                    gl.scissor(bx, by, bw, bh);
                    gl.clear(glow::COLOR_BUFFER_BIT);
                }
            }
            gl.disable(glow::SCISSOR_TEST);
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        }
    }
}
