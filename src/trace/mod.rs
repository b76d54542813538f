//! `gloss trace SCENE`: one frame's GL calls, in the order the frame made
//! them, each with its arguments as GL names, the line of gloss's source
//! that made it, and the pass and technique (with its notes section) it
//! belongs to. The calls come from an executed frame, through the recording
//! layer of src/gl/trace: nothing here reads the source.
//!
//! `listing` prints them (text, or Markdown for docs/), keeping one
//! technique or pass and folding repeated runs (one object's draw, then the
//! same calls for every other object); `docs` keeps the listings in docs/
//! equal to what the frame does, with how to try each technique (`try_it`);
//! `coverage` generates docs/README.md's map of the notes against the
//! registry.

pub mod coverage;
pub mod docs;
pub mod listing;
pub mod notes_sections;
pub mod try_it;
pub mod units;

use crate::gl::Headless;
use crate::gl::program::Sources;
use crate::gl::trace::{self, Call};
use crate::renderer::{Output, Renderer, render_scene};
use crate::scene::Scene;
use anyhow::Result;

/// The GL calls of one frame of `scene` on `ctx` (made after
/// `gl::trace::enable()`), after a first frame that is not recorded: what
/// runs once, on the first frame, is not the frame.
pub fn trace_frame(ctx: &Headless, scene: &Scene) -> Result<Vec<Call>> {
    let r = render_scene(ctx, scene, Output::Srgb8)?;
    record(r, scene)
}

/// The GL calls of the first frame of `scene`: with what a frame draws
/// only when something changed (the sky's cube map).
pub fn trace_first_frame(ctx: &Headless, scene: &Scene) -> Result<Vec<Call>> {
    let (w, h) = scene.render.size;
    let r = Renderer::with_output(
        &ctx.gl,
        &ctx.debug,
        scene,
        &Sources::Embedded,
        w as i32,
        h as i32,
        Output::Srgb8,
    )?;
    record(r, scene)
}

fn record(mut r: Renderer, scene: &Scene) -> Result<Vec<Call>> {
    trace::start();
    let drawn = r.render(&scene.camera);
    let calls = trace::stop();
    drawn?;
    if calls.is_empty() {
        anyhow::bail!("no GL call was recorded: the context was made before gl::trace::enable()");
    }
    Ok(calls)
}
