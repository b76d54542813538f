//! `gloss trace` (src/trace, src/gl/trace): the recording layer lists the
//! calls an executed frame makes, with the source lines that made them, and
//! the GL listings in docs/ are those of the executed frames.
//!
//! * light volumes' state calls come in the notes' order, each from the
//!   line of src/techniques/deferred/light_volumes.rs that makes it (read
//!   back from the file, so the line numbers are checked against the source);
//! * every constant the source names has its name in the trace's table;
//! * every `<!-- gloss trace ... -->` block in docs/ equals what the frame
//!   does now (`GLOSS_BLESS=1` rewrites them), and every technique's page
//!   has one for its technique, with how to try it in the demo (the keys
//!   it names are the demo's);
//! * docs/README.md's map of the notes is the registry's;
//! * texture units never collide (units.rs).

#[path = "../common/mod.rs"]
mod common;

mod docs_listings;
mod material_units;
mod order;
mod plan_programs;
mod registry;
mod try_it;
mod units;

use gloss::gl::Headless;

/// A context whose GL calls can be recorded.
pub fn tracing_context() -> Headless {
    gloss::gl::trace::enable();
    common::context(common::backend())
}
